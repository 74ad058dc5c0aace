// Properties of the CPU BRDF that hold by mathematics, independent of any render.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ibl/ibl.h"
#include "math/brdf.h"
#include "math/cube_geometry.h"

namespace pbr::cpu {
namespace {

constexpr double kPi = std::numbers::pi;

// The GGX distribution is normalised: the projected area of the microfacets is the macro
// surface, integral of D(h) (n.h) over the hemisphere = 1.
TEST(Brdf, GgxDistributionIsNormalised) {
    const glm::vec3 N(0, 0, 1);
    for (float roughness : {0.3f, 0.5f, 0.8f, 1.0f}) {
        double integral = 0.0;
        const int steps = 2000;
        for (int i = 0; i < steps; ++i) {
            const double theta = (i + 0.5) / steps * (kPi / 2.0);
            const glm::vec3 H(float(std::sin(theta)), 0.0f, float(std::cos(theta)));
            // azimuthally symmetric: d(omega) = 2 pi sin(theta) d(theta)
            integral += DistributionGGX(N, H, roughness) * std::cos(theta) * 2.0 * kPi *
                        std::sin(theta) * (kPi / 2.0 / steps);
        }
        EXPECT_NEAR(integral, 1.0, 2e-3) << "roughness " << roughness;
    }
}

TEST(Brdf, FresnelSchlickEndPoints) {
    const glm::vec3 F0(0.04f, 0.5f, 0.9f);
    const glm::vec3 headOn = fresnelSchlick(1.0f, F0);
    const glm::vec3 grazing = fresnelSchlick(0.0f, F0);
    for (int c = 0; c < 3; ++c) {
        EXPECT_FLOAT_EQ(headOn[c], F0[c]);
        EXPECT_FLOAT_EQ(grazing[c], 1.0f);
    }
    // halfway, by the formula F0 + (1 - F0) (1 - cos)^5
    EXPECT_NEAR(fresnelSchlick(0.5f, F0).x, 0.04f + 0.96f / 32.0f, 1e-6f);
}

// The ambient term's Fresnel (Sebastien Lagarde's roughness-aware Schlick, as LearnOpenGL's IBL
// chapter uses it): F0 head-on; at grazing the rim reaches max(1 - roughness, F0), not 1.
TEST(Brdf, FresnelSchlickRoughnessEndPoints) {
    const glm::vec3 F0(0.04f, 0.5f, 0.9f);
    const glm::vec3 rim(0.7f, 0.7f, 0.9f);  // max(1 - 0.3, F0) by hand
    for (int c = 0; c < 3; ++c) {
        EXPECT_FLOAT_EQ(fresnelSchlickRoughness(1.0f, F0, 0.3f)[c], F0[c]);
        EXPECT_FLOAT_EQ(fresnelSchlickRoughness(0.0f, F0, 0.3f)[c], rim[c]);
        EXPECT_NEAR(fresnelSchlickRoughness(0.5f, F0, 0.3f)[c], F0[c] + (rim[c] - F0[c]) / 32.0f,
                    1e-6f);
    }
}

// Both forms of 05's ambient term in a uniform white environment (irradiance = prefiltered = 1)
// with a LUT value (scale 0.8, bias 0.1). The exact form conserves energy: a white dielectric
// gives back all of it, its diffuse taking what its lobe, 0.04 x 0.8 + 0.1 = 0.132, does not; a
// white metal returns the LUT's own albedo, 0.9. LearnOpenGL's form agrees head-on (F = F0) and
// at grazing weighs by F = max(1 - roughness, F0) = 0.7 at roughness 0.3: specular
// 0.7 x 0.8 + 0.1 = 0.66, diffuse 1 - 0.7 = 0.3.
TEST(SplitSumAmbient, WhiteFurnaceClosedForms) {
    const glm::vec3 white(1.0f), sky(1.0f);
    const glm::vec2 lut(0.8f, 0.1f);
    const SplitSumAmbient dielectric =
        splitSumAmbient(0.3f, white, 0.0f, 0.3f, sky, sky, lut, true);
    EXPECT_NEAR(dielectric.specular.x, 0.132f, 1e-6f);
    EXPECT_NEAR(dielectric.diffuse.x + dielectric.specular.x, 1.0f, 1e-6f);
    const SplitSumAmbient metal = splitSumAmbient(0.3f, white, 1.0f, 0.3f, sky, sky, lut, true);
    EXPECT_FLOAT_EQ(metal.diffuse.x, 0.0f);
    EXPECT_NEAR(metal.specular.x, 0.9f, 1e-6f);
    const SplitSumAmbient headOn = splitSumAmbient(1.0f, white, 0.0f, 0.3f, sky, sky, lut, false);
    EXPECT_NEAR(headOn.specular.x, dielectric.specular.x, 1e-6f);
    const SplitSumAmbient grazing = splitSumAmbient(0.0f, white, 0.0f, 0.3f, sky, sky, lut, false);
    EXPECT_NEAR(grazing.specular.x, 0.66f, 1e-6f);
    EXPECT_NEAR(grazing.diffuse.x, 0.3f, 1e-6f);
}

// The glTF samples' ambient term in the same white furnace (LUT scale 0.6, bias 0.05): a white
// dielectric gives back all of the light with or without multiple scattering (its diffuse takes
// what its lobe does not: 1 - (0.04 x 0.6 + 0.05) = 0.926 without); a white metal returns the
// LUT's albedo, 0.65, in single scattering, and the whole environment, 1, with Fdez-Aguera's
// multiple scattering (E + (1 - E) E / (1 - (1 - E)) = 1 for F = 1).
TEST(GltfAmbient, WhiteFurnaceClosedForms) {
    const glm::vec3 origin(0.0f), up(0, 0, 1), white(1.0f), sky(1.0f);
    const glm::vec2 lut(0.6f, 0.05f);
    const GltfSurface dielectric = metallicRoughnessSurface(origin, up, white, 0.0f, 0.5f);
    const GltfSurface metal = metallicRoughnessSurface(origin, up, white, 1.0f, 0.5f);
    for (bool multiple : {false, true}) {
        const GltfAmbient a = gltfAmbient(dielectric, sky, sky, lut, multiple);
        EXPECT_NEAR(a.diffuse.x + a.dielectricSpecular.x, 1.0f, 1e-5f) << multiple;
    }
    EXPECT_NEAR(gltfAmbient(dielectric, sky, sky, lut, false).diffuse.x, 0.926f, 1e-6f);
    EXPECT_NEAR(gltfAmbient(metal, sky, sky, lut, false).metal.x, 0.65f, 1e-6f);
    EXPECT_NEAR(gltfAmbient(metal, sky, sky, lut, true).metal.x, 1.0f, 1e-5f);
}

TEST(Brdf, SchlickGgxGeometryIsOneHeadOnAndFallsAtGrazing) {
    for (float roughness : {0.05f, 0.5f, 1.0f}) {
        EXPECT_FLOAT_EQ(GeometrySchlickGGX(1.0f, roughness), 1.0f);
        EXPECT_FLOAT_EQ(GeometrySchlickGGX(0.0f, roughness), 0.0f);
        // k = (r + 1)^2 / 8, so at NdotV = 0.5: 0.5 / (0.5 (1 - k) + k)
        const float k = (roughness + 1.0f) * (roughness + 1.0f) / 8.0f;
        EXPECT_NEAR(GeometrySchlickGGX(0.5f, roughness), 0.5f / (0.5f * (1.0f - k) + k), 1e-6f);
    }
}

// A Lambertian surface (roughness 1, dielectric, no specular worth speaking of aside) lit head-on
// by one light: the diffuse part is kD * albedo / pi * radiance.
TEST(Brdf, HeadOnLightOnAMatteSurface) {
    SurfacePoint s;
    s.position = {0, 0, 0};
    s.normal = {0, 0, 1};
    s.albedo = {1, 1, 1};
    s.metallic = 0.0f;
    s.roughness = 1.0f;
    s.ao = 0.0f;                                   // no ambient
    const PointLight light{{0, 0, 2}, {4, 4, 4}};  // radiance 4 / 2^2 = 1
    const glm::vec3 Lo = shadePointLights(s, {0, 0, 5}, std::span(&light, 1));
    const float F = 0.04f;  // head-on Fresnel of a dielectric
    const float diffuse = (1.0f - F) / float(kPi);
    // specular: D(r=1) = 1/pi, G = 1 head-on, F = 0.04, / (4 + 0.001)
    const float specular = (1.0f / float(kPi)) * F / (4.0f + 0.001f);
    EXPECT_NEAR(Lo.x, diffuse + specular, 1e-5f);
}

TEST(Brdf, ReinhardGammaMapsZeroOneAndInfinity) {
    EXPECT_FLOAT_EQ(reinhardGamma(glm::vec3(0.0f)).x, 0.0f);
    EXPECT_NEAR(reinhardGamma(glm::vec3(1.0f)).x, std::pow(0.5f, 1.0f / 2.2f), 1e-6f);
    EXPECT_NEAR(reinhardGamma(glm::vec3(1e9f)).x, 1.0f, 1e-6f);
}

}  // namespace
}  // namespace pbr::cpu

