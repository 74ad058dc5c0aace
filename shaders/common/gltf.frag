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
#ifdef TRANSMISSION
uniform sampler2D transmissionBackdrop;  // the scene behind (linear radiance), its mips its blur
uniform sampler2D transmissionLUT;       // the split sum's scale and bias (RG), without the IBL's
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
#endif
#endif
#include "gltf_material.glsl"
#include "tonemap.glsl"
#include "views.glsl"
#include "gltf_views.glsl"

#ifdef GLTF_EXTENSIONS
#ifdef TRANSMISSION
// The node's scale along each of its axes (the model matrix's columns' lengths): the volume's
// thickness is given in the mesh's units.
vec3 nodeScale()
{
    return vec3(length(model[0].xyz), length(model[1].xyz), length(model[2].xyz));
}

// What comes through the surface from behind: the backdrop (the opaque scene and the sky, drawn
// first) where the refracted ray leaves the volume, projected to the screen, read at the mip
// level of the transmission's roughness (the backdrop's whole width, one texel, at roughness 1),
// then attenuated along the ray.
vec3 transmittedBackdrop(LayeredSurface s, vec3 ray)
{
    vec4 clip = projection * view * vec4(WorldPos + ray, 1.0);
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    float lod = log2(float(textureSize(transmissionBackdrop, 0).x)) *
                iorScaledRoughness(s.roughness, s.ior);
    return volumeAttenuation(textureLod(transmissionBackdrop, uv, lod).rgb, length(ray),
                             s.attenuationColor, s.attenuationDistance);
}
#endif

// The advanced material's light (gltf_extensions.glsl): emission through the coat, each punctual
// light through the layers, the image-based light through the layers' split sum (the coat's own
// reads at its normal and roughness, the sheen's from its prefiltered map, the transmission's
// from the backdrop), times occlusion. Without `through`, no light comes through the surface
// (the transmitted view is the difference).
vec3 layeredColor(SurfaceMaterial m, bool through)
{
    LayeredSurface s = readLayeredSurface(m);
    vec3 V = normalize(camPos - WorldPos);
    vec3 ray = vec3(0.0);  // through the volume (none: thin-walled, or no transmission)
#ifdef TRANSMISSION
    ray = volumeRay(s.N, V, s.thickness, s.ior, nodeScale());
#endif
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
            vec3 exitL = L;
            vec3 exitRadiance = through ? radiance : vec3(0.0);
#ifdef TRANSMISSION
            if (s.thickness > 0.0 && through)
                exitRadiance = volumeAttenuation(punctualRadiance(i, WorldPos + ray, exitL),
                                                 length(ray), s.attenuationColor,
                                                 s.attenuationDistance);
#endif
            color += layeredDirectLight(s, V, L, radiance, exitL, exitRadiance, sheenAtV,
                                        sheenAtL);
        }
    }
    // The image-based light; with a transmission, without it too: a black environment, through
    // which what is behind still comes, under the same layers (the split sum's LUT still weighs it)
    bool ambient = useIbl;
#ifdef TRANSMISSION
    ambient = true;
#endif
    if (ambient)
    {
        SplitSumReads base, coat;
        vec3 sheenRadiance = vec3(0.0);
        if (useIbl)
        {
            base = readSplitSum(s.N, V, s.roughness);
            coat = base;
#ifdef CLEARCOAT
            coat = readSplitSum(s.clearcoatN, V, s.clearcoatRoughness);
#endif
#ifdef SHEEN
            sheenRadiance = textureLod(sheenMap, reflect(-V, s.N), s.sheenRoughness * sheenMaxLod).rgb;
#endif
        }
#ifdef TRANSMISSION
        else
        {
            float NdotV = clamp(dot(s.N, V), 0.0, 1.0);
            base = SplitSumReads(NdotV, vec3(0.0), vec3(0.0),
                                 texture(transmissionLUT, vec2(NdotV, s.roughness)).rg);
            coat = SplitSumReads(clamp(dot(s.clearcoatN, V), 0.0, 1.0), vec3(0.0), vec3(0.0),
                                 vec2(0.0));
        }
#endif
        vec3 transmitted = vec3(0.0);
#ifdef TRANSMISSION
        if (through)
            transmitted = transmittedBackdrop(s, ray);
#endif
        color += layeredAmbientLight(s, base, coat, sheenRadiance, sheenAtV, transmitted) *
                 m.occlusion;
    }
    return color;
}

