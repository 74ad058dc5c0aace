// The layers of the advanced glTF materials (sample 10; the cookbook's chapter "Advanced PBR
// extensions"), each as its Khronos extension specifies it, written once. Mirrored on the CPU by
// common/math/gltf_extensions.cpp (same names), which the tests compare against and integrate.
// Needs brdf.glsl first (PI, D_GGX, V_GGX, MIN_GGX_ALPHA, gltfBrdfF90); the layered image-based
// light at the end also needs ibl_ambient.glsl (SplitSumReads, specularIblF90).

// ---- KHR_materials_ior ----
// A dielectric's reflectance at normal incidence in air, from its index of refraction:
// ((ior - 1) / (ior + 1))^2, 0.04 at the core material's 1.5.
float iorToF0(float ior)
{
    float r = (ior - 1.0) / (ior + 1.0);
    return r * r;
}

// ---- KHR_materials_specular ----
// The dielectric's Fresnel ends: the strength (specular, A of its texture) scales the whole
// reflection and is its grazing value F90; the colour tints the normal-incidence one, which stays
// at or below 1 before the strength: F0 = min(iorToF0(ior) specularColor, 1) specular.
struct DielectricFresnel
{
    vec3 F0;
    float F90;
};

DielectricFresnel dielectricFresnel(float ior, vec3 specularColor, float specular)
{
    DielectricFresnel f;
    f.F0 = min(vec3(iorToF0(ior)) * specularColor, vec3(1.0)) * specular;
    f.F90 = specular;
    return f;
}

// ---- KHR_materials_clearcoat ----
// A clear dielectric coat (F0 from the material's ior, F90 1) over the whole material, with its
// own roughness and normal. Its lobe is a GGX specular (D V, alpha = roughness^2); what it
// reflects is mixed over the layer beneath by the coat's Fresnel at its own normal and the view:
//   coated = mix(base, coat lobe, clearcoat Fc(N_coat . V)),   Fc(x) = F0 + (1 - F0)(1 - x)^5
// so the base loses, at every light, the share the coat reflects.
float clearcoatFresnel(float F0, float NdotV)
{
    return F0 + (1.0 - F0) * pow(1.0 - clamp(NdotV, 0.0, 1.0), 5.0);
}

// The coat's lobe for one light, times NdotL at its normal (radiance 1): D V NdotL.
float clearcoatDirect(vec3 coatN, vec3 V, vec3 L, float roughness)
{
    float NdotL = clamp(dot(coatN, L), 0.0, 1.0);
    float NdotV = clamp(dot(coatN, V), 0.0, 1.0);
    float NdotH = clamp(dot(coatN, normalize(V + L)), 0.0, 1.0);
    float alpha = max(roughness * roughness, MIN_GGX_ALPHA);
    return NdotL * D_GGX(NdotH, alpha) * V_GGX(NdotL, NdotV, alpha);
}

// The layer beneath and the coat, mixed by the coat's strength at this view (clearcoat Fc).
vec3 coatOver(vec3 base, vec3 coat, float coatWeight)
{
    return mix(base, coat, coatWeight);
}

// ---- KHR_materials_sheen ----
// A layer of fibres over the material: the Charlie lobe (sheen.glsl), no Fresnel. The layer
// beneath is scaled by what the sheen takes from it (albedo scaling): 1 - max(sheenColor) E, E the
// sheen's directional albedo at the view and at the light (the smaller of the two), read from a
// table (the BRDF LUT's A channel).
#include "sheen.glsl"

// The sheen lobe for one light, times NdotL (radiance 1): sheenColor D V NdotL.
vec3 sheenDirect(vec3 N, vec3 V, vec3 L, vec3 sheenColor, float sheenRoughness)
{
    float NdotL = clamp(dot(N, L), 0.0, 1.0);
    float NdotV = clamp(dot(N, V), 0.0, 1.0);
    if (NdotL <= 0.0 || NdotV <= 0.0)
        return vec3(0.0);
    float NdotH = clamp(dot(N, normalize(V + L)), 0.0, 1.0);
    float alpha = max(sheenRoughness * sheenRoughness, MIN_SHEEN_ALPHA);
    return sheenColor * (NdotL * D_Charlie(NdotH, alpha) * V_Sheen(NdotL, NdotV, alpha));
}

