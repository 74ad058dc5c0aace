#version 330 core
// LearnOpenGL PBR / Lighting, textured: the material comes from five maps.
out vec4 FragColor;
in vec2 TexCoords;
in vec3 WorldPos;
in vec3 Normal;
in vec4 Tangent;

// material maps; albedoMap and aoMap are sRGB textures, so the sampler returns linear values
uniform sampler2D albedoMap;
uniform sampler2D normalMap;
uniform sampler2D metallicMap;
uniform sampler2D roughnessMap;
uniform sampler2D aoMap;
uniform bool useDerivativeTangents;  // the text's screen-space tangent frame instead of the mesh's

// lights
const int MAX_LIGHTS = 4;
uniform int lightCount;
uniform vec3 lightPositions[MAX_LIGHTS];
uniform vec3 lightColors[MAX_LIGHTS];

uniform vec3 camPos;

#include "brdf.glsl"
#include "normal_mapping.glsl"
#include "tonemap.glsl"

vec3 getNormalFromMap()
{
    vec3 tangentNormal = texture(normalMap, TexCoords).xyz * 2.0 - 1.0;
    if (useDerivativeTangents)
        return normalFromMapWithDerivatives(tangentNormal, Normal, WorldPos, TexCoords);
    return normalFromMapWithTangent(tangentNormal, Normal, Tangent);
}

void main()
{
    vec3 albedo = texture(albedoMap, TexCoords).rgb;  // already linear: no pow(2.2) needed
    float metallic = texture(metallicMap, TexCoords).r;
    float roughness = texture(roughnessMap, TexCoords).r;
    float ao = texture(aoMap, TexCoords).r;

    vec3 N = getNormalFromMap();
    vec3 V = normalize(camPos - WorldPos);

    vec3 Lo = vec3(0.0);
    for (int i = 0; i < lightCount; ++i)
    {
        vec3 L = normalize(lightPositions[i] - WorldPos);
        float distance = length(lightPositions[i] - WorldPos);
        vec3 radiance = lightColors[i] / (distance * distance);
        Lo += directLight(N, V, L, radiance, albedo, metallic, roughness);
    }

    vec3 ambient = vec3(0.03) * albedo * ao;
    vec3 color = gammaCorrect(reinhard(ambient + Lo));
    FragColor = vec4(color, 1.0);
}
