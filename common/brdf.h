#pragma once
// The Cook-Torrance BRDF of the tutorial on the CPU (GLM only, no GL): the same functions with the
// same names as shaders/include/brdf.glsl, so tests can shade a pixel independently of the GPU.
#include <span>

#include <glm/glm.hpp>

namespace pbr::cpu {

float DistributionGGX(const glm::vec3& N, const glm::vec3& H, float roughness);
float GeometrySchlickGGX(float NdotV, float roughness);
float GeometrySmith(const glm::vec3& N, const glm::vec3& V, const glm::vec3& L, float roughness);
glm::vec3 fresnelSchlick(float cosTheta, const glm::vec3& F0);

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

// The split-sum BRDF integral for image-based lighting: the scale (x) and bias (y) to F0 of
// the GGX specular lobe at NdotV and roughness (k = roughness^2 / 2), by importance sampling
// with `samples` Hammersley points, in double precision.
glm::dvec2 integrateBrdf(double NdotV, double roughness, int samples);
// The Charlie sheen term of the cookbook's LUT (its B channel): Charlie importance sampling,
// sum of V_Ashikhmin * D_Charlie * NdotL * VdotH over the samples, divided by their count.
double integrateSheen(double NdotV, double roughness, int samples);

// Reinhard c / (c + 1), then gamma 1/2.2: what the direct-light samples write.
glm::vec3 reinhardGamma(const glm::vec3& color);

}  // namespace pbr::cpu
