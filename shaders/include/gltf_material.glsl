// A glTF 2.0 material read at one fragment (the specification's section 3.9 and Appendix B):
// every input a factor times a texture, each texture read at its own texture coordinate set
// through its KHR_texture_transform matrix. Written once for the glTF samples; it hands the
// shading a SurfaceMaterial, the one description both workflows end in: metallic-roughness
// (the core material, sample 07) and KHR_materials_pbrSpecularGlossiness (sample 08). The
// including shader declares the inputs WorldPos, Normal, Tangent, TexCoords0, TexCoords1 and
// VertexColor. Texture units are fixed: 0 base colour (or diffuse), 1 metallic-roughness (or
// specular-glossiness), 2 normal, 3 occlusion, 4 emissive (bound by pbr::GltfRenderer,
// common/gltf/gltf_renderer.h).
#include "normal_mapping.glsl"

const int ALPHA_OPAQUE = 0;
const int ALPHA_MASK = 1;
const int ALPHA_BLEND = 2;

// Absent textures are bound to a 1x1 white texture, so factor x texture is the factor alone.
uniform vec4 baseColorFactor;
uniform sampler2D baseColorTexture;  // sRGB: the sampler returns linear values
uniform int baseColorUvSet;
uniform mat3 baseColorUvTransform;

uniform float metallicFactor;
uniform float roughnessFactor;
uniform sampler2D metallicRoughnessTexture;  // G = roughness, B = metallic (linear)
uniform int metallicRoughnessUvSet;
uniform mat3 metallicRoughnessUvTransform;

// KHR_materials_pbrSpecularGlossiness: its diffuse factor and texture are baseColorFactor and
// baseColorTexture above; unit 1 holds its specular-glossiness texture.
uniform bool specularGlossiness;
uniform vec3 specularFactor;
uniform float glossinessFactor;
uniform sampler2D specularGlossinessTexture;  // RGB specular (sRGB), A glossiness (linear)
uniform int specularGlossinessUvSet;
uniform mat3 specularGlossinessUvTransform;

uniform bool hasNormalTexture;
uniform float normalScale;
uniform sampler2D normalTexture;
uniform int normalUvSet;
uniform mat3 normalUvTransform;

uniform float occlusionStrength;
uniform sampler2D occlusionTexture;  // R
uniform int occlusionUvSet;
uniform mat3 occlusionUvTransform;

uniform vec3 emissiveFactor;
uniform sampler2D emissiveTexture;  // sRGB
uniform int emissiveUvSet;
uniform mat3 emissiveUvTransform;

uniform int alphaMode;
uniform float alphaCutoff;
uniform bool unlit;  // KHR_materials_unlit: the base colour is the result

#ifdef GLTF_EXTENSIONS
// The advanced material (sample 10, gltf_extensions.glsl): KHR_materials_ior, _specular and
// _emissive_strength always; each other layer only in the programs of the materials that use it
// (pbr::materialLayers), its textures on the units after the IBL maps'.
uniform float ior;
uniform float khrSpecularFactor;
uniform vec3 khrSpecularColorFactor;
uniform float emissiveStrength;
#ifdef SPECULAR
uniform sampler2D khrSpecularTexture;  // A
uniform int khrSpecularUvSet;
uniform mat3 khrSpecularUvTransform;
uniform sampler2D khrSpecularColorTexture;  // RGB, sRGB
uniform int khrSpecularColorUvSet;
uniform mat3 khrSpecularColorUvTransform;
#endif
#ifdef CLEARCOAT
uniform float clearcoatFactor;
uniform sampler2D clearcoatTexture;  // R
uniform int clearcoatUvSet;
uniform mat3 clearcoatUvTransform;
uniform float clearcoatRoughnessFactor;
uniform sampler2D clearcoatRoughnessTexture;  // G
uniform int clearcoatRoughnessUvSet;
uniform mat3 clearcoatRoughnessUvTransform;
uniform bool hasClearcoatNormalTexture;
uniform float clearcoatNormalScale;
uniform sampler2D clearcoatNormalTexture;
uniform int clearcoatNormalUvSet;
uniform mat3 clearcoatNormalUvTransform;
#endif
#ifdef SHEEN
uniform vec3 sheenColorFactor;
uniform sampler2D sheenColorTexture;  // RGB, sRGB
uniform int sheenColorUvSet;
uniform mat3 sheenColorUvTransform;
uniform float sheenRoughnessFactor;
uniform sampler2D sheenRoughnessTexture;  // A
uniform int sheenRoughnessUvSet;
uniform mat3 sheenRoughnessUvTransform;
#endif
#ifdef TRANSMISSION  // KHR_materials_transmission with KHR_materials_volume
uniform float transmissionFactor;
uniform sampler2D transmissionTexture;  // R
uniform int transmissionUvSet;
uniform mat3 transmissionUvTransform;
uniform float thicknessFactor;
uniform sampler2D thicknessTexture;  // G
uniform int thicknessUvSet;
uniform mat3 thicknessUvTransform;
uniform vec3 attenuationColor;
uniform float attenuationDistance;  // 0: none (the extension's infinity)
#endif
#endif

