// The layers of the advanced glTF materials (common/math/gltf_extensions.h, the CPU mirror of
// shaders/include/gltf_extensions.glsl) against what holds without them: the Fresnel equations'
// reflectance at normal incidence, and white furnaces integrated over every light direction (a
// white surface under its layers never reflects more light than arrives).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "math/brdf.h"
#include "math/gltf_extensions.h"

namespace pbr::cpu {
namespace {

constexpr double kPiD = std::numbers::pi;
const glm::vec3 kUp(0.0f, 0.0f, 1.0f);

// Reflectance at normal incidence from air, textbook values of the Fresnel equations: water
// (1.333) 2.0 %, glass (1.5) 4 %, diamond (2.42) 17.2 %; an index of 1 reflects nothing.
TEST(GltfExtensions, IorGivesTheFresnelReflectanceAtNormalIncidence) {
    EXPECT_NEAR(iorToF0(1.5f), 0.04f, 1e-6f);
    EXPECT_NEAR(iorToF0(1.333f), 0.0204f, 1e-4f);
    EXPECT_NEAR(iorToF0(2.42f), 0.172f, 1e-3f);
    EXPECT_EQ(iorToF0(1.0f), 0.0f);
}

// KHR_materials_specular's defaults are the core material (F0 0.04, F90 1); its strength scales
// both ends, and its colour tints F0, clamped to 1 before the strength.
TEST(GltfExtensions, SpecularScalesAndTintsTheDielectricsReflection) {
    const DielectricFresnel core = dielectricFresnel(1.5f, glm::vec3(1.0f), 1.0f);
    EXPECT_NEAR(core.F0.x, 0.04f, 1e-6f);
    EXPECT_EQ(core.F90, 1.0f);
    const DielectricFresnel none = dielectricFresnel(1.5f, glm::vec3(1.0f), 0.0f);
    EXPECT_EQ(none.F0, glm::vec3(0.0f));
    EXPECT_EQ(none.F90, 0.0f);
    const DielectricFresnel tinted = dielectricFresnel(1.5f, glm::vec3(30.0f, 0.5f, 1.0f), 0.5f);
    EXPECT_NEAR(tinted.F0.x, 0.5f, 1e-6f);  // 0.04 x 30 = 1.2, clamped to 1, then halved
    EXPECT_NEAR(tinted.F0.y, 0.01f, 1e-6f);
    EXPECT_NEAR(tinted.F0.z, 0.02f, 1e-6f);
    EXPECT_EQ(tinted.F90, 0.5f);
}

// The coat's lobe alone, integrated over the light directions (radiance 1): a smooth coat
// reflects what its lobe receives (the mirror limit, 1), a rougher one less (single scattering
// loses what bounces between microfacets more than once, more the rougher), never more.
// (Roughness 0.1, not smoother: float's NdotH resolves a narrower peak too coarsely.)
double coatAlbedo(double NdotV, float roughness) {
    const double alpha = std::max(double(roughness) * roughness, double(kMinGgxAlpha));
    return integrateOverLights(NdotV, alpha, [&](const glm::dvec3& V, const glm::dvec3& L) {
        return double(clearcoatDirect(kUp, glm::vec3(V), glm::vec3(L), roughness));
    });
}

TEST(GltfExtensions, ASmoothCoatsLobeReflectsAllItReceives) {
    for (const double NdotV : {0.3, 0.7, 1.0}) {
        double previous = coatAlbedo(NdotV, 0.1f);
        EXPECT_NEAR(previous, 1.0, 0.01) << "NdotV " << NdotV;
        for (const float roughness : {0.3f, 0.6f, 1.0f}) {
            const double albedo = coatAlbedo(NdotV, roughness);
            EXPECT_LT(albedo, previous) << "NdotV " << NdotV << ", roughness " << roughness;
            previous = albedo;
        }
    }
}

// A white Lambertian base under a full clear coat, in a white furnace: the coat takes its
// Fresnel's share at the view, the base keeps the rest, so the whole never exceeds what arrives
// (1), and the base's share never vanishes. Across the view angle and the coat's roughness.
TEST(GltfExtensions, AWhiteBaseUnderAClearCoatNeverReflectsMoreThanArrives) {
    const float coatF0 = iorToF0(1.5f);
    for (const double NdotV : {0.05, 0.3, 0.7, 1.0}) {
        const float weight = 1.0f * clearcoatFresnel(coatF0, float(NdotV));
        for (const float roughness : {0.05f, 0.3f, 0.6f, 1.0f}) {
            const double alpha = std::max(double(roughness) * roughness, double(kMinGgxAlpha));
            const double reflected =
                integrateOverLights(NdotV, alpha, [&](const glm::dvec3& V, const glm::dvec3& L) {
                    const glm::vec3 base(float(L.z / kPiD));  // white Lambert, times NdotL
                    const glm::vec3 coat(
                        clearcoatDirect(kUp, glm::vec3(V), glm::vec3(L), roughness));
                    return double(coatOver(base, coat, weight).x);
                });
            EXPECT_LE(reflected, 1.0 + 2e-3) << "NdotV " << NdotV << ", roughness " << roughness;
            EXPECT_GE(reflected, 1.0 - weight - 2e-3)
                << "NdotV " << NdotV << ", roughness " << roughness;
        }
    }
}

// The sheen's directional albedo, a table over NdotL for one roughness, read linearly between
// its entries (as a texture is).
struct SheenAlbedoTable {
    std::vector<double> values;
    explicit SheenAlbedoTable(double roughness) {
        for (int i = 0; i <= 16; ++i) {
            values.push_back(sheenAlbedoQuadrature(std::max(i / 16.0, 0.02), roughness));
        }
    }
    double at(double cosine) const {
        const double x = std::clamp(cosine, 0.0, 1.0) * 16.0;
        const int i = std::min(int(x), 15);
        return values[size_t(i)] + (values[size_t(i) + 1] - values[size_t(i)]) * (x - i);
    }
};

// A white Lambertian base under a white sheen, in a white furnace: the sheen's lobe plus the
// base scaled by what the sheen leaves of it, 1 - E at the view and the light (the smaller),
// never exceeds 1. The sheen's albedo E itself stays within (0, 1].
TEST(GltfExtensions, AWhiteBaseUnderAWhiteSheenNeverReflectsMoreThanArrives) {
    const glm::vec3 white(1.0f);
    for (const double roughness : {0.2, 0.5, 1.0}) {
        const SheenAlbedoTable table(roughness);
        for (const double value : table.values) {
            EXPECT_GT(value, 0.0) << "roughness " << roughness;
            EXPECT_LE(value, 1.0) << "roughness " << roughness;
        }
        const double alpha = std::max(roughness * roughness, double(kMinSheenAlpha));
        for (const double NdotV : {0.2, 0.6, 1.0}) {
            const double atV = table.at(NdotV);
            const double reflected =
                integrateOverLights(NdotV, alpha, [&](const glm::dvec3& V, const glm::dvec3& L) {
                    const glm::vec3 sheen =
                        sheenDirect(kUp, glm::vec3(V), glm::vec3(L), white, float(roughness));
                    const float keep = sheenAlbedoScaling(white, float(atV), float(table.at(L.z)));
                    return double(sheen.x) + L.z / kPiD * keep;
                });
            std::printf("sheen roughness %.1f, NdotV %.1f: E %.4f, furnace %.4f\n", roughness,
                        NdotV, atV, reflected);
            EXPECT_LE(reflected, 1.0 + 2e-3) << "roughness " << roughness << ", NdotV " << NdotV;
            EXPECT_GE(reflected, 0.5) << "roughness " << roughness << ", NdotV " << NdotV;
        }
    }
}

// A white surface under every layer at once (a white sheen, a full clear coat over a white
// Lambertian base: KHR_materials_specular 0, for Appendix B's own base reflects up to 27 % more
// than arrives at grazing views, smooth at NdotV 0.2, its diffuse weighted by 1 - F of each half
// vector), lit by a white environment of radiance 1: the layers' image-based light, from the
// split sum's reads made by quadrature (the LUT's scale and bias, the sheen's albedo), never
// exceeds 1, with multiple scattering and without; and one light integrated over every direction
// of arrival neither.
TEST(GltfExtensions, AWhiteLayeredSurfaceInAWhiteFurnaceNeverReflectsMoreThanArrives) {
    for (const float roughness : {0.2f, 0.6f, 1.0f}) {
        LayeredSurface s;
        s.diffuseColor = glm::vec3(1.0f);
        s.F0 = glm::vec3(0.0f);
        s.F90 = 0.0f;
        s.roughness = roughness;
        s.sheenColor = glm::vec3(1.0f);
        s.sheenRoughness = 1.0f - 0.5f * roughness;
        s.clearcoat = 1.0f;
        s.clearcoatRoughness = 0.5f * roughness;
        const SheenAlbedoTable sheenTable(s.sheenRoughness);
        for (const double NdotV : {0.2, 0.6, 1.0}) {
            const float atV = float(sheenTable.at(NdotV));
            SplitSumReads base{float(NdotV), glm::vec3(1.0f), glm::vec3(1.0f),
                               glm::vec2(splitSumQuadrature(NdotV, roughness))};
            SplitSumReads coat{float(NdotV), glm::vec3(1.0f), glm::vec3(1.0f),
                               glm::vec2(splitSumQuadrature(NdotV, s.clearcoatRoughness))};
            for (const bool multiple : {false, true}) {
                const glm::vec3 ambient =
                    layeredAmbientLight(s, base, coat, glm::vec3(1.0f), atV, glm::vec3(0.0f),
                                        multiple);
                EXPECT_LE(ambient.x, 1.0f + 1e-3f) << "roughness " << roughness << ", NdotV "
                                                    << NdotV << ", multiple " << multiple;
                EXPECT_GE(ambient.x, 0.5f) << "roughness " << roughness << ", NdotV " << NdotV;
            }
            const double alpha = std::max(double(roughness) * roughness, double(kMinGgxAlpha));
            const double direct =
                integrateOverLights(NdotV, alpha, [&](const glm::dvec3& V, const glm::dvec3& L) {
                    return double(layeredDirectLight(s, glm::vec3(V), glm::vec3(L),
                                                     glm::vec3(1.0f), glm::vec3(L),
                                                     glm::vec3(1.0f), atV,
                                                     float(sheenTable.at(L.z)))
                                      .x);
                });
            std::printf("roughness %.1f, NdotV %.1f: one light over every direction %.4f\n",
                        double(roughness), NdotV, direct);
            EXPECT_LE(direct, 1.0 + 2e-3) << "roughness " << roughness << ", NdotV " << NdotV;
        }
    }
}

// Without the extensions' layers (no sheen, no coat, ior 1.5 and specular 1) the layered light
// is the core material's, to the bit: sample 10 draws a plain material as 07 does.
TEST(GltfExtensions, WithoutLayersTheLightIsTheCoreMaterials) {
    const glm::vec3 N = glm::normalize(glm::vec3(0.2f, 0.1f, 1.0f));
    const glm::vec3 V = glm::normalize(glm::vec3(-0.3f, 0.2f, 1.0f));
    const glm::vec3 L = glm::normalize(glm::vec3(0.5f, -0.4f, 0.8f));
    const DielectricFresnel fresnel = dielectricFresnel(1.5f, glm::vec3(1.0f), 1.0f);
    for (const float metallic : {0.0f, 0.5f, 1.0f}) {
        LayeredSurface s;
        s.N = N;
        s.clearcoatN = N;
        s.diffuseColor = s.metalColor = glm::vec3(0.8f, 0.4f, 0.1f);
        s.F0 = fresnel.F0;
        s.F90 = fresnel.F90;
        s.metallic = metallic;
        s.roughness = 0.4f;
        const GltfSurface core =
            metallicRoughnessSurface(glm::vec3(0.0f), N, s.diffuseColor, metallic, 0.4f);
        const glm::vec3 radiance(2.0f, 1.5f, 1.0f);
        EXPECT_EQ(layeredDirectLight(s, V, L, radiance, L, radiance, 0.3f, 0.2f),
                  gltfDirectLight(N, V, L, radiance, core));
        const SplitSumReads reads{glm::dot(N, V), glm::vec3(0.5f, 0.6f, 0.7f),
                                  glm::vec3(1.2f, 0.9f, 0.4f), glm::vec2(0.6f, 0.1f)};
        const GltfAmbient ambient =
            gltfAmbient(core, reads.irradiance, reads.prefilteredColor, reads.envBRDF, true);
        EXPECT_EQ(layeredAmbientLight(s, reads, reads, glm::vec3(3.0f), 0.3f, glm::vec3(5.0f), true),
                  glm::mix(ambient.diffuse + ambient.dielectricSpecular, ambient.metal, metallic));
    }
}

// A white dielectric that transmits all it does not reflect (KHR_materials_transmission 1, thin-
// walled, ior 1.5: the transmission lobe as rough as the reflection's), lit by one light from
// every direction on both sides: reflection and transmission share the GGX lobe, each light's
// 1 - F going through, so together they return exactly the lobe's own directional albedo (the
// integral of D V NdotL, no Fresnel), the same for any F0. Under a white environment that the
// backdrop shows too, the layers' image-based light returns what arrives.
TEST(GltfExtensions, ReflectionAndTransmissionShareTheLobeAndLoseNothing) {
    for (const float roughness : {0.2f, 0.5f, 0.8f}) {
        for (const float F0 : {0.04f, 0.5f}) {
            LayeredSurface s;
            s.diffuseColor = s.metalColor = glm::vec3(1.0f);
            s.F0 = glm::vec3(F0);
            s.roughness = roughness;
            s.transmission = 1.0f;
            for (const double NdotV : {0.3, 0.7, 1.0}) {
                const double alpha =
                    std::max(double(roughness) * roughness, double(kMinGgxAlpha));
                // each direction above once as a light in front, once mirrored to behind
                const double both =
                    integrateOverLights(NdotV, alpha, [&](const glm::dvec3& V, const glm::dvec3& L) {
                        const glm::vec3 in(L), behind(L.x, L.y, -L.z), v(V);
                        const glm::vec3 front =
                            layeredDirectLight(s, v, in, glm::vec3(1.0f), in, glm::vec3(0.0f), 0, 0);
                        const glm::vec3 through = layeredDirectLight(
                            s, v, behind, glm::vec3(0.0f), behind, glm::vec3(1.0f), 0, 0);
                        return double(front.x + through.x);
                    });
                const double lobe =
                    integrateOverLights(NdotV, alpha, [&](const glm::dvec3& V, const glm::dvec3& L) {
                        const double NdotH = glm::normalize(V + L).z;
                        return double(D_GGX(float(NdotH), float(alpha)) *
                                      V_GGX(float(L.z), float(V.z), float(alpha))) *
                               L.z;
                    });
                EXPECT_NEAR(both, lobe, 2e-3 * lobe)
                    << "roughness " << roughness << ", F0 " << F0 << ", NdotV " << NdotV;
                const SplitSumReads white{float(NdotV), glm::vec3(1.0f), glm::vec3(1.0f),
                                          glm::vec2(splitSumQuadrature(NdotV, roughness))};
                for (const bool multiple : {false, true}) {
                    const glm::vec3 ambient =
                        layeredAmbientLight(s, white, white, glm::vec3(0.0f), 0.0f,
                                            glm::vec3(1.0f), multiple);
                    EXPECT_NEAR(ambient.x, 1.0f, 1e-5f) << "roughness " << roughness;
                }
            }
        }
    }
}

// The emission is as bright as its strength says, and the coat's reflected share of it is lost.
TEST(GltfExtensions, EmissionIsScaledByItsStrengthOnceAndDimmedByTheCoat) {
    const glm::vec3 emitted = emission(glm::vec3(0.5f, 1.0f, 0.0f), 4.0f, 0.25f);
    EXPECT_FLOAT_EQ(emitted.x, 1.5f);
    EXPECT_FLOAT_EQ(emitted.y, 3.0f);
    EXPECT_FLOAT_EQ(emitted.z, 0.0f);
}

}  // namespace
}  // namespace pbr::cpu
