#pragma once
// The layers of the advanced glTF materials on the CPU: the same functions with the same names as
// shaders/include/gltf_extensions.glsl (KHR_materials_ior, _specular, _clearcoat, _sheen,
// _emissive_strength, _transmission, _volume), so tests can integrate them and compare the
// shaders with them.
#include <glm/glm.hpp>

#include "math/brdf.h"

namespace pbr::cpu {

// KHR_materials_ior: ((ior - 1) / (ior + 1))^2.
float iorToF0(float ior);

// KHR_materials_specular: F0 = min(iorToF0(ior) specularColor, 1) specular, F90 = specular.
struct DielectricFresnel {
    glm::vec3 F0{0.04f};
    float F90 = 1.0f;
};
DielectricFresnel dielectricFresnel(float ior, const glm::vec3& specularColor, float specular);

// KHR_materials_clearcoat: the coat's Fresnel F0 + (1 - F0)(1 - NdotV)^5 at its normal, its GGX
// lobe for one light times NdotL (D V NdotL, alpha = roughness^2), and the mix of the layer
// beneath with the coat's light by clearcoat x that Fresnel.
float clearcoatFresnel(float F0, float NdotV);
float clearcoatDirect(const glm::vec3& coatN, const glm::vec3& V, const glm::vec3& L,
                      float roughness);
glm::vec3 coatOver(const glm::vec3& base, const glm::vec3& coat, float coatWeight);

// KHR_materials_sheen: the Charlie distribution and visibility (alpha = sheenRoughness^2), the
// lobe for one light times NdotL, and what the layer beneath keeps.
float D_Charlie(float NdotH, float alpha);
float charlieL(float x, float alpha);
float lambdaSheen(float cosTheta, float alpha);
float V_Sheen(float NdotL, float NdotV, float alpha);
constexpr float kMinSheenAlpha = 1e-6f;  // MIN_SHEEN_ALPHA of gltf_extensions.glsl
glm::vec3 sheenDirect(const glm::vec3& N, const glm::vec3& V, const glm::vec3& L,
                      const glm::vec3& sheenColor, float sheenRoughness);
float max3(const glm::vec3& v);
float sheenAlbedoScaling(const glm::vec3& sheenColor, float albedoAtV, float albedoAtL);
// The directional albedo of a white sheen (the table the albedo scaling reads): the integral of
// D_Charlie V_Sheen NdotL over light directions, by numerical quadrature (integrateOverLights).
double sheenAlbedoQuadrature(double NdotV, double sheenRoughness);

// KHR_materials_transmission and KHR_materials_volume: the transmission lobe's roughness (down to
// none as ior nears 1), the refracted ray through the volume (0 when thin-walled), Beer-Lambert's
// attenuation along it (attenuationDistance 0: none), and the lobe for one light behind the
// surface times its cosine: the reflection's D V NdotL with the light mirrored through the plane,
// times 1 - F at that lobe's half vector (what the reflection leaves).
float iorScaledRoughness(float roughness, float ior);
glm::vec3 volumeRay(const glm::vec3& N, const glm::vec3& V, float thickness, float ior,
                    const glm::vec3& modelScale);
glm::vec3 volumeAttenuation(const glm::vec3& radiance, float distance,
                            const glm::vec3& attenuationColor, float attenuationDistance);
glm::vec3 transmissionDirect(const glm::vec3& N, const glm::vec3& V, const glm::vec3& L,
                             const glm::vec3& F0, float F90, float roughness, float ior);

// KHR_materials_emissive_strength, seen through the clear coat: emissive strength (1 - coatWeight).
glm::vec3 emission(const glm::vec3& emissive, float strength, float coatWeight);

// The layers together (gltf_extensions.glsl's LayeredSurface): the core material's surface with
// the dielectric's F0 and F90, the sheen over it, the clear coat over both.
struct LayeredSurface {
    glm::vec3 N{0.0f, 0.0f, 1.0f};
    glm::vec3 diffuseColor{1.0f};
    glm::vec3 F0{0.04f};
    float F90 = 1.0f;
    glm::vec3 metalColor{1.0f};  // the base colour: the metal's, and the transmission's tint
    float metallic = 0.0f;
    float roughness = 0.5f;
    glm::vec3 sheenColor{0.0f};
    float sheenRoughness = 0.0f;
    float clearcoat = 0.0f;
    float clearcoatRoughness = 0.0f;
    glm::vec3 clearcoatN{0.0f, 0.0f, 1.0f};
    float clearcoatF0 = 0.04f;
    float transmission = 0.0f;
    float ior = 1.5f;
    float thickness = 0.0f;  // 0: thin-walled
    glm::vec3 attenuationColor{1.0f};
    float attenuationDistance = 0.0f;  // 0: no attenuation
};
// Radiance towards V from one light: the base lobes scaled by what the sheen leaves, plus the
// sheen, then the coat mixed over it all; the sheen's albedo at V and at L from its table. The
// transmission's share sees the light along exitL with exitRadiance (from where the refracted
// ray leaves the volume, after its attenuation; L and radiance when thin-walled).
glm::vec3 layeredDirectLight(const LayeredSurface& s, const glm::vec3& V, const glm::vec3& L,
                             const glm::vec3& radiance, const glm::vec3& exitL,
                             const glm::vec3& exitRadiance, float sheenAlbedoAtV,
                             float sheenAlbedoAtL);
// The layers' image-based light before occlusion, from the split sum's reads at the base and at
// the coat, the sheen's prefiltered radiance and its albedo at V, and the radiance transmitted
// from behind (the backdrop's, along the refracted ray, after the volume).
glm::vec3 layeredAmbientLight(const LayeredSurface& s, const SplitSumReads& base,
                              const SplitSumReads& coat, const glm::vec3& sheenRadiance,
                              float sheenAlbedoAtV, const glm::vec3& transmitted,
                              bool multipleScattering);

}  // namespace pbr::cpu
