#include "math/brdf.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <vector>

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

glm::vec3 fresnelSchlickRoughness(float cosTheta, const glm::vec3& F0, float roughness) {
    const glm::vec3 grazing = glm::max(glm::vec3(1.0f - roughness), F0);  // the rim's reflectance
    return F0 + (grazing - F0) * std::pow(std::clamp(1.0f - cosTheta, 0.0f, 1.0f), 5.0f);
}

SplitSumAmbient splitSumAmbient(float NdotV, const glm::vec3& albedo, float metallic,
                                float roughness, const glm::vec3& irradiance,
                                const glm::vec3& prefiltered, const glm::vec2& scaleBias,
                                bool exact) {
    const glm::vec3 F0 = glm::mix(glm::vec3(0.04f), albedo, metallic);
    const float scale = scaleBias.x, bias = scaleBias.y;
    SplitSumAmbient ambient;
    if (exact) {
        const float dielectricAlbedo = 0.04f * scale + bias;  // what a dielectric's lobe reflects
        ambient.diffuse = (1.0f - metallic) * (1.0f - dielectricAlbedo) * albedo * irradiance;
        ambient.specular = (F0 * scale + bias) * prefiltered;
    } else {
        const glm::vec3 F = fresnelSchlickRoughness(NdotV, F0, roughness);
        ambient.diffuse = (1.0f - F) * (1.0f - metallic) * albedo * irradiance;
        ambient.specular = (F * scale + bias) * prefiltered;
    }
    return ambient;
}

CookTorrance cookTorrance(const glm::vec3& N, const glm::vec3& V, const glm::vec3& L,
                          const glm::vec3& albedo, float metallic, float roughness) {
    CookTorrance t;
    const glm::vec3 F0 = glm::mix(glm::vec3(0.04f), albedo, metallic);
    const glm::vec3 H = glm::normalize(V + L);
    t.D = DistributionGGX(N, H, roughness);
    t.G = GeometrySmith(N, V, L, roughness);
    t.F = fresnelSchlick(std::max(glm::dot(H, V), 0.0f), F0);
    const float NdotV = std::max(glm::dot(N, V), 0.0f);
    t.NdotL = std::max(glm::dot(N, L), 0.0f);
    // + 0.001 keeps the denominator off zero at grazing angles, as in the text.
    t.specular = t.D * t.G * t.F / (4.0f * NdotV * t.NdotL + 0.001f);
    t.kD = (glm::vec3(1.0f) - t.F) * (1.0f - metallic);
    return t;
}

glm::vec3 directLight(const glm::vec3& N, const glm::vec3& V, const glm::vec3& L,
                      const glm::vec3& radiance, const glm::vec3& albedo, float metallic,
                      float roughness) {
    const CookTorrance t = cookTorrance(N, V, L, albedo, metallic, roughness);
    return (t.kD * albedo / PI + t.specular) * radiance * t.NdotL;
}

glm::vec3 shadePointLights(const SurfacePoint& s, const glm::vec3& cameraPosition,
                           std::span<const PointLight> lights) {
    const glm::vec3 V = glm::normalize(cameraPosition - s.position);
    glm::vec3 Lo(0.0f);
    for (const PointLight& light : lights) {
        const glm::vec3 L = glm::normalize(light.position - s.position);
        const float distance = glm::length(light.position - s.position);
        Lo += directLight(s.normal, V, L, light.color / (distance * distance), s.albedo, s.metallic,
                          s.roughness);
    }
    return glm::vec3(0.03f) * s.albedo * s.ao + Lo;
}

float lightAttenuation(const PackedLight& light, float d) {
    return 1.0f / (light.constant() + light.linear() * d + light.quadratic() * d * d);
}

float spotCone(const PackedLight& light, const glm::vec3& toLight) {
    const float cutOff = std::cos(glm::radians(light.cutoff()));
    const float outerCutOff = std::cos(glm::radians(light.outerCutoff()));
    const float theta = glm::dot(toLight, glm::normalize(-light.forward()));
    return std::clamp((theta - outerCutOff) / (cutOff - outerCutOff), 0.0f, 1.0f);
}