float max3(vec3 v)
{
    return max(v.x, max(v.y, v.z));
}

// What the layer beneath keeps under the sheen, from the sheen's albedo at the view and the light.
float sheenAlbedoScaling(vec3 sheenColor, float albedoAtV, float albedoAtL)
{
    float strength = max3(sheenColor);
    return min(1.0 - strength * albedoAtV, 1.0 - strength * albedoAtL);
}

// ---- KHR_materials_emissive_strength ----
// The emission, as bright as the strength says (the core material's factor stops at 1), seen
// through the clear coat: emissive strength (1 - clearcoat Fc).
vec3 emission(vec3 emissive, float strength, float coatWeight)
{
    return emissive * strength * (1.0 - coatWeight);
}

// ---- KHR_materials_transmission and KHR_materials_volume ----
// Light through the surface. By the transmission factor, the base's diffuse share gives way to a
// specular transmission tinted by the base colour, which gets what the reflection leaves (1 - F).
// Thin-walled (without a volume) a ray leaves where it arrived. With KHR_materials_volume it is
// refracted by ior, crosses the thickness (the mesh's units, times the node's scale) and keeps
// attenuationColor^(distance / attenuationDistance) of its light in each channel (Beer-Lambert).

// A transmission lobe's roughness (perceptual, or alpha): the surface's, down to none as ior nears
// 1 (an interface that does not refract does not blur what is behind it).
float iorScaledRoughness(float roughness, float ior)
{
    return roughness * clamp(2.0 * ior - 2.0, 0.0, 1.0);
}

// From the surface to where the refracted ray leaves the volume (0 when thin-walled).
vec3 volumeRay(vec3 N, vec3 V, float thickness, float ior, vec3 modelScale)
{
    return normalize(refract(-V, N, 1.0 / max(ior, 1.0))) * thickness * modelScale;
}

// What light keeps after `distance` through the volume (attenuationDistance 0: nothing lost, the
// extension's infinity).
vec3 volumeAttenuation(vec3 radiance, float distance, vec3 attenuationColor,
                       float attenuationDistance)
{
    if (attenuationDistance <= 0.0 || distance <= 0.0)
        return radiance;
    return radiance * pow(attenuationColor, vec3(distance / attenuationDistance));
}

// The transmission lobe for one light behind the surface, times its cosine (radiance 1): the
// reflection's GGX lobe D V NdotL with the light mirrored through the surface's plane, at the
// transmission's alpha, times what the reflection leaves of it: 1 - F at that lobe's half vector
// (F from F0 to F90, as the reflection's), so that reflection and transmission share the lobe.
vec3 transmissionDirect(vec3 N, vec3 V, vec3 L, vec3 F0, float F90, float roughness, float ior)
{
    vec3 mirrored = L - 2.0 * N * dot(L, N);
    vec3 H = normalize(mirrored + V);
    float NdotL = clamp(dot(N, mirrored), 0.0, 1.0);
    float NdotV = clamp(dot(N, V), 0.0, 1.0);
    float alpha = max(iorScaledRoughness(roughness * roughness, ior), MIN_GGX_ALPHA);
    vec3 F = F0 + (F90 - F0) * pow(1.0 - clamp(dot(V, H), 0.0, 1.0), 5.0);
    return (1.0 - F) * (NdotL * D_GGX(clamp(dot(N, H), 0.0, 1.0), alpha) * V_GGX(NdotL, NdotV, alpha));
}

// ---- The layers together ----
// A surface of the advanced material at one point: the core material's (Appendix B, with the
// dielectric's F0 and F90 of ior and specular), the sheen over it and the clear coat over both.
// Without the extensions (clearcoat 0, sheenColor 0, transmission 0, ior 1.5, specular 1) it is
// the core's.
struct LayeredSurface
{
    vec3 N;
    vec3 diffuseColor;
    vec3 F0;
    float F90;
    vec3 metalColor;  // the base colour: the metal's, and the transmission's tint
    float metallic;
    float roughness;
    vec3 sheenColor;
    float sheenRoughness;
    float clearcoat;
    float clearcoatRoughness;
    vec3 clearcoatN;
    float clearcoatF0;
    float transmission;
    float ior;
    float thickness;  // 0: thin-walled
    vec3 attenuationColor;
    float attenuationDistance;  // 0: no attenuation
};