struct SurfaceMaterial
{
    vec3 baseColor;     // linear: what an unlit material shows
    vec3 diffuseColor;  // c_diff: the dielectric's diffuse colour
    vec3 F0;            // the dielectric's reflectance at normal incidence
    float metallic;     // how much of the metal BRDF (of colour baseColor) is mixed in
    float roughness;    // perceptual; alpha = roughness^2
    float alpha;        // opacity (1 unless BLEND)
    float occlusion;    // 1 - strength + strength x texture: scales indirect light only
    vec3 emissive;      // linear radiance
    vec3 N;             // world-space shading normal, facing the viewer on double-sided back faces
};

vec2 textureUv(int uvSet, mat3 transform)
{
    vec2 uv = uvSet == 1 ? TexCoords1 : TexCoords0;
    return (transform * vec3(uv, 1.0)).xy;
}

// The shading normal: the geometric one (flipped on the back faces of a double-sided material,
// as the specification asks), perturbed by the normal texture scaled in x and y by normalScale.
vec3 gltfShadingNormal()
{
    vec3 normal = gl_FrontFacing ? Normal : -Normal;
    vec4 tangent = gl_FrontFacing ? Tangent : -Tangent;  // T and B flip with the normal
    if (!hasNormalTexture)
        return normalize(normal);
    vec3 tangentNormal = texture(normalTexture, textureUv(normalUvSet, normalUvTransform)).xyz * 2.0 - 1.0;
    tangentNormal.xy *= normalScale;
    return normalFromMapWithTangent(normalize(tangentNormal), normal, tangent);
}

#ifdef CLEARCOAT
// The clear coat's own normal: the geometric one, perturbed by its normal texture when it has one
// (not by the base's: the coat lies smooth over a bumpy base).
vec3 clearcoatShadingNormal()
{
    vec3 normal = gl_FrontFacing ? Normal : -Normal;
    vec4 tangent = gl_FrontFacing ? Tangent : -Tangent;
    if (!hasClearcoatNormalTexture)
        return normalize(normal);
    vec3 tangentNormal = texture(clearcoatNormalTexture,
                                 textureUv(clearcoatNormalUvSet, clearcoatNormalUvTransform)).xyz * 2.0 - 1.0;
    tangentNormal.xy *= clearcoatNormalScale;
    return normalFromMapWithTangent(normalize(tangentNormal), normal, tangent);
}
#endif

// The material at this fragment, in either workflow. MASK discards what lies below the cutoff.
SurfaceMaterial readGltfMaterial()
{
    SurfaceMaterial m;
    // base colour, or the diffuse colour of specular-glossiness (its alpha is the opacity)
    vec4 base = baseColorFactor * VertexColor *
                texture(baseColorTexture, textureUv(baseColorUvSet, baseColorUvTransform));
    if (alphaMode == ALPHA_MASK && base.a < alphaCutoff)
        discard;
    m.alpha = alphaMode == ALPHA_BLEND ? base.a : 1.0;
    m.baseColor = base.rgb;

    if (specularGlossiness)
    {
        // the extension's conversion: F0 = specular, roughness = 1 - glossiness, and the
        // diffuse colour keeps what the specular reflection leaves: 1 - max(specular)
        vec4 sg = texture(specularGlossinessTexture,
                          textureUv(specularGlossinessUvSet, specularGlossinessUvTransform));
        vec3 specular = clamp(specularFactor * sg.rgb, 0.0, 1.0);
        m.F0 = specular;
        m.roughness = clamp(1.0 - glossinessFactor * sg.a, 0.0, 1.0);
        m.diffuseColor = base.rgb * (1.0 - max(specular.r, max(specular.g, specular.b)));
        m.metallic = 0.0;
    }
    else
    {
        // Appendix B: a dielectric (F0 0.04 over a diffuse base colour) and a metal (of the
        // base colour) mixed by metallic
        vec4 mr = texture(metallicRoughnessTexture,
                          textureUv(metallicRoughnessUvSet, metallicRoughnessUvTransform));
        m.metallic = clamp(metallicFactor * mr.b, 0.0, 1.0);
        m.roughness = clamp(roughnessFactor * mr.g, 0.0, 1.0);
        m.diffuseColor = base.rgb;
        m.F0 = vec3(0.04);
    }

    float ao = texture(occlusionTexture, textureUv(occlusionUvSet, occlusionUvTransform)).r;
    m.occlusion = 1.0 + occlusionStrength * (ao - 1.0);
    m.emissive = emissiveFactor *
                 texture(emissiveTexture, textureUv(emissiveUvSet, emissiveUvTransform)).rgb;
    m.N = gltfShadingNormal();
    return m;
}

