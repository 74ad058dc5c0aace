#version 330 core
// LearnOpenGL PBR / Lighting: Cook-Torrance with four point lights and constant material values.
out vec4 FragColor;
in vec2 TexCoords;
in vec3 WorldPos;
in vec3 Normal;

// material parameters
uniform vec3 albedo;
uniform float metallic;
uniform float roughness;
uniform float ao;

// lights
const int MAX_LIGHTS = 4;
uniform int lightCount;
uniform vec3 lightPositions[MAX_LIGHTS];
uniform vec3 lightColors[MAX_LIGHTS];

uniform vec3 camPos;

#include "brdf.glsl"
#include "tonemap.glsl"
#include "views.glsl"

void main()
{
    vec3 N = normalize(Normal);  // interpolation shortens the normal: normalize per fragment
    vec3 V = normalize(camPos - WorldPos);

    // reflectance equation: with point lights the integral is a sum over the lights
    vec3 Lo = vec3(0.0);
    for (int i = 0; i < lightCount; ++i)
    {
        vec3 L = normalize(lightPositions[i] - WorldPos);
        float distance = length(lightPositions[i] - WorldPos);
        float attenuation = 1.0 / (distance * distance);  // physically correct inverse square
        vec3 radiance = lightColors[i] * attenuation;
        Lo += directLight(N, V, L, radiance, albedo, metallic, roughness);
    }

    // a constant ambient term stands in for environment lighting (IBL comes in sample 04)
    vec3 ambient = vec3(0.03) * albedo * ao;
    vec3 color = ambient + Lo;

    // HDR -> LDR, then linear -> gamma
    color = gammaCorrect(reinhard(color));
#ifdef TERM_VIEWS  // --view: one input or term of the equation instead (views.glsl)
    DirectSums sums = noDirectSums();
    for (int i = 0; i < lightCount; ++i)
        addDirectTerms(sums, N, V, normalize(lightPositions[i] - WorldPos), albedo, metallic,
                       roughness);
    color = directView(termView, albedo, N, metallic, roughness, ao, sums,
                       gammaCorrect(reinhard(Lo)));
    if (termView == VIEW_AMBIENT) color = gammaCorrect(reinhard(ambient));  // the term alone
#endif
    FragColor = vec4(color, 1.0);
}