// Radiance towards V from light arriving along L with `radiance`: the base lobes, scaled by what
// the sheen leaves of them, plus the sheen; then the coat mixed over it all. The sheen's albedo
// at the view and at the light comes from its table (the caller reads it). The transmission's
// share sees the light from where the refracted ray leaves the volume: along exitL, with
// exitRadiance (after the volume's attenuation; L and radiance when thin-walled).
vec3 layeredDirectLight(LayeredSurface s, vec3 V, vec3 L, vec3 radiance, vec3 exitL,
                        vec3 exitRadiance, float sheenAlbedoAtV, float sheenAlbedoAtL)
{
    GltfBrdf b = gltfBrdfF90(s.N, V, L, s.diffuseColor, s.F0, s.F90, s.metalColor, s.metallic,
                             s.roughness);
    vec3 base = vec3(0.0);
    if (dot(s.N, L) > 0.0)  // gltfDirectLight's, to the bit, without transmission
        base = (b.diffuse * (1.0 - s.transmission) + b.specular) * radiance * b.NdotL;
    if (s.transmission > 0.0)
        base += (1.0 - s.metallic) * s.transmission * s.metalColor * exitRadiance *
                transmissionDirect(s.N, V, exitL, s.F0, s.F90, s.roughness, s.ior);
    vec3 sheened = sheenDirect(s.N, V, L, s.sheenColor, s.sheenRoughness) * radiance +
                   base * sheenAlbedoScaling(s.sheenColor, sheenAlbedoAtV, sheenAlbedoAtL);
    float coatWeight = s.clearcoat * clearcoatFresnel(s.clearcoatF0, dot(s.clearcoatN, V));
    vec3 coat = clearcoatDirect(s.clearcoatN, V, L, s.clearcoatRoughness) * radiance;
    return coatOver(sheened, coat, coatWeight);
}

// The image-based light of the layers, before occlusion: the base's split sum (ambientLightGltf's,
// with F90), its diffuse share giving way by the transmission factor to what comes through the
// surface (`transmitted`, the backdrop's radiance along the refracted ray, after the volume),
// tinted by the base colour; the sheen, the environment prefiltered by its lobe times its albedo
// at the view, over the base scaled by what the sheen leaves; the coat's lobe, the environment
// prefiltered at its roughness along its reflection times the lobe's albedo (scale + bias: its
// Fresnel is the mix's), mixed over it all. `base` and `coat` are the split sum's reads at the
// base's normal and roughness and at the coat's.
vec3 layeredAmbientLight(LayeredSurface s, SplitSumReads base, SplitSumReads coat,
                         vec3 sheenRadiance, float sheenAlbedoAtV, vec3 transmitted)
{
    vec3 dielectricAlbedo, metalAlbedo, dielectricMultiple, metalMultiple;
    vec3 dielectricSpecular =
        specularIblF90(s.F0, s.F90, base, dielectricAlbedo, dielectricMultiple);
    vec3 metal = specularIblF90(s.metalColor, 1.0, base, metalAlbedo, metalMultiple);
    vec3 diffuse = mix(s.diffuseColor * base.irradiance, s.metalColor * transmitted,
                       s.transmission) * (1.0 - dielectricAlbedo);
    vec3 core = mix(diffuse + dielectricSpecular, metal, s.metallic);
    vec3 sheened = s.sheenColor * sheenRadiance * sheenAlbedoAtV +
                   core * (1.0 - max3(s.sheenColor) * sheenAlbedoAtV);
    float coatWeight = s.clearcoat * clearcoatFresnel(s.clearcoatF0, coat.NdotV);
    vec3 coatLight = coat.prefilteredColor * (coat.envBRDF.x + coat.envBRDF.y);
    return coatOver(sheened, coatLight, coatWeight);
}
