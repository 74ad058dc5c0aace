#version 330 core
// The diffuse irradiance convolution as LearnOpenGL's text describes it, restated for the
// ibl_accuracy tool (not used by any sample): a Riemann sum over the hemisphere around N with a
// fixed step of 0.025 rad along phi and theta, each loop starting at 0 and stepping while below
// its bound (left endpoints), every sample weighted by cos(theta) sin(theta). The environment is
// read at level 0 only: the text's environment has no mipmaps at this step. The result is
// pi * (weighted mean), i.e. irradiance / pi, so a constant environment L gives about L.
out vec4 FragColor;
in vec3 WorldPos;

uniform samplerCube environmentMap;

const float PI = 3.14159265359;
const float stepSize = 0.025;

void main()
{
    vec3 N = normalize(WorldPos);
    // The frame of the text (and of ours, away from the poles). No texel centre of an even-sized
    // face lies on the Y axis, so the cross product never vanishes here.
    vec3 up = vec3(0.0, 1.0, 0.0);
    vec3 right = normalize(cross(up, N));
    up = normalize(cross(N, right));

    vec3 weightedSum = vec3(0.0);
    float count = 0.0;
    for (float phi = 0.0; phi < 2.0 * PI; phi += stepSize)
    {
        for (float theta = 0.0; theta < 0.5 * PI; theta += stepSize)
        {
            // spherical (theta from N, phi around it) -> the tangent frame -> world
            float sinTheta = sin(theta);
            float cosTheta = cos(theta);
            vec3 local = vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
            vec3 direction = local.x * right + local.y * up + local.z * N;
            weightedSum += textureLod(environmentMap, direction, 0.0).rgb * cosTheta * sinTheta;
            count += 1.0;
        }
    }
    FragColor = vec4(PI * weightedSum / count, 1.0);
}
