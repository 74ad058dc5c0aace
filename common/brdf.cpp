#include "brdf.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace pbr::cpu {

namespace {
constexpr float PI = std::numbers::pi_v<float>;
}

float DistributionGGX(const glm::vec3& N, const glm::vec3& H, float roughness) {
    const float a = roughness * roughness;  // Disney/Epic: the NDF takes roughness squared
    const float a2 = a * a;
    const float NdotH = std::max(glm::dot(N, H), 0.0f);
    const float denom = NdotH * NdotH * (a2 - 1.0f) + 1.0f;
    return a2 / (PI * denom * denom);
}

float GeometrySchlickGGX(float NdotV, float roughness) {
    const float r = roughness + 1.0f;
    const float k = (r * r) / 8.0f;  // k for direct light
    return NdotV / (NdotV * (1.0f - k) + k);
}

float GeometrySmith(const glm::vec3& N, const glm::vec3& V, const glm::vec3& L, float roughness) {
    const float NdotV = std::max(glm::dot(N, V), 0.0f);
    const float NdotL = std::max(glm::dot(N, L), 0.0f);
    return GeometrySchlickGGX(NdotV, roughness) * GeometrySchlickGGX(NdotL, roughness);
}

glm::vec3 fresnelSchlick(float cosTheta, const glm::vec3& F0) {
    return F0 + (1.0f - F0) * std::pow(std::clamp(1.0f - cosTheta, 0.0f, 1.0f), 5.0f);
}

glm::vec3 shadePointLights(const SurfacePoint& s, const glm::vec3& cameraPosition,
                           std::span<const PointLight> lights) {
    const glm::vec3 N = s.normal;
    const glm::vec3 V = glm::normalize(cameraPosition - s.position);
    const glm::vec3 F0 = glm::mix(glm::vec3(0.04f), s.albedo, s.metallic);
    glm::vec3 Lo(0.0f);
    for (const PointLight& light : lights) {
        const glm::vec3 L = glm::normalize(light.position - s.position);
        const glm::vec3 H = glm::normalize(V + L);
        const float distance = glm::length(light.position - s.position);
        const glm::vec3 radiance = light.color / (distance * distance);

        const float NDF = DistributionGGX(N, H, s.roughness);
        const float G = GeometrySmith(N, V, L, s.roughness);
        const glm::vec3 F = fresnelSchlick(std::max(glm::dot(H, V), 0.0f), F0);
        const float NdotV = std::max(glm::dot(N, V), 0.0f);
        const float NdotL = std::max(glm::dot(N, L), 0.0f);
        // + 0.001 keeps the denominator off zero at grazing angles, as in the text.
        const glm::vec3 specular = NDF * G * F / (4.0f * NdotV * NdotL + 0.001f);
        const glm::vec3 kD = (glm::vec3(1.0f) - F) * (1.0f - s.metallic);
        Lo += (kD * s.albedo / PI + specular) * radiance * NdotL;
    }
    return glm::vec3(0.03f) * s.albedo * s.ao + Lo;
}

glm::vec3 reinhardGamma(const glm::vec3& color) {
    const glm::vec3 mapped = color / (color + glm::vec3(1.0f));
    return glm::pow(mapped, glm::vec3(1.0f / 2.2f));
}

namespace {
// Hammersley point i of `samples`: (i / N, the radical inverse of i in base 2).
glm::dvec2 hammersley(int i, int samples) {
    std::uint32_t bits = std::uint32_t(i);
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return {double(i) / samples, double(bits) * 2.3283064365386963e-10};
}

glm::dvec3 fromSpherical(double cosTheta, double phi) {
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}
}  // namespace

glm::dvec2 integrateBrdf(double NdotV, double roughness, int samples) {
    const glm::dvec3 V(std::sqrt(1.0 - NdotV * NdotV), 0.0, NdotV);
    const double a = roughness * roughness, k = roughness * roughness / 2.0;
    glm::dvec2 sum(0.0);
    for (int i = 0; i < samples; ++i) {
        const glm::dvec2 Xi = hammersley(i, samples);
        const double cosTheta = std::sqrt((1.0 - Xi.y) / (1.0 + (a * a - 1.0) * Xi.y));
        const glm::dvec3 H = fromSpherical(cosTheta, 2.0 * std::numbers::pi * Xi.x);
        const glm::dvec3 L = glm::normalize(2.0 * glm::dot(V, H) * H - V);
        const double NdotL = std::max(L.z, 0.0), NdotH = std::max(H.z, 0.0);
        const double VdotH = std::max(glm::dot(V, H), 0.0);
        if (NdotL <= 0.0) continue;
        const double G = (NdotV / (NdotV * (1.0 - k) + k)) * (NdotL / (NdotL * (1.0 - k) + k));
        const double visibility = G * VdotH / (NdotH * NdotV);
        const double Fc = std::pow(1.0 - VdotH, 5.0);
        sum += glm::dvec2((1.0 - Fc) * visibility, Fc * visibility);
    }
    return sum / double(samples);
}

double integrateSheen(double NdotV, double roughness, int samples) {
    const glm::dvec3 V(std::sqrt(1.0 - NdotV * NdotV), 0.0, NdotV);
    const double alpha = roughness * roughness;
    const double invR = 1.0 / std::max(roughness, 0.000001);
    double sum = 0.0;
    for (int i = 0; i < samples; ++i) {
        const glm::dvec2 Xi = hammersley(i, samples);
        const double sinTheta = std::pow(Xi.y, alpha / (2.0 * alpha + 1.0));
        const glm::dvec3 H = fromSpherical(std::sqrt(std::max(0.0, 1.0 - sinTheta * sinTheta)),
                                           2.0 * std::numbers::pi * Xi.x);
        const glm::dvec3 L = 2.0 * glm::dot(V, H) * H - V;
        const double NdotL = std::max(L.z, 0.0), NdotH = std::max(H.z, 0.0);
        const double VdotH = std::max(glm::dot(V, H), 0.0);
        if (NdotL <= 0.0) continue;
        const double visibility =
            std::clamp(1.0 / (4.0 * (NdotL + NdotV - NdotL * NdotV)), 0.0, 1.0);  // Ashikhmin
        const double charlie = (2.0 + invR) *
                               std::pow(std::max(1.0 - NdotH * NdotH, 0.0), invR * 0.5) /
                               (2.0 * std::numbers::pi);
        sum += visibility * charlie * NdotL * VdotH;
    }
    return sum / double(samples);
}

}  // namespace pbr::cpu
