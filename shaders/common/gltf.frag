#version 330 core
// The cookbook's glTF PBR recipes ("metallic-roughness", sample 07; "specular-glossiness",
// sample 08), as the glTF 2.0 specification defines the material: image-based light (the exact
// split sum of 05's maps) times occlusion, plus the file's punctual lights through the
// Appendix B BRDF, plus emission; then exposure and a tone mapper. Either workflow arrives as one
// SurfaceMaterial (gltf_material.glsl). The render target is sRGB: this writes linear values and
// the GL encodes them.
out vec4 FragColor;
in vec3 WorldPos;
in vec3 Normal;
in vec4 Tangent;
in vec2 TexCoords0;
in vec2 TexCoords1;
in vec4 VertexColor;

uniform vec3 camPos;
uniform bool useIbl;
uniform bool usePunctual;
uniform int toneMapper;  // TONEMAP_* of tonemap.glsl
uniform float exposure;

#include "brdf.glsl"
#include "ibl_ambient.glsl"
#include "punctual_lights.glsl"
#ifdef GLTF_EXTENSIONS
// sample 10's layers (pbr::materialLayers: this program has those of the material it draws)
#include "gltf_extensions.glsl"
#ifdef SHEEN
uniform sampler2D sheenLUT;   // A: the sheen's albedo at (NdotV, sheen roughness)
uniform samplerCube sheenMap;  // the environment prefiltered by the sheen's lobe
uniform float sheenMaxLod;     // its last mip level: sheen roughness 1
#endif
#endif
#include "gltf_material.glsl"
#include "tonemap.glsl"
#include "views.glsl"
#include "gltf_views.glsl"

#ifdef GLTF_EXTENSIONS
// The advanced material's light (gltf_extensions.glsl): emission through the coat, each punctual
// light through the layers, the image-based light through the layers' split sum (the coat's own
// reads at its normal and roughness, the sheen's from its prefiltered map), times occlusion.
vec3 layeredColor(SurfaceMaterial m)
{
    LayeredSurface s = readLayeredSurface(m);
    vec3 V = normalize(camPos - WorldPos);
    float sheenAtV = 0.0;
#ifdef SHEEN
    sheenAtV = texture(sheenLUT, vec2(clamp(dot(s.N, V), 0.0, 1.0), s.sheenRoughness)).a;
#endif
    float coatWeight = s.clearcoat * clearcoatFresnel(s.clearcoatF0, dot(s.clearcoatN, V));
    vec3 color = emission(m.emissive, emissiveStrength, coatWeight);
    if (usePunctual)
    {
        for (int i = 0; i < punctualLightCount; ++i)
        {
            vec3 L;
            vec3 radiance = punctualRadiance(i, WorldPos, L);
            float sheenAtL = 0.0;
#ifdef SHEEN
            sheenAtL = texture(sheenLUT, vec2(clamp(dot(s.N, L), 0.0, 1.0), s.sheenRoughness)).a;
#endif
            color += layeredDirectLight(s, V, L, radiance, sheenAtV, sheenAtL);
        }
    }
    if (useIbl)
    {
        SplitSumReads base = readSplitSum(s.N, V, s.roughness);
        SplitSumReads coat = base;
#ifdef CLEARCOAT
        coat = readSplitSum(s.clearcoatN, V, s.clearcoatRoughness);
#endif
        vec3 sheenRadiance = vec3(0.0);
#ifdef SHEEN
        sheenRadiance = textureLod(sheenMap, reflect(-V, s.N), s.sheenRoughness * sheenMaxLod).rgb;
#endif
        color += layeredAmbientLight(s, base, coat, sheenRadiance, sheenAtV) * m.occlusion;
    }
    return color;
}
#endif

void main()
{
    SurfaceMaterial m = readGltfMaterial();
    vec3 color = m.baseColor;
#ifdef GLTF_EXTENSIONS
    if (!unlit)
        color = layeredColor(m);
#else
    if (!unlit)
    {
        vec3 V = normalize(camPos - WorldPos);
        color = m.emissive;
        if (usePunctual)
        {
            for (int i = 0; i < punctualLightCount; ++i)
            {
                vec3 L;
                vec3 radiance = punctualRadiance(i, WorldPos, L);
                color += gltfDirectLight(m.N, V, L, radiance, m.diffuseColor, m.F0, m.baseColor,
                                         m.metallic, m.roughness);
            }
        }
        if (useIbl)
            color += ambientLightGltf(m.N, V, m.diffuseColor, m.F0, m.baseColor, m.metallic,
                                      m.roughness) * m.occlusion;
    }
#endif
    FragColor = vec4(toneMap(color, toneMapper, exposure), m.alpha);
#ifdef TERM_VIEWS  // --view: one input or term of the equation instead (gltf_views.glsl)
    FragColor.rgb = gltfView(termView, m, normalize(camPos - WorldPos));
#endif
}
