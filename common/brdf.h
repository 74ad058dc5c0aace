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
// The directional albedo of Charlie sheen (Estevez and Kulla; Ashikhmin's visibility), what the
// LUT's B channel holds: integral of D_Charlie(alpha = roughness^2) V_Ashikhmin NdotL dl.
double sheenQuadrature(double NdotV, double roughness);
// The same sums over light directions directly, on a uniform grid of `steps` x 4 `steps`
// midpoints in (theta_l, phi_l): slow, and fit only for wide lobes (roughness >= 0.4); kept as
// a check of the half-vector quadrature itself.
glm::dvec3 bruteForceLut(double NdotV, double roughness, int steps);

// Reinhard c / (c + 1), then gamma 1/2.2: what the direct-light samples write.
glm::vec3 reinhardGamma(const glm::vec3& color);

}  // namespace pbr::cpu
