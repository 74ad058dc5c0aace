#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "base/error.h"
#include "files/mip_chain.h"

namespace pbr {
namespace {

Image grey(int width, int height, const std::vector<int>& values) {
    Image image{width, height, 1, {}};
    for (int v : values) image.pixels.push_back(std::uint8_t(v));
    return image;
}

// The sRGB encoding of linear light (IEC 61966-2-1), written out here from the standard, and
// the nearest 8-bit code.
double encode(double light) {
    return light <= 0.0031308 ? 12.92 * light : 1.055 * std::pow(light, 1 / 2.4) - 0.055;
}
int srgbCode(double light) {
    return int(std::lround(encode(light) * 255.0));
}

// glTexImage2D's rule: each side halved and rounded down, never below 1, down to 1x1.
TEST(MipChain, SidesHalveRoundedDownToOneByOne) {
    const auto sizes = [](int width, int height) {
        std::vector<std::pair<int, int>> out;
        const Image image{width, height, 1, std::vector<std::uint8_t>(size_t(width * height))};
        for (const Image& level : mipChain(image, false))
            out.emplace_back(level.width, level.height);
        return out;
    };
    using Sizes = std::vector<std::pair<int, int>>;
    EXPECT_EQ(sizes(8, 2), (Sizes{{4, 1}, {2, 1}, {1, 1}}));
    EXPECT_EQ(sizes(5, 3), (Sizes{{2, 1}, {1, 1}}));
    EXPECT_EQ(sizes(1, 4), (Sizes{{1, 2}, {1, 1}}));
    EXPECT_EQ(sizes(1, 1), Sizes{});
    EXPECT_EQ(sizes(1024, 512).size(), 10u);
}

// Level 1 holds the 2x2 blocks' means (0.5 rounds up), level 2 the mean of all 16 texels: 7/16
// rounds to 0, where the mean of level 1's rounded codes (3/4) would round to 1.
TEST(MipChain, EvenSidesAverageBlocksOfLevelZeroWithoutAddingUpRounding) {
    // blocks (top left, top right, bottom left, bottom right): sums 2, 2, 2 and 1
    const Image image = grey(4, 4,
                             {1, 0, 1, 0,  //
                              0, 1, 1, 0,  //
                              0, 1, 1, 0,  //
                              0, 1, 0, 0});
    const std::vector<Image> chain = mipChain(image, false);
    ASSERT_EQ(chain.size(), 2u);
    EXPECT_EQ(chain[0].pixels, (std::vector<std::uint8_t>{1, 1, 1, 0}));
    EXPECT_EQ(chain[1].pixels, std::vector<std::uint8_t>{0});
}

// A side of 5 goes to 2: the new texels' centres fall at old texels 0.75 and 3.25 (a quarter of
// texel 0 and three quarters of texel 1; three quarters of 3 and a quarter of 4); from 3 to 1 the
// centre is texel 1's; texels of a side of 1 stay where they are.
TEST(MipChain, OddSidesReadTheLevelAboveAtEachTexelsCentre) {
    const std::vector<Image> chain = mipChain(grey(5, 1, {10, 20, 30, 40, 50}), false);
    ASSERT_EQ(chain.size(), 2u);
    // 17.5 and 42.5, each rounded up; then their mean, 30, from the unrounded values
    EXPECT_EQ(chain[0].pixels, (std::vector<std::uint8_t>{18, 43}));
    EXPECT_EQ(chain[1].pixels, std::vector<std::uint8_t>{30});
    EXPECT_EQ(mipChain(grey(3, 1, {0, 100, 230}), false)[0].pixels, std::vector<std::uint8_t>{100});
    EXPECT_EQ(mipChain(grey(1, 3, {0, 100, 230}), false)[0].pixels, std::vector<std::uint8_t>{100});
    EXPECT_EQ(mipChain(grey(4, 1, {0, 100, 30, 230}), false)[0].pixels,
              (std::vector<std::uint8_t>{50, 130}));
}

// Two black and two white sRGB texels are half the light, which sRGB encodes as 188, not the
// codes' mean 128; the alpha beside them is not sRGB and is the codes' mean (127.5 up to 128).
TEST(MipChain, SrgbColourIsAveragedAsLightAndAlphaAsItIs) {
    const Image image{2,
                      2,
                      4,
                      {0, 0, 0, 0, 255, 255, 255, 255,  //
                       255, 255, 255, 0, 0, 0, 0, 255}};
    const std::vector<Image> chain = mipChain(image, true);
    ASSERT_EQ(chain.size(), 1u);
    const int half = srgbCode(0.5);
    EXPECT_EQ(half, 188);
    EXPECT_EQ(chain[0].pixels, (std::vector<std::uint8_t>{std::uint8_t(half), std::uint8_t(half),
                                                          std::uint8_t(half), 128}));
    // the same texels read as linear: every channel the codes' mean
    EXPECT_EQ(mipChain(image, false)[0].pixels, (std::vector<std::uint8_t>{128, 128, 128, 128}));
    // grey + alpha: grey is colour, the second channel alpha
    const Image greyAlpha{2, 1, 2, {0, 0, 255, 255}};
    EXPECT_EQ(mipChain(greyAlpha, true)[0].pixels,
              (std::vector<std::uint8_t>{std::uint8_t(half), 128}));
}

// A 2x2 block of one code gives that code back, for every code, sRGB or not: the decoding and
// the rounding back agree everywhere.
TEST(MipChain, EveryCodeOfAUniformBlockComesBack) {
    for (bool srgb : {false, true}) {
        SCOPED_TRACE(srgb ? "sRGB" : "linear");
        Image image{512, 2, 3, {}};
        for (int y = 0; y < 2; ++y) {
            for (int x = 0; x < 512; ++x) {
                const auto code = std::uint8_t(x / 2);
                image.pixels.insert(image.pixels.end(), {code, code, code});
            }
        }
        const std::vector<Image> chain = mipChain(image, srgb);
        const Image& level = chain[0];
        ASSERT_EQ(level.width, 256);
        for (int x = 0; x < 256; ++x) {
            for (int c = 0; c < 3; ++c) ASSERT_EQ(int(level.at(x, 0, c)), x) << "channel " << c;
        }
    }
}

// Light between two neighbouring codes rounds to the nearer code as the standard's encoding
// says: 16x16 blocks of codes k and k + 1, from 120 to 136 of their 256 texels one code up (the
// encoded mean close to k + 0.5 on either side), every k, down to the 1x1 level. Ties are left
// out: below code 11 the encoding is a straight line and 128 of 256 is the midpoint.
TEST(MipChain, SrgbLightRoundsToTheNearestCode) {
    const auto decode = [](int code) {
        const double c = code / 255.0;
        return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    };
    for (int k = 0; k < 255; ++k) {
        for (int upper = 120; upper <= 136; upper += 4) {
            Image rgb{16, 16, 3, {}};
            for (int i = 0; i < 256; ++i) {
                const auto v = std::uint8_t(i < upper ? k + 1 : k);
                rgb.pixels.insert(rgb.pixels.end(), {v, v, v});
            }
            const double light = (upper * decode(k + 1) + (256 - upper) * decode(k)) / 256;
            if (std::abs(encode(light) * 255 - (k + 0.5)) < 1e-4) continue;  // either is nearest
            EXPECT_EQ(int(mipChain(rgb, true).back().pixels[0]), srgbCode(light))
                << "code " << k << ", " << upper << " of 256 texels one code up";
        }
    }
}

TEST(MipChain, AnImageWhoseSizeDoesNotMatchItsPixelsIsAnError) {
    EXPECT_THROW(mipChain(Image{2, 2, 3, std::vector<std::uint8_t>(11)}, false), Error);
    EXPECT_THROW(mipChain(Image{2, 2, 5, std::vector<std::uint8_t>(20)}, false), Error);
}

}  // namespace
}  // namespace pbr
