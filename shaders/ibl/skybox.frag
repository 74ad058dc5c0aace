#version 330 core
out vec4 FragColor;
in vec3 WorldPos;

uniform samplerCube environmentMap;
uniform int toneMapper;  // -1: the text's output (04-06); else a TONEMAP_* (or LINEAR_RADIANCE)
uniform float exposure;
uniform float lod;  // the mip level shown: 0, or a prefiltered map's roughness level

#include "tonemap.glsl"

void main()
{
    vec3 envColor = textureLod(environmentMap, WorldPos, lod).rgb;
    if (toneMapper == -1)
        FragColor = vec4(gammaCorrect(reinhard(envColor)), 1.0);  // tone-mapped like the spheres
    else
        FragColor = vec4(toneMap(envColor, toneMapper, exposure), 1.0);
}