#ifdef GLTF_EXTENSIONS
// The layers over the material read above (gltf_extensions.glsl's LayeredSurface): the
// dielectric's F0 and F90 from ior and KHR_materials_specular (its factor times its texture's A,
// its colour times its texture's RGB), the sheen's colour and roughness (texture RGB and A), the
// clear coat's strength, roughness (texture R and G) and normal, the transmission (texture R) and
// the volume's thickness (texture G) and attenuation; a layer the program lacks is off.
LayeredSurface readLayeredSurface(SurfaceMaterial m)
{
    LayeredSurface s;
    float specular = khrSpecularFactor;
    vec3 specularColor = khrSpecularColorFactor;
#ifdef SPECULAR
    specular *= texture(khrSpecularTexture, textureUv(khrSpecularUvSet, khrSpecularUvTransform)).a;
    specularColor *= texture(khrSpecularColorTexture,
                             textureUv(khrSpecularColorUvSet, khrSpecularColorUvTransform)).rgb;
#endif
    DielectricFresnel fresnel = dielectricFresnel(ior, specularColor, specular);
    s.N = m.N;
    s.diffuseColor = m.diffuseColor;
    s.F0 = specularGlossiness ? m.F0 : fresnel.F0;  // the workflow's own (the layers exclude it)
    s.F90 = specularGlossiness ? 1.0 : fresnel.F90;
    s.metalColor = m.baseColor;
    s.metallic = m.metallic;
    s.roughness = m.roughness;
    s.sheenColor = vec3(0.0);
    s.sheenRoughness = 0.0;
#ifdef SHEEN
    s.sheenColor = sheenColorFactor *
                   texture(sheenColorTexture, textureUv(sheenColorUvSet, sheenColorUvTransform)).rgb;
    s.sheenRoughness = sheenRoughnessFactor *
                       texture(sheenRoughnessTexture, textureUv(sheenRoughnessUvSet, sheenRoughnessUvTransform)).a;
#endif
    s.clearcoat = 0.0;
    s.clearcoatRoughness = 0.0;
    s.clearcoatN = m.N;
    s.clearcoatF0 = iorToF0(ior);
#ifdef CLEARCOAT
    s.clearcoat = clearcoatFactor *
                  texture(clearcoatTexture, textureUv(clearcoatUvSet, clearcoatUvTransform)).r;
    s.clearcoatRoughness = clamp(clearcoatRoughnessFactor *
                                     texture(clearcoatRoughnessTexture,
                                             textureUv(clearcoatRoughnessUvSet, clearcoatRoughnessUvTransform)).g,
                                 0.0, 1.0);
    s.clearcoatN = clearcoatShadingNormal();
#endif
    s.transmission = 0.0;
    s.ior = ior;
    s.thickness = 0.0;
    s.attenuationColor = vec3(1.0);
    s.attenuationDistance = 0.0;
#ifdef TRANSMISSION
    s.transmission = transmissionFactor *
                     texture(transmissionTexture, textureUv(transmissionUvSet, transmissionUvTransform)).r;
    s.thickness = thicknessFactor *
                  texture(thicknessTexture, textureUv(thicknessUvSet, thicknessUvTransform)).g;
    s.attenuationColor = attenuationColor;
    s.attenuationDistance = attenuationDistance;
#endif
    return s;
}
#endif
