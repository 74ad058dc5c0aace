#version 330 core
// LearnOpenGL PBR / IBL / Specular IBL, textured: the split-sum ambient of pbr.frag on spheres
// whose material comes from five maps (as in 02).
out vec4 FragColor;
in vec2 TexCoords;
in vec3 WorldPos;
in vec3 Normal;
in vec4 Tangent;

const int MAX_LIGHTS = 4;
uniform int lightCount;
uniform vec3 lightPositions[MAX_LIGHTS];
uniform vec3 lightColors[MAX_LIGHTS];

uniform vec3 camPos;

#include "brdf.glsl"
#include "ibl_ambient.glsl"
#include "material_maps.glsl"
#include "tonemap.glsl"

void main()
{
    Material m = readMaterialMaps();
    vec3 V = normalize(camPos - WorldPos);

    vec3 Lo = vec3(0.0);
    for (int i = 0; i < lightCount; ++i)
    {
        vec3 L = normalize(lightPositions[i] - WorldPos);
        float distance = length(lightPositions[i] - WorldPos);
        vec3 radiance = lightColors[i] / (distance * distance);
        Lo += directLight(m.N, V, L, radiance, m.albedo, m.metallic, m.roughness);
    }

    vec3 ambient = ambientLight(m.N, V, m.albedo, m.metallic, m.roughness, m.ao);
    FragColor = vec4(gammaCorrect(reinhard(ambient + Lo)), 1.0);
}