namespace pbr {
namespace {

// The LUT's reference quadrature, checked against what is known without it. Near a mirror
// (roughness 0.01) every half vector is the normal: VdotH = NdotV and G = 1, so the scale and bias
// are 1 - (1 - NdotV)^5 and (1 - NdotV)^5 exactly in the limit.
TEST(BrdfQuadrature, MirrorLimitIsFresnelSchlick) {
    for (const double NdotV : {0.2, 0.5, 0.9}) {
        const glm::dvec2 ab = cpu::splitSumQuadrature(NdotV, 0.01);
        const double Fc = std::pow(1.0 - NdotV, 5.0);
        EXPECT_NEAR(ab.x, 1.0 - Fc, 2e-3) << NdotV;
        EXPECT_NEAR(ab.y, Fc, 2e-3) << NdotV;
    }
}

// For wide lobes a plain midpoint sum over light directions converges, and must agree with the
// half-vector quadrature on all three channels.
TEST(BrdfQuadrature, AgreesWithABruteForceSumOverLightDirections) {
    for (const double NdotV : {0.2, 0.6, 0.95}) {
        for (const double roughness : {0.5, 0.8, 1.0}) {
            const glm::dvec3 brute = cpu::bruteForceLut(NdotV, roughness, 500);
            const glm::dvec2 ab = cpu::splitSumQuadrature(NdotV, roughness);
            const double sheen = cpu::sheenQuadrature(NdotV, roughness);
            EXPECT_NEAR(ab.x, brute.x, 1e-3) << NdotV << ", " << roughness;
            EXPECT_NEAR(ab.y, brute.y, 1e-3) << NdotV << ", " << roughness;
            EXPECT_NEAR(sheen, brute.z, 1e-3) << NdotV << ", " << roughness;
        }
    }
}

// The prefiltered map's weight (pbr::prefilterNormalization integrates over the half vector)
// against a sum over light directions that needs no change of variables: midpoints in
// (theta_L, phi) of D_GGX(H) N.L sin(theta_L) with N = V. At roughness 1 D is 1 / pi and the
// integral is exactly 1. A Jacobian of 1 instead of 4 cos(theta_H), or an N.L left out, misses.
TEST(IblWeights, PrefilterNormalizationAgreesWithASumOverLightDirections) {
    EXPECT_NEAR(prefilterNormalization(1.0), 1.0, 1e-6);
    for (double roughness : {0.25, 0.5, 0.75}) {
        const double a2 = std::pow(roughness, 4.0), pi = std::numbers::pi;
        constexpr int kSteps = 20000;
        const double step = (pi / 2.0) / kSteps;
        double sum = 0.0;
        for (int k = 0; k < kSteps; ++k) {
            const double thetaL = (k + 0.5) * step;
            const double cosH = std::cos(thetaL / 2.0);  // N = V: H halfway, theta_H = theta_L / 2
            const double denom = cosH * cosH * (a2 - 1.0) + 1.0;
            sum += a2 / (pi * denom * denom) * std::cos(thetaL) * std::sin(thetaL) * step;
        }
        sum *= 2.0 * pi;  // phi
        EXPECT_NEAR(prefilterNormalization(roughness), sum, 1e-4 * sum)
            << "roughness " << roughness;
    }
}

// The cube map's texel solid angles tile the sphere: 4 pi in all, and a face's centre texel
// close to (2 / n)^2 (the face is at distance 1).
TEST(CubeGeometry, TexelSolidAnglesTileTheSphere) {
    for (int n : {1, 2, 7, 64}) {
        double total = 0.0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) total += cubeTexelSolidAngle(i, j, n);
        EXPECT_NEAR(6.0 * total, 4.0 * std::numbers::pi, 1e-9) << n;
    }
    EXPECT_NEAR(cubeTexelSolidAngle(32, 32, 64), std::pow(2.0 / 64.0, 2.0), 1e-6);
    // the centre of +Y's face looks up, of -Z's forward
    EXPECT_NEAR(cubeFaceDirection(2, 0.0, 0.0).y, 1.0, 1e-12);
    EXPECT_NEAR(cubeFaceDirection(5, 0.0, 0.0).z, -1.0, 1e-12);
}

}  // namespace
}  // namespace pbr
