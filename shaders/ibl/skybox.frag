#version 330 core
out vec4 FragColor;
in vec3 WorldPos;

uniform samplerCube environmentMap;

#include "tonemap.glsl"

void main()
{
    vec3 envColor = textureLod(environmentMap, WorldPos, 0.0).rgb;
    FragColor = vec4(gammaCorrect(reinhard(envColor)), 1.0);  // tone-mapped like the spheres
}
