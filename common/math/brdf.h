#pragma once
// The Cook-Torrance BRDF of the tutorial on the CPU (GLM only, no GL): the same functions with the
// same names as shaders/include/brdf.glsl, so tests can shade a pixel independently of the GPU.
#include <functional>
#include <span>

#include <glm/glm.hpp>

#include "math/light_block.h"
#include "math/punctual_light.h"

namespace pbr::cpu {

float DistributionGGX(const glm::vec3& N, const glm::vec3& H, float roughness);
float GeometrySchlickGGX(float NdotV, float roughness);
float GeometrySmith(const glm::vec3& N, const glm::vec3& V, const glm::vec3& L, float roughness);
glm::vec3 fresnelSchlick(float cosTheta, const glm::vec3& F0);
// Fresnel of the view angle with the roughness folded in (Lagarde's form, LearnOpenGL PBR / IBL /
// Diffuse irradiance): F0 + (max(1 - roughness, F0) - F0) (1 - cosTheta)^5.
glm::vec3 fresnelSchlickRoughness(float cosTheta, const glm::vec3& F0, float roughness);

struct PointLight {
    glm::vec3 position;
    glm::vec3 color;
};

struct SurfacePoint {
    glm::vec3 position;  // world space
    glm::vec3 normal;    // unit
    glm::vec3 albedo;    // linear
    float metallic = 0.0f;
    float roughness = 0.5f;
    float ao = 1.0f;
};

// Radiance leaving `surface` towards `cameraPosition`: the sum over point lights (1/d^2 falloff)
// plus the tutorial's constant ambient 0.03 * albedo * ao. Linear, before tone mapping.
glm::vec3 shadePointLights(const SurfacePoint& surface, const glm::vec3& cameraPosition,
                           std::span<const PointLight> lights);

// The terms of the BRDF for one light direction L (cookTorrance of brdf.glsl): D, G, F, the
// specular term D G F / (4 NdotV NdotL + 0.001), kD = (1 - F)(1 - metallic), NdotL.
struct CookTorrance {
    float D = 0.0f;
    float G = 0.0f;
    glm::vec3 F{0.0f};
    glm::vec3 specular{0.0f};
    glm::vec3 kD{0.0f};
    float NdotL = 0.0f;
};
CookTorrance cookTorrance(const glm::vec3& N, const glm::vec3& V, const glm::vec3& L,
                          const glm::vec3& albedo, float metallic, float roughness);

// One light's share: (kD albedo / pi + specular) radiance NdotL, the text's integrand for one
// direction (directLight of brdf.glsl).
glm::vec3 directLight(const glm::vec3& N, const glm::vec3& V, const glm::vec3& L,
                      const glm::vec3& radiance, const glm::vec3& albedo, float metallic,
                      float roughness);

// Sample 09: the Overload engine's five light types (light_types.glsl) at `surface`: the direct
// lights through directLight, plus ambient x albedo x ao from every ambient volume holding the
// point (no constant ambient). Linear, before tone mapping.
glm::vec3 shadeLightTypes(const SurfacePoint& surface, const glm::vec3& cameraPosition,
                          std::span<const PackedLight> lights);
// What one light brings to `position`: a direct light's radiance there (attenuation and cone
// included) from the unit direction it sets in L; an ambient volume's colour where the volume
// holds the point, else 0 (L is then +Y, unused).
glm::vec3 lightTypeRadiance(const PackedLight& light, const glm::vec3& position, glm::vec3& L);
bool isAmbientVolume(const PackedLight& light);
// The parts, for tests: 1 / (c + l d + q d^2); the spot's cone factor for the unit direction
// from the point towards the light; whether a point lies in an ambient volume.
float lightAttenuation(const PackedLight& light, float distance);
float spotCone(const PackedLight& light, const glm::vec3& toLight);
bool insideAmbientVolume(const PackedLight& light, const glm::vec3& point);

// The ambient light of the split-sum IBL at one point, from its three reads there: the
// irradiance map's value at N, the prefiltered radiance along R and the LUT's (scale, bias) at
// (NdotV, roughness). Its two parts before occlusion, in one of two forms (ibl_ambient.glsl):
//   the text's:  diffuse = (1 - F)(1 - metallic) irradiance albedo, F = fresnelSchlickRoughness,
//                specular = prefiltered (F scale + bias);
//   the exact:   diffuse = (1 - metallic) albedo irradiance (1 - (0.04 scale + bias)), what the
//                dielectric's specular lobe leaves; specular = prefiltered (F0 scale + bias).
struct SplitSumAmbient {
    glm::vec3 diffuse{0.0f};
    glm::vec3 specular{0.0f};
};
SplitSumAmbient splitSumAmbient(float NdotV, const glm::vec3& albedo, float metallic,
                                float roughness, const glm::vec3& irradiance,
                                const glm::vec3& prefiltered, const glm::vec2& scaleBias,
                                bool exact);

// Reference values of the BRDF LUT by deterministic numerical quadrature, not sampling: the
// integrand is summed over half vectors h with Gauss-Legendre rules on panels of theta_h graded
// towards where each lobe concentrates (around the normal for GGX, at the horizon for Charlie),
// and the midpoint rule in phi_h; light direction l = reflect(-v, h), dl = 4 (v.h) dh. Double
// precision. Independent of the shaders' importance sampling, so it can judge them.
//
// The split-sum integral of the GGX specular lobe (Karis): the scale (x) and bias (y) to F0,
//   x = integral of D G (1 - Fc) / (4 NdotL NdotV) NdotL dl,   y = the same with Fc,
// Fc = (1 - VdotH)^5, D = GGX with alpha = roughness^2, G = Smith-Schlick with k = roughness^2 / 2.
glm::dvec2 splitSumQuadrature(double NdotV, double roughness);
// The same for the glTF BRDF (what BrdfLutChannels::GltfScaleBias holds): G / (4 NdotL NdotV)
// replaced by its height-correlated Smith visibility V_GGX, the one its direct light has.
glm::dvec2 gltfSplitSumQuadrature(double NdotV, double roughness);
// The directional albedo of Charlie sheen (Estevez and Kulla; Ashikhmin's visibility), what the
// LUT's B channel holds: integral of D_Charlie(alpha = roughness^2) V_Ashikhmin NdotL dl.
double sheenQuadrature(double NdotV, double roughness);
// The integral over the light directions l of the upper hemisphere (z up) of integrand(V, L) dl,
// V = (sqrt(1 - NdotV^2), 0, NdotV), by the half-vector quadrature above, its panels graded for
// lobes of width alpha (GGX's around the normal, Charlie's at the horizon). The integrand must be
// isotropic (mirror-symmetric about the xz plane).
double integrateOverLights(double NdotV, double alpha,
                           const std::function<double(const glm::dvec3&, const glm::dvec3&)>& integrand);
// The same sums over light directions directly, on a uniform grid of `steps` x 4 `steps`
// midpoints in (theta_l, phi_l): slow, and fit only for wide lobes (roughness >= 0.4); kept as
// a check of the half-vector quadrature itself.
glm::dvec3 bruteForceLut(double NdotV, double roughness, int steps);

// ---- glTF 2.0, Appendix B, and KHR_lights_punctual (the glTF samples 07, 08) ----
// The same functions as shaders/include/brdf.glsl and punctual_lights.glsl.
float D_GGX(float NdotH, float alpha);
float V_GGX(float NdotL, float NdotV, float alpha);
constexpr float kMinGgxAlpha = 0.002f;  // MIN_GGX_ALPHA of brdf.glsl
// A surface as the Appendix B implementation takes it (both workflows end here): a dielectric
// layer (diffuse colour c_diff under a specular layer of reflectance F0) and a metal of colour
// metalColor, mixed by metallic.
struct GltfSurface {
    glm::vec3 position;  // world space
    glm::vec3 normal;    // unit, shading normal
    glm::vec3 diffuseColor;
    glm::vec3 F0;
    float roughness = 0.5f;  // perceptual
    glm::vec3 metalColor{0.0f};
    float metallic = 0.0f;
    float F90 = 1.0f;  // the dielectric's grazing reflectance (KHR_materials_specular's strength)
};
// The metallic-roughness workflow: c_diff = metalColor = base colour, F0 = 0.04.
GltfSurface metallicRoughnessSurface(const glm::vec3& position, const glm::vec3& normal,
                                     const glm::vec3& baseColor, float metallic, float roughness);
// KHR_materials_pbrSpecularGlossiness' conversion: F0 = specular, roughness = 1 - glossiness,
// c_diff = diffuse x (1 - the largest component of specular), metallic 0.
GltfSurface specularGlossinessSurface(const glm::vec3& position, const glm::vec3& normal,
                                      const glm::vec3& diffuse, const glm::vec3& specular,
                                      float glossiness);
// The terms of that BRDF for one light direction (brdf.glsl's gltfBrdf): D, the visibility
// Vis = G / (4 NdotL NdotV), F of the dielectric and metal mixed, the diffuse and specular lobes
// before radiance and NdotL, NdotL and NdotV.
struct GltfBrdf {
    float D = 0.0f;
    float Vis = 0.0f;
    glm::vec3 F{0.0f};
    glm::vec3 diffuse{0.0f};
    glm::vec3 specular{0.0f};
    float NdotL = 0.0f;
    float NdotV = 0.0f;
};
GltfBrdf gltfBrdf(const glm::vec3& N, const glm::vec3& V, const glm::vec3& L,
                  const GltfSurface& surface);
// The glTF samples' image-based light at a point, from the split sum's three reads there (see
// splitSumAmbient): its parts before occlusion, which mix(diffuse + dielectricSpecular, metal,
// metallic) sums. A lobe of reflectance F0 returns E_ss = F0 scale + bias of the prefiltered
// radiance; with multiple scattering (Fdez-Aguera, JCGT 2019) also
// E_ms = (1 - scale - bias) F_avg E_ss / (1 - F_avg (1 - scale - bias)) of the irradiance,
// F_avg = F0 + (1 - F0) / 21; the dielectric's diffuse layer gets 1 - (E_ss + E_ms) of its lobe.
// The split sum's three reads at one surface point (ibl_ambient.glsl's SplitSumReads).
struct SplitSumReads {
    float NdotV = 1.0f;
    glm::vec3 irradiance{0.0f};        // at N
    glm::vec3 prefilteredColor{0.0f};  // along R, at the roughness's level
    glm::vec2 envBRDF{0.0f};           // the LUT's (scale, bias)
};
// What a lobe of reflectance F0 (head-on) to F90 (grazing) returns of the environment, and in
// `albedo` the share of the light it takes (ibl_ambient.glsl's specularIblF90).
glm::vec3 specularIblF90(const glm::vec3& F0, float F90, const SplitSumReads& reads,
                         bool multipleScattering, glm::vec3& albedo);
struct GltfAmbient {
    glm::vec3 diffuse{0.0f};
    glm::vec3 dielectricSpecular{0.0f};
    glm::vec3 metal{0.0f};
};
GltfAmbient gltfAmbient(const GltfSurface& surface, const glm::vec3& irradiance,
                        const glm::vec3& prefiltered, const glm::vec2& scaleBias,
                        bool multipleScattering);
// mix(dielectric BRDF, metal BRDF, metallic) for one light (brdf.glsl's gltfDirectLight).
glm::vec3 gltfDirectLight(const glm::vec3& N, const glm::vec3& V, const glm::vec3& L,
                          const glm::vec3& radiance, const GltfSurface& surface);
float rangeAttenuation(float range, float distance);
float spotAttenuation(const glm::vec3& lightToPoint, const glm::vec3& spotDirection,
                      float outerConeCos, float innerConeCos);
// The radiance `light` brings to `position`, and the unit direction towards it in `L`.
glm::vec3 punctualRadiance(const PunctualLight& light, const glm::vec3& position, glm::vec3& L);
// Radiance towards `cameraPosition` from the punctual lights (no image-based light, no
// emission), linear, before exposure and tone mapping.
glm::vec3 shadePunctualLights(const GltfSurface& surface, const glm::vec3& cameraPosition,
                              std::span<const PunctualLight> lights);

// Reinhard c / (c + 1), then gamma 1/2.2: what the direct-light samples write.
glm::vec3 reinhardGamma(const glm::vec3& color);

}  // namespace pbr::cpu
