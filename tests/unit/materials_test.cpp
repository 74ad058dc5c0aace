// The project's material sets: properties each must have to read as its name, derived from what
// the material is (not from the recipe's numbers), and determinism.
#include <gtest/gtest.h>

#include <cmath>

#include "materials.h"
#include "procedural.h"

namespace pbr::materials {
namespace {

constexpr int kSize = 512;  // large enough for the wall's mortar joints to be several texels wide

struct Stats {
    double mean = 0, min = 1, max = 0;
};

// Mean / min / max of one channel, 0..1.
Stats channelStats(const Image& image, int channel) {
    Stats s;
    const size_t count = size_t(image.width) * size_t(image.height);
    for (size_t i = 0; i < count; ++i) {
        const double v = image.pixels[i * size_t(image.channels) + size_t(channel)] / 255.0;
        s.mean += v / double(count);
        s.min = std::min(s.min, v);
        s.max = std::max(s.max, v);
    }
    return s;
}

// Share of texels for which predicate(pixel index) holds.
template <class F>
double share(const Image& image, F predicate) {
    const size_t count = size_t(image.width) * size_t(image.height);
    size_t hits = 0;
    for (size_t i = 0; i < count; ++i) hits += predicate(i) ? 1 : 0;
    return double(hits) / double(count);
}

// Mean tilt of the normal map away from +Z, in degrees.
double meanTiltDegrees(const Image& normal) {
    return 180.0 / M_PI *
           std::acos(std::clamp(channelStats(normal, 2).mean * 2.0 - 1.0, -1.0, 1.0));
}

class Materials : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        for (const std::string& name : kSetNames) sets_.push_back(bake(name, kSize));
    }
    static const MaterialSet& set(const std::string& name) {
        for (const MaterialSet& s : sets_)
            if (s.name == name) return s;
        throw std::runtime_error("no set " + name);
    }
    static std::vector<MaterialSet> sets_;
};
std::vector<MaterialSet> Materials::sets_;

TEST_F(Materials, EverySetHasFiveMapsOfTheRightShape) {
    for (const MaterialSet& s : sets_) {
        for (const Image* map : {&s.albedo, &s.normal, &s.metallic, &s.roughness, &s.ao}) {
            EXPECT_EQ(map->width, kSize) << s.name;
            EXPECT_EQ(map->height, kSize) << s.name;
        }
        EXPECT_EQ(s.albedo.channels, 3);
        EXPECT_EQ(s.normal.channels, 3);
        EXPECT_EQ(s.metallic.channels, 1);
        // every normal points out of the surface and is (close to) unit length
        for (size_t i = 0; i < size_t(kSize * kSize); ++i) {
            const glm::vec3 n(s.normal.pixels[i * 3] / 127.5f - 1.0f,
                              s.normal.pixels[i * 3 + 1] / 127.5f - 1.0f,
                              s.normal.pixels[i * 3 + 2] / 127.5f - 1.0f);
            ASSERT_GT(n.z, 0.0f) << s.name;
            ASSERT_NEAR(glm::length(n), 1.0f, 0.02f) << s.name;
        }
    }
}

TEST_F(Materials, RustedIronIsMetalWithPatchesOfRoughOrangeRust) {
    const MaterialSet& s = set("rusted_iron");
    // both bare metal and rust, each a real share of the surface
    const double metal = share(s.metallic, [&](size_t i) { return s.metallic.pixels[i] > 200; });
    const double rust = share(s.metallic, [&](size_t i) { return s.metallic.pixels[i] < 30; });
    EXPECT_GT(metal, 0.3);
    EXPECT_GT(rust, 0.15);
    // rust is orange-brown (red > green > blue) and rough; the metal is grey and smoother
    double rustRough = 0, metalRough = 0, orange = 0, metalTint = 0;
    int rustCount = 0, metalCount = 0;
    for (size_t i = 0; i < size_t(kSize * kSize); ++i) {
        const int r = s.albedo.pixels[i * 3], g = s.albedo.pixels[i * 3 + 1],
                  b = s.albedo.pixels[i * 3 + 2];
        if (s.metallic.pixels[i] < 30) {
            rustRough += s.roughness.pixels[i] / 255.0;
            orange += (r > g + 20 && g > b + 10) ? 1 : 0;
            ++rustCount;
        } else if (s.metallic.pixels[i] > 200) {
            metalRough += s.roughness.pixels[i] / 255.0;
            metalTint += std::abs(r - b) / 255.0;
            ++metalCount;
        }
    }
    EXPECT_GT(rustRough / rustCount, 0.75);
    EXPECT_LT(metalRough / metalCount, 0.55);
    EXPECT_GT(orange / rustCount, 0.9);
    EXPECT_LT(metalTint / metalCount, 0.04);  // the bare metal is grey
    // pitting: a few texels deep in occlusion, and the normal map is not flat
    EXPECT_LT(channelStats(s.ao, 0).min, 0.6);
    EXPECT_GT(meanTiltDegrees(s.normal), 2.0);
}