bool insideAmbientVolume(const PackedLight& light, const glm::vec3& p) {
    if (light.type() == LightType::AmbientBox) {
        const glm::vec3 d = glm::abs(p - light.position());
        const glm::vec3 half = light.halfSize();
        return d.x < half.x && d.y < half.y && d.z < half.z;
    }
    if (light.type() == LightType::AmbientSphere)
        return glm::distance(p, light.position()) < light.radius();
    return false;
}

glm::vec3 lightTypeRadiance(const PackedLight& light, const glm::vec3& position, glm::vec3& L) {
    const glm::vec3 color = light.color() * light.intensity();
    L = glm::vec3(0.0f, 1.0f, 0.0f);
    switch (light.type()) {
        case LightType::AmbientBox:
        case LightType::AmbientSphere:
            return insideAmbientVolume(light, position) ? color : glm::vec3(0.0f);
        case LightType::Directional:
            L = glm::normalize(-light.forward());
            return color;
        case LightType::Point:
        case LightType::Spot: {
            const glm::vec3 toLight = light.position() - position;
            L = glm::normalize(toLight);
            float coefficient = lightAttenuation(light, glm::length(toLight));
            if (light.type() == LightType::Spot) coefficient *= spotCone(light, L);
            return color * coefficient;
        }
    }
    return glm::vec3(0.0f);
}

bool isAmbientVolume(const PackedLight& light) {
    return light.type() == LightType::AmbientBox || light.type() == LightType::AmbientSphere;
}

glm::vec3 shadeLightTypes(const SurfacePoint& s, const glm::vec3& cameraPosition,
                          std::span<const PackedLight> lights) {
    const glm::vec3 V = glm::normalize(cameraPosition - s.position);
    glm::vec3 Lo(0.0f), ambient(0.0f);
    for (const PackedLight& light : lights) {
        glm::vec3 L;
        const glm::vec3 radiance = lightTypeRadiance(light, s.position, L);
        if (isAmbientVolume(light))
            ambient += radiance;
        else
            Lo += directLight(s.normal, V, L, radiance, s.albedo, s.metallic, s.roughness);
    }
    return ambient * s.albedo * s.ao + Lo;
}

float D_GGX(float NdotH, float alpha) {
    const float a2 = alpha * alpha;
    const float f = NdotH * NdotH * (a2 - 1.0f) + 1.0f;
    return a2 / (PI * f * f);
}

float V_GGX(float NdotL, float NdotV, float alpha) {
    const float a2 = alpha * alpha;
    const float ggxV = NdotL * std::sqrt(NdotV * NdotV * (1.0f - a2) + a2);
    const float ggxL = NdotV * std::sqrt(NdotL * NdotL * (1.0f - a2) + a2);
    const float sum = ggxV + ggxL;
    return sum > 0.0f ? 0.5f / sum : 0.0f;
}

GltfSurface metallicRoughnessSurface(const glm::vec3& position, const glm::vec3& normal,
                                     const glm::vec3& baseColor, float metallic, float roughness) {
    return {position, normal, baseColor, glm::vec3(0.04f), roughness, baseColor, metallic};
}

GltfSurface specularGlossinessSurface(const glm::vec3& position, const glm::vec3& normal,
                                      const glm::vec3& diffuse, const glm::vec3& specular,
                                      float glossiness) {
    const float strongest = std::max(specular.r, std::max(specular.g, specular.b));
    return {position, normal, diffuse * (1.0f - strongest), specular, 1.0f - glossiness};
}

GltfBrdf gltfBrdf(const glm::vec3& N, const glm::vec3& V, const glm::vec3& L,
                  const GltfSurface& s) {
    GltfBrdf b;
    b.NdotL = std::clamp(glm::dot(N, L), 0.0f, 1.0f);
    const glm::vec3 H = glm::normalize(V + L);
    b.NdotV = std::clamp(glm::dot(N, V), 0.0f, 1.0f);
    const float NdotH = std::clamp(glm::dot(N, H), 0.0f, 1.0f);
    const float VdotH = std::clamp(glm::dot(V, H), 0.0f, 1.0f);
    const float alpha = std::max(s.roughness * s.roughness, kMinGgxAlpha);
    const float schlick = std::pow(1.0f - VdotH, 5.0f);
    const glm::vec3 dielectricF = s.F0 + (s.F90 - s.F0) * schlick;
    const glm::vec3 metalF = s.metalColor + (1.0f - s.metalColor) * schlick;
    b.D = D_GGX(NdotH, alpha);
    b.Vis = V_GGX(b.NdotL, b.NdotV, alpha);
    b.F = glm::mix(dielectricF, metalF, s.metallic);
    b.diffuse = (1.0f - s.metallic) * (1.0f - dielectricF) * s.diffuseColor / PI;
    b.specular = b.F * b.D * b.Vis;
    return b;
}

