#version 330 core
// LearnOpenGL PBR / IBL / Specular IBL: the grid of 04, its ambient now the full split sum
// (irradiance for the diffuse part, prefiltered environment and BRDF LUT for the specular part).
out vec4 FragColor;
in vec2 TexCoords;
in vec3 WorldPos;
in vec3 Normal;

uniform vec3 albedo;
uniform float metallic;
uniform float roughness;
uniform float ao;

const int MAX_LIGHTS = 4;
uniform int lightCount;
uniform vec3 lightPositions[MAX_LIGHTS];
uniform vec3 lightColors[MAX_LIGHTS];

uniform vec3 camPos;
uniform bool noIbl;  // --no-ibl: no ambient light, the point lights alone (false: the lesson)

#include "brdf.glsl"
#include "ibl_ambient.glsl"
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

    vec3 ambient = noIbl ? vec3(0.0) : ambientLight(N, V, albedo, metallic, roughness, ao);
    vec3 color = gammaCorrect(reinhard(ambient + Lo));
#ifdef TERM_VIEWS  // --view: one input or term of the equation instead (views.glsl)
    DirectSums sums = noDirectSums();
    for (int i = 0; i < lightCount; ++i)
        addDirectTerms(sums, N, V, normalize(lightPositions[i] - WorldPos), albedo, metallic,
                       roughness);
    color = directView(termView, albedo, N, metallic, roughness, ao, sums,
                       gammaCorrect(reinhard(Lo)));
    AmbientTerms t = ambientTerms(N, V, albedo, metallic, roughness);
    float shown = noIbl ? 0.0 : ao;
    color = iblView(termView, t.reads.irradiance, t.reads.prefilteredColor, t.reads.envBRDF,
                    t.diffuse * shown, t.specular * shown, gammaCorrect(reinhard(ambient)), color);
    color = ambientWeightView(termView, t.kS, t.kD, t.specularFactor, color);
#endif
    FragColor = vec4(color, 1.0);
}
