// Real outdoor HDRs: an unclipped sun goes far past a half float's 65504. An equirect of a grey
// sky (radiance 1) with a small sun at 1e5 or 1e7: 06 must write maps with no NaN and no
// infinity anywhere, that keep the sun's energy; 04 and 05 must draw lit spheres, not black ones.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "files/image.h"
#include "files/ktx.h"
#include "support/golden.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 128, kHeight = 64;
// The sun: texels x 44..46, y 18..20 (3 x 3 texels, 25 to 32 degrees above the horizon).
bool inSun(int x, int y) {
    return x >= 44 && x <= 46 && y >= 18 && y <= 20;
}

// Writes the sky with its sun at `sun`; returns the radiance each sun texel really holds (the
// RGBE encoding rounds it) times its solid angle, summed: the sun's power per unit area, L Omega.
double writeSky(const fs::path& path, float sun) {
    HdrImage image{kWidth, kHeight, std::vector<float>(size_t(kWidth) * kHeight * 3, 1.0f)};
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            if (!inSun(x, y)) continue;
            for (int c = 0; c < 3; ++c)
                image.pixels[(size_t(y) * kWidth + size_t(x)) * 3 + c] = sun;
        }
    }
    writeHdr(path, image);
    const HdrImage read = readHdr(path);
    const double pi = std::numbers::pi;
    double power = 0.0;
    for (int y = 0; y < kHeight; ++y) {
        const double latitude = (0.5 - (y + 0.5) / kHeight) * pi;
        const double solidAngle = (2.0 * pi / kWidth) * (pi / kHeight) * std::cos(latitude);
        for (int x = 0; x < kWidth; ++x) {
            if (inSun(x, y)) power += (double(read.at(x, y).r) - 1.0) * solidAngle;
        }
    }
    return power;
}

// The solid angle of texel (i, j) of a cube face `size` texels wide: the area on the unit sphere
// of the square it covers on the face at distance 1.
double texelSolidAngle(int i, int j, int size) {
    auto corner = [](double x, double y) {
        return std::atan2(x * y, std::sqrt(x * x + y * y + 1));
    };
    const double x0 = 2.0 * i / size - 1.0, x1 = 2.0 * (i + 1) / size - 1.0;
    const double y0 = 2.0 * j / size - 1.0, y1 = 2.0 * (j + 1) / size - 1.0;
    return corner(x0, y0) - corner(x0, y1) - corner(x1, y0) + corner(x1, y1);
}

// Every value of every face and level, as floats.
std::vector<float> values(const KtxImage& image) {
    std::vector<float> out;
    for (const auto& bytes : image.images) {
        if (image.bytesPerChannel() == 4) {
            const size_t count = bytes.size() / 4;
            const size_t start = out.size();
            out.resize(start + count);
            std::memcpy(&out[start], bytes.data(), bytes.size());
        } else {
            for (size_t i = 0; i + 1 < bytes.size(); i += 2) {
                out.push_back(halfToFloat(std::uint16_t(bytes[i] | bytes[i + 1] << 8)));
            }
        }
    }
    return out;
}

