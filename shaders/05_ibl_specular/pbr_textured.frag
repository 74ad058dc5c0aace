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
uniform bool noIbl;  // --no-ibl: no ambient light, the point lights alone (false: the lesson)

#include "brdf.glsl"
#include "ibl_ambient.glsl"
#include "material_maps.glsl"
#include "tonemap.glsl"
#include "views.glsl"

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

    vec3 ambient =
        noIbl ? vec3(0.0) : ambientLight(m.N, V, m.albedo, m.metallic, m.roughness, m.ao);
    vec3 color = gammaCorrect(reinhard(ambient + Lo));
#ifdef TERM_VIEWS  // --view: one input or term of the equation instead (views.glsl)
    DirectSums sums = noDirectSums();
    for (int i = 0; i < lightCount; ++i)
        addDirectTerms(sums, m.N, V, normalize(lightPositions[i] - WorldPos), m.albedo,
                       m.metallic, m.roughness);
    color = directView(termView, m.albedo, m.N, m.metallic, m.roughness, m.ao, sums,
                       gammaCorrect(reinhard(Lo)));
    AmbientTerms t = ambientTerms(m.N, V, m.albedo, m.metallic, m.roughness);
    float shown = noIbl ? 0.0 : m.ao;
    color = iblView(termView, t.reads.irradiance, t.reads.prefilteredColor, t.reads.envBRDF,
                    t.diffuse * shown, t.specular * shown, gammaCorrect(reinhard(ambient)), color);
    color = ambientWeightView(termView, t.kS, t.kD, t.specularFactor, color);
#endif
    FragColor = vec4(color, 1.0);
}
