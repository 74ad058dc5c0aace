#pragma once
// Images on the CPU: PNG read and write, and the comparison metrics and difference picture the
// golden tests use. No OpenGL. Rows are stored top row first, as in a PNG file.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace pbr {

struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;  // 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA
    std::vector<std::uint8_t> pixels;

    std::uint8_t at(int x, int y, int c) const {
        return pixels[(size_t(y) * size_t(width) + size_t(x)) * size_t(channels) + size_t(c)];
    }
};

// Reads a PNG or JPEG as 8-bit; channels = what the file has, or `wantChannels` when non-zero.
// Throws Error("<path>: <reason>"), also for any other format.
Image readImage(const std::filesystem::path& path, int wantChannels = 0);
// Decodes an image file's bytes held in memory; `what` names it in the error.
Image decodeImage(const std::vector<std::uint8_t>& bytes, const std::string& what,
                  int wantChannels = 0);
// How hard the PNG encoder works; the pixels are the same either way, only the bytes differ.
enum class PngEncoding {
    Fast,   // the frames a run writes: one filter (Sub) for every row, stb's level 5
    Small,  // the assets the build bakes once and the pages carry: stb's defaults (each row
            // tried with all five filters, level 8)
};
// An 8-bit PNG file's bytes (the same bytes for the same pixels). Throws Error when malformed.
std::string encodePng(const Image& image, PngEncoding encoding = PngEncoding::Fast);
// Writes an 8-bit PNG, whole or not at all (see output.h). Throws Error("<path>: <reason>").
void writePng(const std::filesystem::path& path, const Image& image,
              PngEncoding encoding = PngEncoding::Fast);
// The image with its rows in the opposite order (GL reads bottom row first).
Image flipRows(const Image& image);

// A float RGB image (linear radiance), rows top first: Radiance .hdr files.
struct HdrImage {
    int width = 0;
    int height = 0;
    std::vector<float> pixels;  // RGB

    glm::vec3 at(int x, int y) const {
        const size_t i = (size_t(y) * size_t(width) + size_t(x)) * 3;
        return {pixels[i], pixels[i + 1], pixels[i + 2]};
    }
};
// The largest half-float value, 65504: an HDR image fits a 16-bit float texture when no value is
// larger.
inline constexpr float kMaxHalfFloat = 65504.0f;
bool fitsHalfFloat(const HdrImage& image);
// The largest value of an HDR image (0 for an empty one).
float maxValue(const HdrImage& image);

// Reads a Radiance .hdr; throws Error("<path>: <reason>") for anything but a complete file
// (missing, empty, not Radiance, an unsupported layout, a size out of range, bad run-length data,
// truncated).
HdrImage readHdr(const std::filesystem::path& path);
// The same from the file's bytes; `name` is what the error messages call it.
HdrImage decodeHdr(std::string_view bytes, const std::string& name);
// A Radiance .hdr file's bytes (RGBE, run-length encoded; same bytes for the same pixels).
std::string encodeHdr(const HdrImage& image);
// Writes a Radiance .hdr (RGBE, run-length encoded; same bytes for the same pixels), whole or not
// at all. Throws Error("<path>: <reason>").
void writeHdr(const std::filesystem::path& path, const HdrImage& image);

// How far `actual` is from `expected` (same size; colour channels only, alpha ignored).
struct ImageDiff {
    int maxChannelDiff = 0;          // largest |a - b| of any channel, 0..255
    size_t pixelsOverThreshold = 0;  // pixels with any channel differing by more than `threshold`
    double fractionOverThreshold = 0.0;
    double psnr = 0.0;         // dB over RGB; +infinity when identical
    double meanAbsDiff = 0.0;  // per channel, 0..255
};
ImageDiff compareImages(const Image& actual, const Image& expected, int threshold);

// |actual - expected| * gain per channel on black, so a one-level change is visible.
Image differenceImage(const Image& actual, const Image& expected, int gain);

}  // namespace pbr
