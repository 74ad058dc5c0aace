#version 330 core
// The Overload engine's standard PBR shader, as sample 09 teaches it: a material from five maps
// with the engine's inputs (texture tiling and offset, an albedo tint, metallic and roughness
// factors), lit by every light of one buffer (light_types.glsl), then Reinhard and gamma as the
// engine does.
out vec4 FragColor;
in vec2 TexCoords;
in vec3 WorldPos;
in vec3 Normal;
in vec4 Tangent;

uniform vec3 camPos;
uniform vec2 textureTiling;   // the engine's u_TextureTiling
uniform vec2 textureOffset;   // u_TextureOffset
uniform vec4 albedoTint;      // u_Albedo: multiplies the albedo map (its rgb in linear terms)
uniform float metallicFactor; // u_Metallic
uniform float roughnessFactor;// u_Roughness
uniform bool untextured;      // the tests' plain material: white maps (albedo = the tint,
                              // metallic and roughness = the factors), ao 1, no normal map

#include "brdf.glsl"
#include "material_maps.glsl"
#include "tonemap.glsl"
#include "views.glsl"
#include "light_types.glsl"

void main()
{
    // tiling and offset: uv x tiling + offset on REPEAT textures (the engine takes the fractional
    // part first, which gives the same texels but a seam where the mip level jumps)
    vec2 uv = TexCoords * textureTiling + textureOffset;
    Material m;
    if (untextured)
    {
        m.albedo = vec3(1.0);
        m.metallic = 1.0;
        m.roughness = 1.0;
        m.ao = 1.0;
        m.N = normalize(Normal);
    }
    else
    {
        m = readMaterialMapsAt(uv);
    }
    vec3 albedo = m.albedo * albedoTint.rgb;
    float metallic = clamp(m.metallic * metallicFactor, 0.0, 1.0);
    float roughness = clamp(m.roughness * roughnessFactor, 0.0, 1.0);
    vec3 V = normalize(camPos - WorldPos);
    vec3 color = shadeLights(WorldPos, m.N, V, albedo, metallic, roughness, m.ao);
    color = gammaCorrect(reinhard(color));
#ifdef TERM_VIEWS  // --view: one input or term of the equation instead (light_types.glsl)
    color = lightTypesView(termView, m.N, albedo, metallic, roughness, m.ao);
#endif
    FragColor = vec4(color, 1.0);
}