glm::vec3 gltfDirectLight(const glm::vec3& N, const glm::vec3& V, const glm::vec3& L,
                          const glm::vec3& radiance, const GltfSurface& s) {
    if (glm::dot(N, L) <= 0.0f) return glm::vec3(0.0f);
    const GltfBrdf b = gltfBrdf(N, V, L, s);
    return (b.diffuse + b.specular) * radiance * b.NdotL;
}

glm::vec3 specularIblF90(const glm::vec3& F0, float F90, const SplitSumReads& reads,
                         bool multipleScattering, glm::vec3& albedo) {
    const glm::vec2 scaleBias = reads.envBRDF;
    const glm::vec3 single = F0 * scaleBias.x + F90 * scaleBias.y;
    glm::vec3 multiple(0.0f);
    if (multipleScattering) {
        const float lost = 1.0f - (scaleBias.x + scaleBias.y);
        const glm::vec3 averageF = F0 + (F90 - F0) / 21.0f;
        multiple = lost * averageF * single / (1.0f - averageF * lost);
    }
    albedo = single + multiple;
    return single * reads.prefilteredColor + multiple * reads.irradiance;
}

GltfAmbient gltfAmbient(const GltfSurface& s, const glm::vec3& irradiance,
                        const glm::vec3& prefiltered, const glm::vec2& scaleBias,
                        bool multipleScattering) {
    const SplitSumReads reads{0.0f, irradiance, prefiltered, scaleBias};
    GltfAmbient ambient;
    glm::vec3 dielectricShare, metalShare;
    ambient.dielectricSpecular =
        specularIblF90(s.F0, s.F90, reads, multipleScattering, dielectricShare);
    ambient.metal = specularIblF90(s.metalColor, 1.0f, reads, multipleScattering, metalShare);
    ambient.diffuse = s.diffuseColor * irradiance * (1.0f - dielectricShare);
    return ambient;
}

float rangeAttenuation(float range, float distance) {
    const float inverseSquare = 1.0f / (distance * distance);
    if (range <= 0.0f) return inverseSquare;
    const float ratio = distance / range;
    return std::clamp(1.0f - ratio * ratio * ratio * ratio, 0.0f, 1.0f) * inverseSquare;
}

float spotAttenuation(const glm::vec3& lightToPoint, const glm::vec3& spotDirection,
                      float outerConeCos, float innerConeCos) {
    const float cd = glm::dot(spotDirection, lightToPoint);
    const float t =
        std::clamp((cd - outerConeCos) / std::max(0.001f, innerConeCos - outerConeCos), 0.0f, 1.0f);
    return t * t;
}

glm::vec3 punctualRadiance(const PunctualLight& light, const glm::vec3& position, glm::vec3& L) {
    if (light.type == PunctualLight::Type::Directional) {
        L = -light.direction;
        return light.color;
    }
    const glm::vec3 toLight = light.position - position;
    const float distance = glm::length(toLight);
    L = toLight / distance;
    glm::vec3 radiance = light.color * rangeAttenuation(light.range, distance);
    if (light.type == PunctualLight::Type::Spot) {
        radiance *= spotAttenuation(-L, light.direction, std::cos(light.outerConeAngle),
                                    std::cos(light.innerConeAngle));
    }
    return radiance;
}

glm::vec3 shadePunctualLights(const GltfSurface& s, const glm::vec3& cameraPosition,
                              std::span<const PunctualLight> lights) {
    const glm::vec3 V = glm::normalize(cameraPosition - s.position);
    glm::vec3 color(0.0f);
    for (const PunctualLight& light : lights) {
        glm::vec3 L;
        const glm::vec3 radiance = punctualRadiance(light, s.position, L);
        color += gltfDirectLight(s.normal, V, L, radiance, s);
    }
    return color;
}

