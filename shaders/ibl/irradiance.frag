#version 330 core
// Diffuse irradiance: the cosine-weighted average of the environment over the hemisphere around
// N. The environment's bright texels (its sun) are summed exactly, each by its solid angle and
// cosine; the rest is sampled by Riemann sums over (phi, theta) as in the text, but at the
// midpoints of a whole number of
// steps (the text's left-endpoint sums stop short of pi/2: 0.3 % low at its step of 0.025, 2 % at
// 0.05), each sample reading the environment at the mip level of its cell's size. Stored as
// irradiance / pi (what a white Lambertian surface reflects), so a constant environment L gives L.
out vec4 FragColor;
in vec3 WorldPos;

uniform samplerCube environmentMap;  // the rest: the environment less its bright texels
uniform float sampleDelta;   // radians between samples along phi and theta
uniform float sourceTexelSolidAngle;  // 4 pi / (6 size^2) of the environment's level 0

const float PI = 3.14159265359;

#include "bright_texels.glsl"

void main()
{
    vec3 N = normalize(WorldPos);
    vec3 up = abs(N.y) < 0.999 ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0);
    vec3 right = normalize(cross(up, N));
    up = normalize(cross(N, right));

    int phiSteps = int(round(2.0 * PI / sampleDelta));
    int thetaSteps = int(round(0.5 * PI / sampleDelta));
    float phiDelta = 2.0 * PI / float(phiSteps);
    float thetaDelta = 0.5 * PI / float(thetaSteps);

    vec3 irradiance = vec3(0.0);
    float nrSamples = 0.0;
    for (int i = 0; i < phiSteps; ++i)
    {
        float phi = (float(i) + 0.5) * phiDelta;
        for (int j = 0; j < thetaSteps; ++j)
        {
            float theta = (float(j) + 0.5) * thetaDelta;
            // each sample stands for a cell thetaDelta high and phiDelta sin(theta) wide: read the
            // environment at the mip level whose texels are as large as the cell's longer side,
            // so that a small bright sun is neither missed between cells nor counted twice by the
            // narrow cells near the pole
            float cellSide = max(thetaDelta, phiDelta * sin(theta));
            float sampleSolidAngle = cellSide * cellSide;
            float lod = max(0.5 * log2(sampleSolidAngle / sourceTexelSolidAngle), 0.0);
            vec3 tangentSample = vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
            vec3 sampleVec = tangentSample.x * right + tangentSample.y * up + tangentSample.z * N;
            irradiance += textureLod(environmentMap, sampleVec, lod).rgb * cos(theta) * sin(theta);
            nrSamples++;
        }
    }
    irradiance = PI * irradiance / nrSamples;

    vec3 bright = vec3(0.0);
    for (int i = 0; i < brightCount; ++i)
        bright += brightRadiance[i] * (brightDirection[i].w * max(dot(N, brightDirection[i].xyz), 0.0));
    FragColor = vec4(irradiance + bright / PI, 1.0);
}
