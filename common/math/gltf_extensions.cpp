#include "math/gltf_extensions.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "math/brdf.h"

namespace pbr::cpu {

float iorToF0(float ior) {
    const float r = (ior - 1.0f) / (ior + 1.0f);
    return r * r;
}

DielectricFresnel dielectricFresnel(float ior, const glm::vec3& specularColor, float specular) {
    DielectricFresnel f;
    f.F0 = glm::min(glm::vec3(iorToF0(ior)) * specularColor, glm::vec3(1.0f)) * specular;
    f.F90 = specular;
    return f;
}

float clearcoatFresnel(float F0, float NdotV) {
    return F0 + (1.0f - F0) * std::pow(1.0f - std::clamp(NdotV, 0.0f, 1.0f), 5.0f);
}

float clearcoatDirect(const glm::vec3& coatN, const glm::vec3& V, const glm::vec3& L,
                      float roughness) {
    const float NdotL = std::clamp(glm::dot(coatN, L), 0.0f, 1.0f);
    const float NdotV = std::clamp(glm::dot(coatN, V), 0.0f, 1.0f);
    const float NdotH = std::clamp(glm::dot(coatN, glm::normalize(V + L)), 0.0f, 1.0f);
    const float alpha = std::max(roughness * roughness, kMinGgxAlpha);
    return NdotL * D_GGX(NdotH, alpha) * V_GGX(NdotL, NdotV, alpha);
}

glm::vec3 coatOver(const glm::vec3& base, const glm::vec3& coat, float coatWeight) {
    return glm::mix(base, coat, coatWeight);
}

float D_Charlie(float NdotH, float alpha) {
    const float invAlpha = 1.0f / alpha;
    const float sin2h = std::max(1.0f - NdotH * NdotH, 0.0f);
    return (2.0f + invAlpha) * std::pow(sin2h, invAlpha * 0.5f) / (2.0f * std::numbers::pi_v<float>);
}

float charlieL(float x, float alpha) {
    const float t = (1.0f - alpha) * (1.0f - alpha);
    const float a = glm::mix(21.5473f, 25.3245f, t);
    const float b = glm::mix(3.82987f, 3.32435f, t);
    const float c = glm::mix(0.19823f, 0.16801f, t);
    const float d = glm::mix(-1.97760f, -1.27393f, t);
    const float e = glm::mix(-4.32054f, -4.85967f, t);
    return a / (1.0f + b * std::pow(x, c)) + d * x + e;
}

float lambdaSheen(float cosTheta, float alpha) {
    return std::abs(cosTheta) < 0.5f
               ? std::exp(charlieL(cosTheta, alpha))
               : std::exp(2.0f * charlieL(0.5f, alpha) - charlieL(1.0f - cosTheta, alpha));
}

float V_Sheen(float NdotL, float NdotV, float alpha) {
    const float g = 1.0f + lambdaSheen(NdotV, alpha) + lambdaSheen(NdotL, alpha);
    return std::clamp(1.0f / (g * 4.0f * NdotV * NdotL), 0.0f, 1.0f);
}

glm::vec3 sheenDirect(const glm::vec3& N, const glm::vec3& V, const glm::vec3& L,
                      const glm::vec3& sheenColor, float sheenRoughness) {
    const float NdotL = std::clamp(glm::dot(N, L), 0.0f, 1.0f);
    const float NdotV = std::clamp(glm::dot(N, V), 0.0f, 1.0f);
    if (NdotL <= 0.0f || NdotV <= 0.0f) return glm::vec3(0.0f);
    const float NdotH = std::clamp(glm::dot(N, glm::normalize(V + L)), 0.0f, 1.0f);
    const float alpha = std::max(sheenRoughness * sheenRoughness, kMinSheenAlpha);
    return sheenColor * (NdotL * D_Charlie(NdotH, alpha) * V_Sheen(NdotL, NdotV, alpha));
}

float max3(const glm::vec3& v) {
    return std::max(v.x, std::max(v.y, v.z));
}

float sheenAlbedoScaling(const glm::vec3& sheenColor, float albedoAtV, float albedoAtL) {
    const float strength = max3(sheenColor);
    return std::min(1.0f - strength * albedoAtV, 1.0f - strength * albedoAtL);
}

double sheenAlbedoQuadrature(double NdotV, double sheenRoughness) {
    const double alpha = std::max(sheenRoughness * sheenRoughness, double(kMinSheenAlpha));
    return integrateOverLights(NdotV, alpha, [&](const glm::dvec3& V, const glm::dvec3& L) {
        return double(sheenDirect(glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(V), glm::vec3(L),
                                  glm::vec3(1.0f), float(sheenRoughness))
                          .x);
    });
}

float iorScaledRoughness(float roughness, float ior) {
    return roughness * std::clamp(2.0f * ior - 2.0f, 0.0f, 1.0f);
}

glm::vec3 volumeRay(const glm::vec3& N, const glm::vec3& V, float thickness, float ior,
                    const glm::vec3& modelScale) {
    return glm::normalize(glm::refract(-V, N, 1.0f / std::max(ior, 1.0f))) * thickness * modelScale;
}

glm::vec3 volumeAttenuation(const glm::vec3& radiance, float distance,
                            const glm::vec3& attenuationColor, float attenuationDistance) {
    if (attenuationDistance <= 0.0f || distance <= 0.0f) return radiance;
    return radiance * glm::pow(attenuationColor, glm::vec3(distance / attenuationDistance));
}

glm::vec3 transmissionDirect(const glm::vec3& N, const glm::vec3& V, const glm::vec3& L,
                             const glm::vec3& F0, float F90, float roughness, float ior) {
    const glm::vec3 mirrored = L - 2.0f * N * glm::dot(L, N);
    const glm::vec3 H = glm::normalize(mirrored + V);
    const float NdotL = std::clamp(glm::dot(N, mirrored), 0.0f, 1.0f);
    const float NdotV = std::clamp(glm::dot(N, V), 0.0f, 1.0f);
    const float alpha = std::max(iorScaledRoughness(roughness * roughness, ior), kMinGgxAlpha);
    const glm::vec3 F =
        F0 + (F90 - F0) * std::pow(1.0f - std::clamp(glm::dot(V, H), 0.0f, 1.0f), 5.0f);
    return (1.0f - F) *
           (NdotL * D_GGX(std::clamp(glm::dot(N, H), 0.0f, 1.0f), alpha) * V_GGX(NdotL, NdotV, alpha));
}

glm::vec3 emission(const glm::vec3& emissive, float strength, float coatWeight) {
    return emissive * strength * (1.0f - coatWeight);
}

glm::vec3 layeredDirectLight(const LayeredSurface& s, const glm::vec3& V, const glm::vec3& L,
                             const glm::vec3& radiance, const glm::vec3& exitL,
                             const glm::vec3& exitRadiance, float sheenAlbedoAtV,
                             float sheenAlbedoAtL) {
    const GltfSurface surface{glm::vec3(0.0f), s.N,          s.diffuseColor, s.F0,
                              s.roughness,     s.metalColor, s.metallic,     s.F90};
    const GltfBrdf b = gltfBrdf(s.N, V, L, surface);
    glm::vec3 base(0.0f);
    if (glm::dot(s.N, L) > 0.0f)  // gltfDirectLight's, to the bit, without transmission
        base = (b.diffuse * (1.0f - s.transmission) + b.specular) * radiance * b.NdotL;
    if (s.transmission > 0.0f) {
        base += (1.0f - s.metallic) * s.transmission * s.metalColor * exitRadiance *
                transmissionDirect(s.N, V, exitL, s.F0, s.F90, s.roughness, s.ior);
    }
    const glm::vec3 sheened =
        sheenDirect(s.N, V, L, s.sheenColor, s.sheenRoughness) * radiance +
        base * sheenAlbedoScaling(s.sheenColor, sheenAlbedoAtV, sheenAlbedoAtL);
    const float coatWeight = s.clearcoat * clearcoatFresnel(s.clearcoatF0, glm::dot(s.clearcoatN, V));
    const glm::vec3 coat = clearcoatDirect(s.clearcoatN, V, L, s.clearcoatRoughness) * radiance;
    return coatOver(sheened, coat, coatWeight);
}

glm::vec3 layeredAmbientLight(const LayeredSurface& s, const SplitSumReads& base,
                              const SplitSumReads& coat, const glm::vec3& sheenRadiance,
                              float sheenAlbedoAtV, const glm::vec3& transmitted,
                              bool multipleScattering) {
    glm::vec3 dielectricAlbedo, metalAlbedo;
    const glm::vec3 dielectricSpecular =
        specularIblF90(s.F0, s.F90, base, multipleScattering, dielectricAlbedo);
    const glm::vec3 metal = specularIblF90(s.metalColor, 1.0f, base, multipleScattering, metalAlbedo);
    const glm::vec3 diffuse =
        glm::mix(s.diffuseColor * base.irradiance, s.metalColor * transmitted, s.transmission) *
        (1.0f - dielectricAlbedo);
    const glm::vec3 core = glm::mix(diffuse + dielectricSpecular, metal, s.metallic);
    const glm::vec3 sheened = s.sheenColor * sheenRadiance * sheenAlbedoAtV +
                              core * (1.0f - max3(s.sheenColor) * sheenAlbedoAtV);
    const float coatWeight = s.clearcoat * clearcoatFresnel(s.clearcoatF0, coat.NdotV);
    const glm::vec3 coatLight = coat.prefilteredColor * (coat.envBRDF.x + coat.envBRDF.y);
    return coatOver(sheened, coatLight, coatWeight);
}

}  // namespace pbr::cpu