glm::vec3 reinhardGamma(const glm::vec3& color) {
    const glm::vec3 mapped = color / (color + glm::vec3(1.0f));
    return glm::pow(mapped, glm::vec3(1.0f / 2.2f));
}

namespace {

constexpr double kPi = std::numbers::pi;

// An n-point Gauss-Legendre rule on [-1, 1]: nodes (Legendre roots, by Newton's method) and
// weights.
struct GaussLegendre {
    std::vector<double> nodes, weights;
    explicit GaussLegendre(int n) {
        for (int i = 0; i < n; ++i) {
            double x = std::cos(kPi * (i + 0.75) / (n + 0.5)), derivative = 0.0;
            for (int iteration = 0; iteration < 100; ++iteration) {
                double p0 = 1.0, p1 = x;
                for (int k = 2; k <= n; ++k) {
                    const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                derivative = n * (x * p1 - p0) / (x * x - 1.0);
                const double step = p1 / derivative;
                x -= step;
                if (std::abs(step) < 1e-15) break;
            }
            nodes.push_back(x);
            weights.push_back(2.0 / ((1.0 - x * x) * derivative * derivative));
        }
    }
};

double ggxDistribution(double cosH, double alpha) {
    const double a2 = alpha * alpha, d = (a2 - 1.0) * cosH * cosH + 1.0;
    return a2 / (kPi * d * d);
}

double charlieDistribution(double cosH, double alpha) {
    const double sin2 = std::max(1.0 - cosH * cosH, 0.0);
    return (2.0 + 1.0 / alpha) * std::pow(sin2, 0.5 / alpha) / (2.0 * kPi);
}

double smithSchlickIbl(double NdotV, double NdotL, double roughness) {
    const double k = roughness * roughness / 2.0;
    return (NdotV / (NdotV * (1.0 - k) + k)) * (NdotL / (NdotL * (1.0 - k) + k));
}

double ashikhmin(double NdotL, double NdotV) {
    return std::clamp(1.0 / (4.0 * (NdotL + NdotV - NdotL * NdotV)), 0.0, 1.0);
}

// What the LUT integrates for one light direction, per unit solid angle of l: (scale, bias,
// sheen), the lobe's masking-shadowing the texts' Schlick-GGX or (`heightCorrelated`) glTF's
// V_GGX. Zero below the horizon. Without `withSheen` the sheen is left 0 (a split sum's
// quadrature does not use it: its pow was a third of the time).
glm::dvec3 lutIntegrand(const glm::dvec3& V, const glm::dvec3& L, double roughness,
                        bool heightCorrelated = false, bool withSheen = true) {
    const double NdotL = L.z, NdotV = V.z;
    if (NdotL <= 0.0) return glm::dvec3(0.0);
    const glm::dvec3 H = glm::normalize(V + L);
    const double VdotH = std::max(glm::dot(V, H), 0.0), alpha = roughness * roughness;
    // D G / (4 NdotL NdotV) times NdotL, or D Vis NdotL
    const double specular =
        heightCorrelated
            ? ggxDistribution(H.z, alpha) * V_GGX(float(NdotL), float(NdotV), float(alpha)) * NdotL
            : ggxDistribution(H.z, alpha) * smithSchlickIbl(NdotV, NdotL, roughness) /
                  (4.0 * NdotV);
    const double Fc = std::pow(1.0 - VdotH, 5.0);
    const double sheen =
        withSheen ? charlieDistribution(H.z, alpha) * ashikhmin(NdotL, NdotV) * NdotL : 0.0;
    return {specular * (1.0 - Fc), specular * Fc, sheen};
}

// The integral over half vectors of integrand(V, L) times the Jacobian 4 (v.h) (l = reflect(-v, h)).
// theta_h runs over panels graded geometrically towards 0 (a GGX lobe, width alpha) and towards
// pi/2 (a Charlie one, width sqrt(alpha)), 16 Gauss-Legendre nodes each; phi_h over [0, pi] by the
// midpoint rule, doubled (v lies in the xz plane: the integrand is mirror-symmetric in phi).
template <typename T, typename Integrand>
T halfVectorQuadrature(double NdotV, double alpha, const Integrand& integrand) {
    static const GaussLegendre rule(16);
    constexpr int kPhi = 256;
    const double halfPi = kPi / 2.0;
    alpha = std::max(alpha, 1e-8);
    std::vector<double> edges = {0.0, halfPi};
    for (double d = alpha / 64.0; d < halfPi; d *= 2.0) edges.push_back(d);
    for (double d = std::sqrt(alpha) / 64.0; d < halfPi; d *= 2.0) edges.push_back(halfPi - d);
    for (int i = 1; i < 32; ++i) edges.push_back(halfPi * i / 32.0);
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

    // the midpoints' cos and sin, the same for every ring (computed once: the same values)
    static const std::array<glm::dvec2, kPhi> ringDirections = [] {
        std::array<glm::dvec2, kPhi> directions;
        for (int k = 0; k < kPhi; ++k) {
            const double phi = kPi * (k + 0.5) / kPhi;
            directions[size_t(k)] = {std::cos(phi), std::sin(phi)};
        }
        return directions;
    }();

    const glm::dvec3 V(std::sqrt(std::max(0.0, 1.0 - NdotV * NdotV)), 0.0, NdotV);
    T sum(0.0);
    for (size_t p = 0; p + 1 < edges.size(); ++p) {
        const double lo = edges[p], hi = edges[p + 1], half = (hi - lo) / 2.0;
        for (size_t n = 0; n < rule.nodes.size(); ++n) {
            const double theta = lo + half * (rule.nodes[n] + 1.0);
            const double sinTheta = std::sin(theta), cosTheta = std::cos(theta);
            const double weightTheta = half * rule.weights[n] * sinTheta;
            T ring(0.0);
            for (const glm::dvec2& phi : ringDirections) {
                const glm::dvec3 H(sinTheta * phi.x, sinTheta * phi.y, cosTheta);
                const double VdotH = glm::dot(V, H);
                if (VdotH <= 0.0) continue;
                const glm::dvec3 L = 2.0 * VdotH * H - V;
                if (L.z <= 0.0) continue;
                ring += integrand(V, L) * (4.0 * VdotH);
            }
            sum += ring * (weightTheta * 2.0 * kPi / kPhi);
        }
    }
    return sum;
}

glm::dvec3 halfVectorQuadrature(double NdotV, double roughness, bool heightCorrelated = false,
                                bool withSheen = true) {
    return halfVectorQuadrature<glm::dvec3>(
        NdotV, roughness * roughness,
        [roughness, heightCorrelated, withSheen](const glm::dvec3& V, const glm::dvec3& L) {
            return lutIntegrand(V, L, roughness, heightCorrelated, withSheen);
        });
}

}  // namespace

double integrateOverLights(double NdotV, double alpha,
                           const std::function<double(const glm::dvec3&, const glm::dvec3&)>& integrand) {
    return halfVectorQuadrature<double>(NdotV, alpha, integrand);
}

glm::dvec2 splitSumQuadrature(double NdotV, double roughness) {
    return glm::dvec2(halfVectorQuadrature(NdotV, roughness, false, false));
}

glm::dvec2 gltfSplitSumQuadrature(double NdotV, double roughness) {
    return glm::dvec2(halfVectorQuadrature(NdotV, roughness, true, false));
}

double sheenQuadrature(double NdotV, double roughness) {
    return halfVectorQuadrature(NdotV, roughness).z;
}

glm::dvec3 bruteForceLut(double NdotV, double roughness, int steps) {
    const glm::dvec3 V(std::sqrt(std::max(0.0, 1.0 - NdotV * NdotV)), 0.0, NdotV);
    const double dTheta = (kPi / 2.0) / steps, dPhi = 2.0 * kPi / (4 * steps);
    glm::dvec3 sum(0.0);
    for (int i = 0; i < steps; ++i) {
        const double theta = (i + 0.5) * dTheta;
        for (int k = 0; k < 4 * steps; ++k) {
            const double phi = (k + 0.5) * dPhi;
            const glm::dvec3 L(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                               std::cos(theta));
            sum += lutIntegrand(V, L, roughness) * (std::sin(theta) * dTheta * dPhi);
        }
    }
    return sum;
}

}  // namespace pbr::cpu
