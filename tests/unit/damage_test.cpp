// Damage never crashes: every truncation and a few thousand random byte flips of real files, fed
// to the KTX, Radiance .hdr and PNG readers. Each must either decode (a flip in the pixel data is
// still a picture) or refuse with one Error; never crash, hang or throw anything else. Run under
// AddressSanitizer + UBSan by the test command, where an out-of-bounds read is a failure too.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <random>
#include <string>

#include "base/error.h"
#include "files/image.h"
#include "files/ktx.h"

namespace pbr {
namespace {

constexpr int kFlips = 3000;

struct Outcome {
    int decoded = 0, refused = 0;
};

// Decodes `bytes` cut at every length, then with `kFlips` random bytes set to random values (one
// to three at a time); `decode` throws pbr::Error for a refusal.
Outcome damage(const std::string& bytes, const std::function<void(const std::string&)>& decode) {
    Outcome outcome;
    auto attempt = [&](const std::string& damaged, const std::string& what) {
        try {
            decode(damaged);
            ++outcome.decoded;
        } catch (const Error& e) {
            ++outcome.refused;
            const std::string message = e.what();
            EXPECT_EQ(message.find('\n'), std::string::npos) << what << ": " << message;
            EXPECT_GT(message.size(), 10u) << what << ": " << message;
        } catch (const std::exception& e) {
            ADD_FAILURE() << what << ": not an Error but " << e.what();
        }
    };
    for (size_t length = 0; length < bytes.size(); ++length) {
        attempt(bytes.substr(0, length), "cut at " + std::to_string(length));
    }
    std::mt19937 random(20261123);
    for (int i = 0; i < kFlips; ++i) {
        std::string damaged = bytes;
        const int count = 1 + int(random() % 3);
        for (int k = 0; k < count; ++k) damaged[random() % damaged.size()] = char(random() & 0xff);
        attempt(damaged, "flip " + std::to_string(i));
    }
    return outcome;
}

TEST(Damage, KtxReaderRefusesEveryCutAndSurvivesFlips) {
    KtxImage cube{.format = KtxFormat::RGBA16F, .width = 16, .height = 16, .faces = 6, .levels = 5};
    for (int level = 0; level < cube.levels; ++level) {
        for (int face = 0; face < 6; ++face) {
            std::vector<std::uint8_t> texels(cube.imageBytes(level));
            for (size_t i = 0; i < texels.size(); ++i) texels[i] = std::uint8_t(i * 31 + face);
            cube.images.push_back(texels);
        }
    }
    cube.metadata = {{"KTXorientation", "S=r,T=u"}, {"pbr.cacheKey", "a key"}};
    const std::string bytes = encodeKtx(cube);
    const Outcome outcome =
        damage(bytes, [](const std::string& b) { decodeKtx(b, "damaged.ktx"); });
    EXPECT_GE(outcome.refused, int(bytes.size()));  // every cut is refused
    EXPECT_GT(outcome.decoded, 0);                  // flips in the texels still read
}

// The header fields a damaged cache file held: each refused by name, never read as a negative int.
TEST(Damage, KtxHeaderFieldsAreCheckedAsUnsigned) {
    KtxImage lut{.format = KtxFormat::RG16F, .width = 4, .height = 4};
    lut.images.push_back(std::vector<std::uint8_t>(lut.imageBytes(0)));
    const std::string good = encodeKtx(lut);
    auto withField = [&](size_t offset, std::uint32_t value) {
        std::string bytes = good;
        for (int i = 0; i < 4; ++i) bytes[offset + size_t(i)] = char((value >> (8 * i)) & 0xff);
        try {
            decodeKtx(bytes, "x.ktx");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    // Offsets from the KTX 1 specification: width 36, height 40, faces 52, levels 56.
    EXPECT_EQ(withField(56, 0xFFFFFFFFu),
              "x.ktx: bad mip level count 4294967295 (at most 3 for "
              "this size)");
    EXPECT_EQ(withField(52, 0xFFFFFFFFu), "x.ktx: faces must be 1 or 6, not 4294967295");
    EXPECT_EQ(withField(36, 0xFFFFFFFFu), "x.ktx: bad KTX image size 4294967295 x 4");
    EXPECT_EQ(withField(40, 0u), "x.ktx: bad KTX image size 4 x 0");
    EXPECT_EQ(withField(56, 0u), "no error");  // 0: the file holds level 0 only
}

TEST(Damage, HdrReaderRefusesEveryCutAndSurvivesFlips) {
    HdrImage image{40, 12, std::vector<float>(40 * 12 * 3)};
    for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float(i % 97) * 0.37f;
    image.pixels[5] = 1.0e5f;  // a sun
    const std::string bytes = encodeHdr(image);
    const Outcome outcome = damage(bytes, [](const std::string& b) { decodeHdr(b, "d.hdr"); });
    EXPECT_GE(outcome.refused, int(bytes.size()));
    EXPECT_GT(outcome.decoded, 0);
}

TEST(Damage, PngReaderRefusesEveryCutAndSurvivesFlips) {
    Image image{24, 16, 3, std::vector<std::uint8_t>(24 * 16 * 3)};
    for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = std::uint8_t(i * 7 % 251);
    const std::string bytes = encodePng(image);
    const Outcome outcome = damage(bytes, [](const std::string& b) {
        decodeImage(std::vector<std::uint8_t>(b.begin(), b.end()), "d.png");
    });
    // A cut may keep every pixel (only the IEND chunk lost), which stb accepts: nearly every cut
    // is refused.
    EXPECT_GE(outcome.refused, int(bytes.size()) - 16);
    EXPECT_GT(outcome.decoded, 0);
}

}  // namespace
}  // namespace pbr
