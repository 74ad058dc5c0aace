// The tone mappers of common/math/tonemap.h against values worked out independently: closed forms by
// hand, and for ACES a double-precision evaluation written out here from the published fit
// (BakingLab's ACES.hlsl, its matrices as rows) rather than the library's column-major GLM.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>

#include "math/tonemap.h"

namespace pbr::cpu {
namespace {

void expectNear(const glm::vec3& actual, const glm::dvec3& expected, double eps = 1e-5) {
    EXPECT_NEAR(actual.r, expected.r, eps);
    EXPECT_NEAR(actual.g, expected.g, eps);
    EXPECT_NEAR(actual.b, expected.b, eps);
}

TEST(ToneMap, NamesRoundTripThroughOneTable) {
    std::set<std::string_view> names;
    for (const ToneMapperName& entry : kToneMapperNames) {
        EXPECT_EQ(toneMapperName(entry.mapper), entry.name);
        EXPECT_EQ(toneMapperFromName(entry.name), entry.mapper);
        names.insert(entry.name);
    }
    EXPECT_EQ(names, (std::set<std::string_view>{"none", "reinhard", "aces", "khronos-neutral"}));
    EXPECT_EQ(toneMapperFromName("ACES"), std::nullopt);
    EXPECT_EQ(toneMapperFromName(""), std::nullopt);
    // The values are the shader's TONEMAP_* constants.
    EXPECT_EQ(int(ToneMapper::None), 0);
    EXPECT_EQ(int(ToneMapper::Reinhard), 1);
    EXPECT_EQ(int(ToneMapper::Aces), 2);
    EXPECT_EQ(int(ToneMapper::KhronosNeutral), 3);
    // The flag's choices: the default first, then the rest, each once.
    const std::vector<std::string> choices = toneMapperChoices(ToneMapper::KhronosNeutral);
    EXPECT_EQ(choices, (std::vector<std::string>{"khronos-neutral", "none", "reinhard", "aces"}));
}

TEST(ToneMap, NoneScalesByExposureAndClamps) {
    expectNear(toneMap({0.25f, 0.5f, 2.0f}, ToneMapper::None, 2.0f), {0.5, 1.0, 1.0});
    expectNear(toneMap({0.3f, 0.0f, 0.7f}, ToneMapper::None, 1.0f), {0.3, 0.0, 0.7});
    expectNear(toneMap({-1.0f, 0.1f, 0.2f}, ToneMapper::None, 1.0f), {0.0, 0.1, 0.2});
}

TEST(ToneMap, ReinhardIsCOverOnePlusC) {
    expectNear(toneMap({1.0f, 3.0f, 0.0f}, ToneMapper::Reinhard, 1.0f), {0.5, 0.75, 0.0});
    expectNear(toneMap({0.5f, 1.5f, 4.5f}, ToneMapper::Reinhard, 2.0f), {0.5, 0.75, 0.9});
    // negative input counts as 0 (c / (1 + c) would turn -2 into 2)
    expectNear(toneMap({-2.0f, -0.5f, 0.0f}, ToneMapper::Reinhard, 1.0f), {0.0, 0.0, 0.0});
}

// Khronos PBR Neutral. Below the knee only the toe offset is subtracted: 0.04 when the smallest
// channel is at least 0.08, else x - 6.25 x^2 of that smallest channel x.
TEST(ToneMap, KhronosNeutralBelowTheKneeSubtractsOnlyTheToe) {
    // min 0.1 >= 0.08: offset 0.04; max 0.5 - 0.04 = 0.46 < 0.76
    expectNear(toneMap({0.5f, 0.3f, 0.1f}, ToneMapper::KhronosNeutral, 1.0f), {0.46, 0.26, 0.06});
    // min 0.04: offset 0.04 - 6.25 * 0.0016 = 0.03
    expectNear(toneMap({0.04f, 0.2f, 0.5f}, ToneMapper::KhronosNeutral, 1.0f), {0.01, 0.17, 0.47});
    // black stays black; a peak of 0.79 - 0.04 = 0.75 is still below the knee
    expectNear(toneMap({0.0f, 0.0f, 0.0f}, ToneMapper::KhronosNeutral, 1.0f), {0.0, 0.0, 0.0});
    expectNear(toneMap({0.79f, 0.4f, 0.2f}, ToneMapper::KhronosNeutral, 1.0f), {0.75, 0.36, 0.16});
    // exposure first: 0.25 x 2 = 0.5
    expectNear(toneMap({0.25f, 0.15f, 0.05f}, ToneMapper::KhronosNeutral, 2.0f),
               {0.46, 0.26, 0.06});
}

// Above the knee (peak p > 0.76 after the offset): the new peak is 1 - 0.24^2 / (p + 0.24 - 0.76),
// the colour scaled to it, then mixed towards grey newPeak by g = 1 - 1 / (0.15 (p - newPeak) + 1).
TEST(ToneMap, KhronosNeutralCompressesBrightColoursBelowOneKeepingTheirHue) {
    // white 10: p = 9.96, newPeak = 1 - 0.0576 / 9.44 = 0.9938983
    expectNear(toneMap({10.0f, 10.0f, 10.0f}, ToneMapper::KhronosNeutral, 1.0f),
               {0.9938983, 0.9938983, 0.9938983});
    // (8, 4, 1): p = 7.96, newPeak = 1 - 0.0576 / 7.44 = 0.9922581, g = 1 - 1 / 2.0451613
    // = 0.5110410; r = newPeak; g, b = (1 - g) (c - 0.04) newPeak / p + g newPeak
    expectNear(toneMap({8.0f, 4.0f, 1.0f}, ToneMapper::KhronosNeutral, 1.0f),
               {0.9922581, 0.7484523, 0.5655980});
    // (2, 0.5, 0.1): p = 1.96, newPeak = 1 - 0.0576 / 1.44 = 0.96, g = 1 - 1 / 1.15 = 0.1304348
    expectNear(toneMap({2.0f, 0.5f, 0.1f}, ToneMapper::KhronosNeutral, 1.0f),
               {0.96, 0.3211358, 0.1507720});

    for (const glm::vec3 color : {glm::vec3(8, 4, 1), glm::vec3(0.3f, 50, 6), glm::vec3(1, 2, 3)}) {
        const glm::vec3 out = toneMap(color, ToneMapper::KhronosNeutral, 1.0f);
        EXPECT_LT(std::max({out.r, out.g, out.b}), 1.0f);
        // Hue: the ratios of the channels' differences are kept (offset, scale and a mix with
        // grey all keep them), and so is the order of the channels.
        EXPECT_NEAR((out.r - out.g) / (out.r - out.b), (color.r - color.g) / (color.r - color.b),
                    1e-4f);
        EXPECT_EQ(out.r < out.g, color.r < color.g);
        EXPECT_EQ(out.g < out.b, color.g < color.b);
    }
    // Continuous at the knee: the compression starts from the identity.
    const glm::vec3 below = toneMap(glm::vec3(0.7999f), ToneMapper::KhronosNeutral, 1.0f);
    const glm::vec3 above = toneMap(glm::vec3(0.8001f), ToneMapper::KhronosNeutral, 1.0f);
    EXPECT_NEAR(below.r, above.r, 3e-4f);
    EXPECT_LT(below.r, above.r);
}

// The ACES fit, written out independently in double: the published matrices as rows.
glm::dvec3 acesByHand(const glm::dvec3& color) {
    const double input[3][3] = {
        {0.59719, 0.35458, 0.04823}, {0.07600, 0.90834, 0.01566}, {0.02840, 0.13383, 0.83777}};
    const double output[3][3] = {{1.60475, -0.53108, -0.07367},
                                 {-0.10208, 1.10813, -0.00605},
                                 {-0.00327, -0.07276, 1.07602}};
    const double boosted[3] = {color.r / 0.6, color.g / 0.6, color.b / 0.6};
    double fitted[3];
    for (int row = 0; row < 3; ++row) {
        const double v =
            input[row][0] * boosted[0] + input[row][1] * boosted[1] + input[row][2] * boosted[2];
        fitted[row] =
            (v * (v + 0.0245786) - 0.000090537) / (v * (0.983729 * v + 0.4329510) + 0.238081);
    }
    double result[3];
    for (int row = 0; row < 3; ++row) {
        const double v =
            output[row][0] * fitted[0] + output[row][1] * fitted[1] + output[row][2] * fitted[2];
        result[row] = std::clamp(v, 0.0, 1.0);
    }
    return {result[0], result[1], result[2]};
}

TEST(ToneMap, AcesMatchesThePublishedFit) {
    // Mid grey: the matrices' rows sum to 1, so grey stays grey: 0.18 / 0.6 = 0.3 through the
    // fit, (0.3 x 0.3245786 - 0.000090537) / (0.3 x 0.7280697 + 0.238081) = 0.213105.
    expectNear(toneMap(glm::vec3(0.18f), ToneMapper::Aces, 1.0f), {0.213105, 0.213105, 0.213103});
    expectNear(toneMap(glm::vec3(1.0f), ToneMapper::Aces, 1.0f), {0.763397, 0.763397, 0.763390});
    // Coloured: the matrices mix the channels (a transposed matrix would show here).
    expectNear(toneMap({0.8f, 0.2f, 0.05f}, ToneMapper::Aces, 1.0f),
               {0.781403, 0.274796, 0.064413});
    expectNear(toneMap({0.05f, 0.3f, 1.5f}, ToneMapper::Aces, 1.0f),
               {0.149882, 0.383546, 0.853330});
    for (const glm::vec3 color :
         {glm::vec3(0.01f, 0.5f, 2.0f), glm::vec3(3, 0.2f, 0.7f), glm::vec3(0.4f, 0.4f, 0.1f)}) {
        expectNear(toneMap(color, ToneMapper::Aces, 1.0f), acesByHand(glm::dvec3(color)));
        expectNear(toneMap(color, ToneMapper::Aces, 0.5f), acesByHand(glm::dvec3(color) * 0.5));
    }
}

TEST(ToneMap, AcesIsMonotonicFromZeroToOne) {
    EXPECT_LT(toneMap(glm::vec3(0.0f), ToneMapper::Aces, 1.0f).g, 1e-6f);
    expectNear(toneMap(glm::vec3(1e4f), ToneMapper::Aces, 1.0f), {1.0, 1.0, 1.0});
    float previous = -1.0f;
    for (float x = 0.0f; x < 100.0f; x = x * 1.05f + 0.001f) {
        const float value = toneMap(glm::vec3(x), ToneMapper::Aces, 1.0f).g;
        EXPECT_GE(value, previous) << "at " << x;
        EXPECT_LE(value, 1.0f);
        previous = value;
    }
    EXPECT_GT(previous, 0.999f);
}

// Every mapper: output in [0, 1], monotonic along a grey ramp, whatever the input.
TEST(ToneMap, EveryMapperGivesDisplayValuesInZeroToOne) {
    for (const ToneMapperName& entry : kToneMapperNames) {
        float previous = -1.0f;
        for (float x = 0.0f; x < 1e4f; x = x * 1.1f + 0.001f) {
            const glm::vec3 out = toneMap(glm::vec3(x), entry.mapper, 1.0f);
            EXPECT_GE(out.g, previous) << entry.name << " at " << x;
            previous = out.g;
            for (int c = 0; c < 3; ++c) {
                EXPECT_GE(out[c], 0.0f) << entry.name;
                EXPECT_LE(out[c], 1.0f) << entry.name;
            }
        }
        const glm::vec3 negative = toneMap({-5.0f, -0.01f, 0.0f}, entry.mapper, 1.0f);
        expectNear(negative, {0.0, 0.0, 0.0}, 1e-6);
    }
}

}  // namespace
}  // namespace pbr::cpu
