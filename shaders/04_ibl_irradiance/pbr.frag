#version 330 core
// LearnOpenGL PBR / IBL / Diffuse irradiance: the constant ambient of sample 01 becomes the
// environment's irradiance, looked up by the normal; the four point lights stay.
out vec4 FragColor;
in vec2 TexCoords;
in vec3 WorldPos;
in vec3 Normal;

uniform vec3 albedo;
uniform float metallic;
uniform float roughness;
uniform float ao;

uniform samplerCube irradianceMap;  // irradiance / pi of the environment

const int MAX_LIGHTS = 4;
uniform int lightCount;
uniform vec3 lightPositions[MAX_LIGHTS];
uniform vec3 lightColors[MAX_LIGHTS];

uniform vec3 camPos;
uniform bool noIbl;  // --no-ibl: no ambient light, the point lights alone (false: the lesson)

#include "brdf.glsl"
#include "tonemap.glsl"
#include "views.glsl"

void main()
{
    vec3 N = normalize(Normal);
    vec3 V = normalize(camPos - WorldPos);

    vec3 Lo = vec3(0.0);
    for (int i = 0; i < lightCount; ++i)
    {
        vec3 L = normalize(lightPositions[i] - WorldPos);
        float distance = length(lightPositions[i] - WorldPos);
        vec3 radiance = lightColors[i] / (distance * distance);
        Lo += directLight(N, V, L, radiance, albedo, metallic, roughness);
    }

    // ambient lighting from the environment: the diffuse part only (specular IBL is sample 05)
    vec3 F0 = mix(vec3(0.04), albedo, metallic);
    vec3 kS = fresnelSchlickRoughness(max(dot(N, V), 0.0), F0, roughness);
    vec3 kD = (1.0 - kS) * (1.0 - metallic);
    vec3 irradiance = texture(irradianceMap, N).rgb;
    vec3 diffuse = irradiance * albedo;
    vec3 ambient = noIbl ? vec3(0.0) : (kD * diffuse) * ao;

    vec3 color = gammaCorrect(reinhard(ambient + Lo));
#ifdef TERM_VIEWS  // --view: one input or term of the equation instead (views.glsl)
    DirectSums sums = noDirectSums();
    for (int i = 0; i < lightCount; ++i)
        addDirectTerms(sums, N, V, normalize(lightPositions[i] - WorldPos), albedo, metallic,
                       roughness);
    color = directView(termView, albedo, N, metallic, roughness, ao, sums,
                       gammaCorrect(reinhard(Lo)));
    color = iblView(termView, irradiance, vec3(0.0), vec2(0.0), ambient, vec3(0.0),
                    gammaCorrect(reinhard(ambient)), color);
    color = ambientWeightView(termView, kS, kD, vec3(0.0), color);
#endif
    FragColor = vec4(color, 1.0);
}
