// KTX 1 files: the header as the KTX 1 specification lays it out (offsets checked byte by byte),
// round trips, half floats, and every kind of damage refused with a reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>

#include "base/error.h"
#include "files/ktx.h"
#include "support/process.h"

namespace pbr {
namespace {

namespace fs = std::filesystem;

KtxImage smallCube() {
    KtxImage image;
    image.format = KtxFormat::RGBA16F;
    image.width = image.height = 4;
    image.faces = 6;
    image.levels = 3;
    for (int level = 0; level < 3; ++level) {
        for (int face = 0; face < 6; ++face) {
            std::vector<std::uint8_t> data(image.imageBytes(level));
            for (size_t i = 0; i < data.size(); ++i)
                data[i] = std::uint8_t(i * 7 + face * 31 + level * 3);
            image.images.push_back(data);
        }
    }
    image.metadata["pbr.cache-key"] = "abc123";
    return image;
}

std::uint32_t word(const std::string& bytes, size_t offset) {
    std::uint32_t v;
    std::memcpy(&v, bytes.data() + offset, 4);
    return v;
}

std::string messageOf(const fs::path& path) {
    try {
        readKtx(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "read";
}

TEST(Ktx, HeaderFollowsTheSpecification) {
    const fs::path dir = test::testOutputDir("ktx_header");
    writeKtx(dir / "cube.ktx", smallCube());
    const std::string bytes = test::readBytes(dir / "cube.ktx");
    const unsigned char identifier[12] = {0xAB, 'K',  'T',  'X',  ' ',  '1',
                                          '1',  0xBB, '\r', '\n', 0x1A, '\n'};
    EXPECT_EQ(std::memcmp(bytes.data(), identifier, 12), 0);
    EXPECT_EQ(word(bytes, 12), 0x04030201u);  // endianness
    EXPECT_EQ(word(bytes, 16), 0x140Bu);      // glType GL_HALF_FLOAT
    EXPECT_EQ(word(bytes, 20), 2u);           // glTypeSize
    EXPECT_EQ(word(bytes, 24), 0x1908u);      // glFormat GL_RGBA
    EXPECT_EQ(word(bytes, 28), 0x881Au);      // glInternalFormat GL_RGBA16F
    EXPECT_EQ(word(bytes, 36), 4u);           // pixelWidth
    EXPECT_EQ(word(bytes, 40), 4u);           // pixelHeight
    EXPECT_EQ(word(bytes, 52), 6u);           // numberOfFaces
    EXPECT_EQ(word(bytes, 56), 3u);           // numberOfMipmapLevels
    const std::uint32_t keyValueBytes = word(bytes, 60);
    EXPECT_EQ(keyValueBytes % 4, 0u);
    // level 0 starts after the key/value data with imageSize = one face: 4 x 4 x 4 channels x 2
    // bytes
    EXPECT_EQ(word(bytes, 64 + keyValueBytes), 128u);
    // the whole file: header, key/values, then per level imageSize + 6 faces
    EXPECT_EQ(bytes.size(), 64 + keyValueBytes + (4 + 6 * 128) + (4 + 6 * 32) + (4 + 6 * 8));
}

TEST(Ktx, RoundTripKeepsEverything) {
    const fs::path dir = test::testOutputDir("ktx_roundtrip");
    const KtxImage written = smallCube();
    writeKtx(dir / "cube.ktx", written);
    const KtxImage read = readKtx(dir / "cube.ktx");
    EXPECT_EQ(read.format, KtxFormat::RGBA16F);
    EXPECT_EQ(read.width, 4);
    EXPECT_EQ(read.faces, 6);
    EXPECT_EQ(read.levels, 3);
    EXPECT_EQ(read.images, written.images);
    EXPECT_EQ(read.metadata.at("pbr.cache-key"), "abc123");
    // and writing it again gives the same bytes
    writeKtx(dir / "again.ktx", read);
    EXPECT_TRUE(test::readBytes(dir / "cube.ktx") == test::readBytes(dir / "again.ktx"));
}

TEST(Ktx, HalfFloats) {
    EXPECT_EQ(floatToHalf(1.0f), 0x3C00);
    EXPECT_EQ(floatToHalf(-2.0f), 0xC000);
    EXPECT_EQ(floatToHalf(0.5f), 0x3800);
    EXPECT_EQ(floatToHalf(65504.0f), 0x7BFF);  // the largest half
    EXPECT_EQ(floatToHalf(1e6f), 0x7C00);      // overflow: infinity
    EXPECT_EQ(floatToHalf(0.0f), 0x0000);
    EXPECT_EQ(floatToHalf(std::ldexp(1.0f, -24)), 0x0001);  // the smallest subnormal
    for (float v : {0.001f, 0.1f, 0.75f, 1.5f, 3.14159f, 100.0f, 5000.0f, -0.3f}) {
        EXPECT_NEAR(halfToFloat(floatToHalf(v)), v, std::abs(v) / 1024.0f) << v;  // 11 bits
    }
    EXPECT_EQ(halfToFloat(0x0001), std::ldexp(1.0f, -24));
    EXPECT_TRUE(std::isinf(halfToFloat(0x7C00)));
}

TEST(Ktx, DamageIsRefusedWithAReason) {
    const fs::path dir = test::testOutputDir("ktx_damage");
    writeKtx(dir / "good.ktx", smallCube());
    const std::string good = test::readBytes(dir / "good.ktx");

    std::ofstream(dir / "truncated.ktx", std::ios::binary) << good.substr(0, good.size() - 10);
    EXPECT_NE(messageOf(dir / "truncated.ktx").find("truncated.ktx: truncated KTX file"),
              std::string::npos);

    std::string wrong = good;
    wrong[1] = 'X';
    std::ofstream(dir / "identifier.ktx", std::ios::binary) << wrong;
    EXPECT_NE(messageOf(dir / "identifier.ktx").find("not a KTX 1 file"), std::string::npos);

    std::ofstream(dir / "empty.ktx").close();
    EXPECT_NE(messageOf(dir / "empty.ktx").find("not a KTX 1 file"), std::string::npos);

    std::string size = good;
    const std::uint32_t keyValueBytes = word(good, 60);
    size[64 + keyValueBytes] = 0x7f;  // level 0's imageSize no longer matches 4 x 4 RGBA16F
    std::ofstream(dir / "size.ktx", std::ios::binary) << size;
    EXPECT_NE(messageOf(dir / "size.ktx").find("level 0 size does not match"), std::string::npos);

    std::ofstream(dir / "trailing.ktx", std::ios::binary) << good << "more";
    EXPECT_NE(messageOf(dir / "trailing.ktx").find("trailing data"), std::string::npos);

    EXPECT_NE(messageOf(dir / "missing.ktx").find("missing.ktx: no such file"), std::string::npos);
}

TEST(Ktx, InconsistentImagesAreNotWritten) {
    const fs::path dir = test::testOutputDir("ktx_inconsistent");
    KtxImage image = smallCube();
    image.images.pop_back();
    EXPECT_THROW(writeKtx(dir / "bad.ktx", image), Error);
    EXPECT_FALSE(fs::exists(dir / "bad.ktx"));
}

}  // namespace
}  // namespace pbr