#ifdef TERM_VIEWS
// Sample 10's views of its layers (defined in its README): F0 from ior and the specular layer, the
// coat's share and the transmission as they are, the coat's normal as 0.5 + 0.5 N; the sheen's
// light (its lobe over the lights, its image-based part) as x / (1 + x); what the base keeps
// under the sheen at the view, and what the volume leaves along the refracted ray, as they are;
// the light through the surface alone, tone-mapped as the picture (the picture less the picture
// without it).
vec3 layeredView(int which, SurfaceMaterial m, vec3 V)
{
    LayeredSurface s = readLayeredSurface(m);
    if (which == VIEW_F0)
        return encodedAs(mix(s.F0, s.metalColor, s.metallic));
    if (which == VIEW_CLEARCOAT_NORMAL)
        return encodedAs(0.5 + 0.5 * s.clearcoatN);
    if (which == VIEW_VOLUME_ATTENUATION)
    {
        vec3 kept = vec3(1.0);
#ifdef TRANSMISSION
        kept = volumeAttenuation(vec3(1.0), length(volumeRay(s.N, V, s.thickness, s.ior, nodeScale())),
                                 s.attenuationColor, s.attenuationDistance);
#endif
        return encodedAs(kept);
    }
    if (which == VIEW_CLEARCOAT)
        return encodedAs(vec3(s.clearcoat * clearcoatFresnel(s.clearcoatF0, dot(s.clearcoatN, V))));
    if (which == VIEW_TRANSMISSION)
        return encodedAs(vec3(s.transmission));
    if (unlit)  // KHR_materials_unlit: no light takes part, so no term of it either
        return vec3(0.0);
    if (which == VIEW_TRANSMITTED)
        return toneMap(layeredColor(m, true) - layeredColor(m, false), toneMapper, exposure);
    float sheenAtV = 0.0;
#ifdef SHEEN
    sheenAtV = texture(sheenLUT, vec2(clamp(dot(s.N, V), 0.0, 1.0), s.sheenRoughness)).a;
#endif
    if (which == VIEW_SHEEN_SCALING)
        return encodedAs(vec3(1.0 - max3(s.sheenColor) * sheenAtV));
    vec3 sheen = vec3(0.0);
    for (int i = 0; usePunctual && i < punctualLightCount; ++i)
    {
        vec3 L;
        vec3 radiance = punctualRadiance(i, WorldPos, L);
        sheen += sheenDirect(s.N, V, L, s.sheenColor, s.sheenRoughness) * radiance;
    }
#ifdef SHEEN
    if (useIbl)
        sheen += s.sheenColor * sheenAtV * m.occlusion *
                 textureLod(sheenMap, reflect(-V, s.N), s.sheenRoughness * sheenMaxLod).rgb;
#endif
    return encodedAs(viewCompress(sheen));
}
#endif
#endif

void main()
{
    SurfaceMaterial m = readGltfMaterial();
    vec3 color = m.baseColor;
#ifdef GLTF_EXTENSIONS
    if (!unlit)
        color = layeredColor(m, true);
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
    // (the picture itself where a view's frame draws sample 10's transmission backdrop)
#ifdef GLTF_EXTENSIONS
    if (termView >= VIEW_CLEARCOAT || termView == VIEW_F0)
        FragColor.rgb = layeredView(termView, m, normalize(camPos - WorldPos));
    else
#endif
    if (termView != VIEW_FINAL)
        FragColor.rgb = gltfView(termView, m, normalize(camPos - WorldPos));
#endif
}
