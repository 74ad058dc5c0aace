#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "base/error.h"
#include "files/image.h"

namespace pbr {
namespace {

namespace fs = std::filesystem;

Image solid(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Image image{width, height, 3, std::vector<std::uint8_t>(size_t(width * height) * 3)};
    for (size_t i = 0; i < image.pixels.size(); i += 3) {
        image.pixels[i] = r;
        image.pixels[i + 1] = g;
        image.pixels[i + 2] = b;
    }
    return image;
}

fs::path tempDir() {
    const fs::path dir =
        fs::temp_directory_path() / ("pbr-image-test-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

TEST(Image, PngRoundTripKeepsEveryByte) {
    Image image{7, 5, 3, {}};
    for (int i = 0; i < 7 * 5 * 3; ++i) image.pixels.push_back(std::uint8_t(i * 37 % 256));
    const fs::path path = tempDir() / "roundtrip.png";
    writePng(path, image);
    const Image back = readImage(path);
    EXPECT_EQ(back.width, 7);
    EXPECT_EQ(back.height, 5);
    EXPECT_EQ(back.channels, 3);
    EXPECT_EQ(back.pixels, image.pixels);
}

TEST(Image, FlipRowsReversesRowOrder) {
    Image image{1, 3, 1, {10, 20, 30}};
    EXPECT_EQ(flipRows(image).pixels, (std::vector<std::uint8_t>{30, 20, 10}));
}

TEST(Image, IdenticalImagesHaveNoDifference) {
    const Image a = solid(4, 4, 10, 20, 30);
    const ImageDiff diff = compareImages(a, a, 0);
    EXPECT_EQ(diff.maxChannelDiff, 0);
    EXPECT_EQ(diff.pixelsOverThreshold, 0u);
    EXPECT_TRUE(std::isinf(diff.psnr));
}

TEST(Image, MetricsOfOneChangedPixel) {
    const Image a = solid(10, 10, 100, 100, 100);
    Image b = a;
    b.pixels[3 * 42 + 1] = 110;  // pixel 42, green, +10
    const ImageDiff diff = compareImages(b, a, 2);
    EXPECT_EQ(diff.maxChannelDiff, 10);
    EXPECT_EQ(diff.pixelsOverThreshold, 1u);
    EXPECT_DOUBLE_EQ(diff.fractionOverThreshold, 0.01);
    // MSE = 10^2 / (10 * 10 * 3) samples
    const double mse = 100.0 / 300.0;
    EXPECT_NEAR(diff.psnr, 10.0 * std::log10(255.0 * 255.0 / mse), 1e-9);
    EXPECT_EQ(compareImages(b, a, 10).pixelsOverThreshold, 0u);  // "more than" the threshold
}

TEST(Image, DifferenceImageAmplifies) {
    const Image a = solid(2, 1, 50, 50, 50);
    Image b = a;
    b.pixels[0] = 53;  // +3 red on the first pixel
    b.pixels[5] = 0;   // -50 blue on the second
    const Image diff = differenceImage(b, a, 16);
    EXPECT_EQ(diff.at(0, 0, 0), 48);
    EXPECT_EQ(diff.at(0, 0, 1), 0);
    EXPECT_EQ(diff.at(1, 0, 2), 255);  // clamped
}

TEST(Image, SizeMismatchIsAnError) {
    EXPECT_THROW(compareImages(solid(2, 2, 0, 0, 0), solid(2, 3, 0, 0, 0), 0), Error);
}

TEST(Image, BadFilesNameThePathAndTheReason) {
    const fs::path dir = tempDir();
    auto messageOf = [](const fs::path& path) {
        try {
            readImage(path);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string missing = messageOf(dir / "missing.png");
    EXPECT_NE(missing.find("missing.png: no such file"), std::string::npos) << missing;

    std::ofstream(dir / "empty.png").close();
    const std::string empty = messageOf(dir / "empty.png");
    EXPECT_NE(empty.find("empty.png: empty file"), std::string::npos) << empty;

    std::ofstream(dir / "text.png") << "this is not a picture\n";
    const std::string text = messageOf(dir / "text.png");
    EXPECT_NE(text.find("text.png: not a PNG or JPEG image"), std::string::npos) << text;

    // A PNG cut in half.
    Image image = solid(64, 64, 1, 2, 3);
    for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = std::uint8_t(i * 7919 % 251);
    writePng(dir / "whole.png", image);
    std::ifstream in(dir / "whole.png", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(dir / "half.png", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    const std::string half = messageOf(dir / "half.png");
    EXPECT_NE(half.find("half.png: truncated or damaged PNG data"), std::string::npos) << half;

    // A JPEG cut short, and a PNG whose compressed data is damaged: words, not decoder codes.
    std::string damaged = bytes;
    for (size_t i = 60; i < 90; ++i) damaged[i] = char(0xff);
    std::ofstream(dir / "damaged.png", std::ios::binary) << damaged;
    const std::string bad = messageOf(dir / "damaged.png");
    EXPECT_NE(bad.find("damaged.png: truncated or damaged PNG data"), std::string::npos) << bad;
    std::ofstream(dir / "cut.jpg", std::ios::binary)
        << std::string("\xff\xd8\xff\xe0\x00\x10JFIF", 10);
    const std::string jpeg = messageOf(dir / "cut.jpg");
    EXPECT_NE(jpeg.find("cut.jpg: truncated or damaged JPEG data"), std::string::npos) << jpeg;
}

// A flipped width or height byte makes a small PNG claim a huge image. Deflate expands at most
// 1032 times, so rows that the whole file could not hold are refused from the header, before stb
// allocates for them (before this, up to 2 GB for a 1 KB file); the header's own size decodes.
TEST(Image, APngClaimingMoreRowsThanItsBytesCanHoldIsRefusedFromItsHeader) {
    const std::string png = encodePng(solid(64, 48, 10, 20, 30));
    const std::vector<std::uint8_t> whole(png.begin(), png.end());
    EXPECT_EQ(decodeImage(whole, "whole.png").width, 64);
    auto claiming = [&](std::uint32_t width, std::uint32_t height) {
        std::vector<std::uint8_t> bytes = whole;
        for (int i = 0; i < 4; ++i) {
            bytes[size_t(16 + i)] = std::uint8_t(width >> (24 - 8 * i));
            bytes[size_t(20 + i)] = std::uint8_t(height >> (24 - 8 * i));
        }
        try {
            decodeImage(bytes, "claims.png");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("decoded");
    };
    // 2e8 pixels: under the 2^28-pixel limit, 600 MB of rows from a file of a few hundred bytes
    const std::string huge = claiming(20000, 10000);
    EXPECT_EQ(huge, "claims.png: damaged PNG header (it claims 20000 x 10000 pixels, more than " +
                        std::to_string(png.size()) + " bytes of PNG can hold)");
    // what the file could hold (64 x 96 RGB rows are 18 KB, under 1032 times its size) is not
    // refused from the header: stb finds the data short
    const std::string twice = claiming(64, 96);
    EXPECT_EQ(twice, "claims.png: truncated or damaged PNG data");
}

}  // namespace
}  // namespace pbr

namespace pbr {
namespace {

// Damaged Radiance files: each refused with the file's name and the reason, none hangs or reads
// past the end (Debian's stb_image loops forever on a zero run count, which a truncated file
// produces).
TEST(Hdr, DamagedFilesAreRefusedWithAReason) {
    // a valid 8 x 2 run-length image: two scanlines of four channels, each 8 literal bytes
    std::string valid = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 8\n";
    for (int row = 0; row < 2; ++row) {
        valid += std::string{2, 2, 0, 8};
        for (const char value : {char(128), char(64), char(32), char(129)}) {
            valid += char(8) + std::string(8, value);
        }
    }
    const size_t data = valid.find("+X 8\n") + 5;  // the first scanline's header
    const HdrImage image = decodeHdr(valid, "valid.hdr");
    ASSERT_EQ(image.width, 8);
    ASSERT_EQ(image.height, 2);
    EXPECT_FLOAT_EQ(image.pixels[0], 128.0f * 2.0f / 256.0f);  // 128 x 2^(129 - 136)
    EXPECT_FLOAT_EQ(image.pixels[1], 64.0f * 2.0f / 256.0f);

    auto refusal = [](const std::string& bytes) {
        try {
            decodeHdr(bytes, "broken.hdr");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    const std::pair<std::string, std::string> cases[] = {
        {"GIF89a", "not a Radiance .hdr file"},
        {"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n", "truncated in the header"},
        {"#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 2 +X 8\n", "unsupported pixel format"},
        {"#?RADIANCE\n\n-Y 2 +X 8\n", "no FORMAT=32-bit_rle_rgbe"},
        {"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n+Y 2 +X 8\n", "unsupported resolution line"},
        {"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 0 +X 0\n", "out of range"},
        {"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 100000\n", "out of range"},
        {"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 9000 +X 9000\n" + std::string(64, '\2'),
         "truncated (9000 x 9000 pixels"},
        {valid.substr(0, valid.size() - 5), "truncated in the pixel data"},
        {valid.substr(0, data + 4) + '\0' + valid.substr(data + 5), "bad run-length data"},
        {valid.substr(0, data + 4) + char(128 + 9) + valid.substr(data + 5), "bad run-length data"},
        {valid.substr(0, data) + std::string{2, 2, 0, 9} + valid.substr(data + 4),
         "bad scanline header"},
    };
    for (const auto& [bytes, reason] : cases) {
        const std::string message = refusal(bytes);
        EXPECT_EQ(message.rfind("broken.hdr: ", 0), 0u) << message;
        EXPECT_NE(message.find(reason), std::string::npos)
            << "wanted \"" << reason << "\", got " << message;
    }
}

}  // namespace
}  // namespace pbr