TEST(HdrRange, SunsPastHalfFloatKeepTheirEnergyAndNeverMakeANaN) {
    const fs::path dir = testOutputDir("hdr_range");
    double meanExcess[2] = {0.0, 0.0};  // the irradiance map's mean over all normals, less 1
    double power[2] = {0.0, 0.0};
    int index = 0;
    for (const float sun : {1.0e5f, 1.0e7f}) {
        const fs::path hdr = dir / ("sun" + std::to_string(index) + ".hdr");
        power[index] = writeSky(hdr, sun);
        const fs::path out = dir / ("maps" + std::to_string(index));
        fs::create_directory(out);
        const RunResult run =
            runSample({"06_brdf_lut", "--headless", "--size", "64x36", "--output",
                       (out / "06.png").string(), "--no-cache", "--hdr", hdr.string()});
        ASSERT_EQ(run.exitCode, 0) << run.err;
        EXPECT_NE(run.err.find("past half-float range (65504): its IBL maps are kept in 32-bit "
                               "floats"),
                  std::string::npos)
            << run.err;
        for (const char* map : {".irradiance.ktx", ".prefiltered.ktx"}) {
            const KtxImage image = readKtx(out / (hdr.stem().string() + map));
            EXPECT_EQ(image.format, KtxFormat::RGBA32F) << map;
            size_t bad = 0;
            float largest = 0.0f;
            for (const float value : values(image)) {
                if (!std::isfinite(value) || value < 0.0f) ++bad;
                largest = std::max(largest, value);
            }
            EXPECT_EQ(bad, 0u) << map << ": NaN, infinite or negative values";
            EXPECT_GT(largest, 1.0f) << map << ": the sun is missing";
            if (std::string(map) != ".irradiance.ktx") continue;
            const std::vector<float> texels = values(image);
            double sum = 0.0, total = 0.0;
            for (int face = 0; face < 6; ++face) {
                for (int j = 0; j < image.width; ++j) {
                    for (int i = 0; i < image.width; ++i) {
                        const double omega = texelSolidAngle(i, j, image.width);
                        sum +=
                            omega * texels[(size_t(face * image.width + j) * image.width + i) * 4];
                        total += omega;
                    }
                }
            }
            EXPECT_NEAR(total, 4.0 * std::numbers::pi, 1e-9);
            meanExcess[index] = sum / total - 1.0;
        }
        ++index;
    }
    // The energy: the irradiance map holds irradiance / pi, and over all normals its mean is the
    // environment's mean radiance (each direction of the sky lights half the normals, by a
    // cosine that integrates to pi): the grey sky's 1 plus the sun's L Omega / (4 pi). Clipped
    // or overflowed maps lose it; the convolution's own sampling error is well under 2 %.
    for (int i = 0; i < 2; ++i) {
        const double expected = power[i] / (4.0 * std::numbers::pi);
        std::printf("sun %d: mean excess %.4f, expected %.4f (ratio %.4f)\n", i, meanExcess[i],
                    expected, meanExcess[i] / expected);
        EXPECT_NEAR(meanExcess[i] / expected, 1.0, 0.02)
            << "sun " << i << ": " << meanExcess[i] << " against " << expected;
    }
    // And linearly: a sun 100 times brighter adds 100 times the light.
    EXPECT_NEAR(meanExcess[1] / meanExcess[0], power[1] / power[0], 0.01 * power[1] / power[0]);
}

// Past 1e20 (more than the maps' 32-bit sums can carry) a value is lowered, and one line says so.
TEST(HdrRange, ValuesPastWhatTheSumsCarryAreClampedAndSaid) {
    const fs::path dir = testOutputDir("hdr_range_clamp");
    const fs::path hdr = dir / "blinding.hdr";
    writeSky(hdr, 1.0e25f);
    const RunResult run =
        runSample({"04_ibl_irradiance", "--headless", "--size", "32x18", "--no-cache", "--output",
                   (dir / "04.png").string(), "--hdr", hdr.string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto lines = run.errLines();
    ASSERT_EQ(lines.size(), 1u) << run.err;
    EXPECT_NE(lines[0].find("blinding.hdr: 9 texels above 1e+20 lowered to 1e+20"),
              std::string::npos)
        << lines[0];
}

// The pictures: with a 1e5 sun, 04's and 05's spheres were black (NaN from overflowed half
// floats); lit now, they are as far from black as the grey sky.
TEST(HdrRange, SamplesDrawLitSpheresUnderABrightSun) {
    const fs::path dir = testOutputDir("hdr_range_pictures");
    const fs::path hdr = dir / "sun.hdr";
    writeSky(hdr, 1.0e5f);
    for (const char* sample : {"04_ibl_irradiance", "05_ibl_specular"}) {
        const fs::path picture = dir / (std::string(sample) + ".png");
        const RunResult run = runSample({sample, "--headless", "--size", "320x180", "--output",
                                         picture.string(), "--hdr", hdr.string()},
                                        {.setEnv = {{"PBR_CACHE_DIR", (dir / "cache").string()}}});
        ASSERT_EQ(run.exitCode, 0) << run.err;
        const Image image = readImage(picture, 3);
        size_t black = 0;
        for (size_t i = 0; i < image.pixels.size(); i += 3) {
            if (image.pixels[i] < 8 && image.pixels[i + 1] < 8 && image.pixels[i + 2] < 8) ++black;
        }
        EXPECT_LT(double(black) / double(image.width * image.height), 0.005)
            << sample << ": " << black << " black pixels";
    }
}

}  // namespace
}  // namespace pbr::test
