#version 330 core
// LearnOpenGL PBR / Lighting, textured: the material comes from five maps.
out vec4 FragColor;
in vec2 TexCoords;
in vec3 WorldPos;
in vec3 Normal;
in vec4 Tangent;

// lights
const int MAX_LIGHTS = 4;
uniform int lightCount;
uniform vec3 lightPositions[MAX_LIGHTS];
uniform vec3 lightColors[MAX_LIGHTS];

uniform vec3 camPos;

#include "brdf.glsl"
#include "material_maps.glsl"
#include "tonemap.glsl"
#include "views.glsl"

void main()
{
    Material m = readMaterialMaps();
    vec3 N = m.N;
    vec3 V = normalize(camPos - WorldPos);

    vec3 Lo = vec3(0.0);
    for (int i = 0; i < lightCount; ++i)
    {
        vec3 L = normalize(lightPositions[i] - WorldPos);
        float distance = length(lightPositions[i] - WorldPos);
        vec3 radiance = lightColors[i] / (distance * distance);
        Lo += directLight(N, V, L, radiance, m.albedo, m.metallic, m.roughness);
    }

    vec3 ambient = vec3(0.03) * m.albedo * m.ao;
    vec3 color = gammaCorrect(reinhard(ambient + Lo));
#ifdef TERM_VIEWS  // --view: one input or term of the equation instead (views.glsl)
    DirectSums sums = noDirectSums();
    for (int i = 0; i < lightCount; ++i)
        addDirectTerms(sums, N, V, normalize(lightPositions[i] - WorldPos), m.albedo, m.metallic,
                       m.roughness);
    color = directView(termView, m.albedo, N, m.metallic, m.roughness, m.ao, sums,
                       gammaCorrect(reinhard(Lo)));
    if (termView == VIEW_AMBIENT) color = gammaCorrect(reinhard(ambient));  // the term alone
#endif
    FragColor = vec4(color, 1.0);
}