TEST_F(Materials, GoldIsSmoothYellowMetal) {
    const MaterialSet& s = set("gold");
    EXPECT_EQ(channelStats(s.metallic, 0).min, 1.0);
    EXPECT_LT(channelStats(s.roughness, 0).mean, 0.35);
    const Stats r = channelStats(s.albedo, 0), g = channelStats(s.albedo, 1),
                b = channelStats(s.albedo, 2);
    EXPECT_GT(r.mean, 0.85);
    EXPECT_GT(r.mean, g.mean + 0.05);
    EXPECT_GT(g.mean, b.mean + 0.15);
    // light wear: roughness varies a little, never becomes matte
    EXPECT_GT(channelStats(s.roughness, 0).max - channelStats(s.roughness, 0).min, 0.05);
    EXPECT_LT(channelStats(s.roughness, 0).max, 0.7);
}

TEST_F(Materials, GrassIsGreenRoughDielectric) {
    const MaterialSet& s = set("grass");
    EXPECT_EQ(channelStats(s.metallic, 0).max, 0.0);
    EXPECT_GT(channelStats(s.roughness, 0).mean, 0.7);
    const double green = share(s.albedo, [&](size_t i) {
        return s.albedo.pixels[i * 3 + 1] > s.albedo.pixels[i * 3] &&
               s.albedo.pixels[i * 3 + 1] > s.albedo.pixels[i * 3 + 2];
    });
    EXPECT_GT(green, 0.6);
    EXPECT_GT(meanTiltDegrees(s.normal), 5.0);  // blades stand out
}

TEST_F(Materials, PlasticIsSmoothUniformColouredDielectric) {
    const MaterialSet& s = set("plastic");
    EXPECT_EQ(channelStats(s.metallic, 0).max, 0.0);
    EXPECT_LT(channelStats(s.roughness, 0).mean, 0.4);
    for (int c = 0; c < 3; ++c) {
        const Stats stats = channelStats(s.albedo, c);
        EXPECT_LT(stats.max - stats.min, 0.05) << "channel " << c;  // one colour
    }
    // saturated: channels far apart
    EXPECT_GT(channelStats(s.albedo, 2).mean - channelStats(s.albedo, 0).mean, 0.4);
    EXPECT_LT(meanTiltDegrees(s.normal), 2.0);
}

TEST_F(Materials, WallHasBricksAndRecessedMortar) {
    const MaterialSet& s = set("wall");
    EXPECT_EQ(channelStats(s.metallic, 0).max, 0.0);
    // mortar: light, low-saturation texels; bricks: red-brown ones; both present
    const double mortar = share(s.albedo, [&](size_t i) {
        const int r = s.albedo.pixels[i * 3], b = s.albedo.pixels[i * 3 + 2];
        return r > 140 && r - b < 25;
    });
    const double brick = share(s.albedo, [&](size_t i) {
        return s.albedo.pixels[i * 3] > s.albedo.pixels[i * 3 + 2] + 50;
    });
    EXPECT_GT(mortar, 0.05);
    EXPECT_GT(brick, 0.5);
    // grooves are occluded, and the edges tilt the normals strongly
    EXPECT_LT(channelStats(s.ao, 0).min, 0.6);
    EXPECT_GT(meanTiltDegrees(s.normal), 5.0);
}

TEST(MaterialBake, SameBytesEveryTime) {
    for (const std::string& name : kSetNames) {
        const MaterialSet a = bake(name, 64), b = bake(name, 64);
        EXPECT_EQ(a.albedo.pixels, b.albedo.pixels) << name;
        EXPECT_EQ(a.normal.pixels, b.normal.pixels) << name;
        EXPECT_EQ(a.roughness.pixels, b.roughness.pixels) << name;
        EXPECT_EQ(a.ao.pixels, b.ao.pixels) << name;
    }
}

// The normal map convention (OpenGL, +Y up): a surface rising to the right tilts its normal to
// the left, one rising towards the image's top (row 0) tilts it down.
TEST(Procedural, NormalsFromHeightFollowOpenGlConvention) {
    const procedural::Field risingRight = procedural::makeField(
        16, [](float u, float, int, int) { return std::sin(u * 2.0f * float(M_PI)); });
    const auto normals = procedural::normalsFromHeight(risingRight, 0.05f);
    EXPECT_LT(normals[risingRight.index(0, 8)].x, -0.1f);  // at u ~ 0 the sine rises
    EXPECT_NEAR(normals[risingRight.index(0, 8)].y, 0.0f, 1e-6f);
    const procedural::Field risingUp = procedural::makeField(16, [](float, float v, int, int) {
        return -std::sin(v * 2.0f * float(M_PI));  // rises as v shrinks, towards row 0, near v ~ 0
    });
    const auto up = procedural::normalsFromHeight(risingUp, 0.05f);
    EXPECT_LT(up[risingUp.index(8, 0)].y, -0.1f);
    EXPECT_NEAR(up[risingUp.index(8, 0)].x, 0.0f, 1e-6f);
}

TEST(Procedural, FbmTilesAcrossTheEdges) {
    for (float v : {0.1f, 0.5f, 0.9f}) {
        EXPECT_NEAR(procedural::tilingFbm(0.0f, v, 4, 5, 0.5f, 3),
                    procedural::tilingFbm(1.0f, v, 4, 5, 0.5f, 3), 1e-5f);
        EXPECT_NEAR(procedural::tilingFbm(v, 0.0f, 4, 5, 0.5f, 3),
                    procedural::tilingFbm(v, 1.0f, 4, 5, 0.5f, 3), 1e-5f);
    }
}

}  // namespace
}  // namespace pbr::materials
