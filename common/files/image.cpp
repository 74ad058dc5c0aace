#include "files/image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <optional>
#include <string_view>

#include "base/error.h"
#include "base/output.h"
#include "base/paths.h"

namespace pbr {

namespace fs = std::filesystem;

namespace {

bool startsWith(const std::vector<std::uint8_t>& bytes, std::initializer_list<std::uint8_t> magic) {
    return bytes.size() >= magic.size() && std::equal(magic.begin(), magic.end(), bytes.begin());
}
bool isPng(const std::vector<std::uint8_t>& bytes) {
    return startsWith(bytes, {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'});
}
bool isJpeg(const std::vector<std::uint8_t>& bytes) {
    return startsWith(bytes, {0xff, 0xd8, 0xff});
}

// stb_image's failure codes ("outofdata", "bad zlib header", ...) in words a user understands.
std::string decodeFailure(const std::vector<std::uint8_t>& bytes) {
    const std::string code = stbi_failure_reason() ? stbi_failure_reason() : "";
    if (code == "outofmem") return "out of memory while decoding the image";
    if (code == "too large") return "image too large to decode";
    if (code == "0-pixel image" || code == "0 width" || code == "invalid width")
        return "the image has no pixels";
    const bool png = isPng(bytes);
    const bool jpeg = isJpeg(bytes);
    if (png) {
        if (code == "1/2/4/8/16-bit only") return "unsupported PNG bit depth";
        return "truncated or damaged PNG data";
    }
    if (jpeg) {
        if (code == "only 8-bit") return "unsupported JPEG (12-bit samples)";
        if (code == "no header height") return "unsupported JPEG (height given after the pixels)";
        return "truncated or damaged JPEG data";
    }
    if (code == "unknown image type") return "not a PNG or JPEG image";
    return "damaged or unsupported image data";
}

// A PNG's rows (a filter byte each, then the pixels at the header's bit depth) come out of
// deflate, which expands its input at most 1032 times (a 258-byte match in two one-bit codes):
// a header claiming more rows than the whole file could hold is damaged, and is refused before
// stb allocates for it (a flipped width byte asked for up to 2 GB).
void refuseImpossiblePng(const std::vector<std::uint8_t>& bytes, const std::string& what) {
    if (bytes.size() < 33 || !isPng(bytes) ||
        !std::equal(bytes.begin() + 12, bytes.begin() + 16, "IHDR")) {
        return;  // stb says what is wrong with it
    }
    auto get32 = [&](size_t at) {
        return double((std::uint32_t(bytes[at]) << 24) | (std::uint32_t(bytes[at + 1]) << 16) |
                      (std::uint32_t(bytes[at + 2]) << 8) | std::uint32_t(bytes[at + 3]));
    };
    const double width = get32(16), height = get32(20), depth = bytes[24];
    const int colorType = bytes[25];
    const double samples = colorType == 2 ? 3 : colorType == 4 ? 2 : colorType == 6 ? 4 : 1;
    const double rowBytes = 1 + std::ceil(width * depth * samples / 8);
    if (height * rowBytes > 1032.0 * double(bytes.size())) {
        const std::string claimed =
            std::to_string(std::uint64_t(width)) + " x " + std::to_string(std::uint64_t(height));
        throw Error(what + ": damaged PNG header (it claims " + claimed + " pixels, more than " +
                    std::to_string(bytes.size()) + " bytes of PNG can hold)");
    }
    // Each chunk up to IEND must hold the bytes its length claims: stb grows its buffer of
    // compressed data to what an IDAT chunk claims before reading it (a 528-byte file claiming
    // 1.4 GB asked for that). stb fails on such a chunk anyway, after the allocation.
    for (size_t at = 8; bytes.size() - at >= 8;) {
        const std::uint64_t length = std::uint64_t(get32(at));
        if (length > bytes.size() - at - 8) {
            throw Error(what + ": truncated or damaged PNG data (a chunk at byte " +
                        std::to_string(at) + " claims " + std::to_string(length) + " bytes, " +
                        std::to_string(bytes.size() - at - 8) + " are left)");
        }
        const auto type = bytes.begin() + std::ptrdiff_t(at + 4);
        if (std::equal(type, type + 4, "IEND")) break;
        at += 12 + length;  // length, type, data, CRC
        if (at > bytes.size()) break;
    }
}

}  // namespace

Image readImage(const fs::path& path, int wantChannels) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Error(displayPath(path) + ": no such file");
    if (fs::is_directory(path, ec)) throw Error(displayPath(path) + ": is a directory");
    const std::string text = readTextFile(path);
    if (text.empty()) throw Error(displayPath(path) + ": empty file");
    return decodeImage(std::vector<std::uint8_t>(text.begin(), text.end()), displayPath(path),
                       wantChannels);
}

Image decodeImage(const std::vector<std::uint8_t>& bytes, const std::string& what,
                  int wantChannels) {
    if (bytes.empty()) throw Error(what + ": empty image");
    if (bytes.size() > size_t(std::numeric_limits<int>::max()))
        throw Error(what + ": image file too large");
    // PNG and JPEG only, the formats of texture sets and of glTF's images: stb's other readers
    // allocate for any size their header claims before the data is there, and its Radiance
    // reader loops forever on a truncated file (the suite reads .hdr files itself, decodeHdr).
    if (!isPng(bytes) && !isJpeg(bytes)) throw Error(what + ": not a PNG or JPEG image");
    int width = 0, height = 0, channels = 0;
    const bool known =
        stbi_info_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels);
    // A damaged header may claim any size: refuse more than 2^28 pixels (16384^2) before stb
    // allocates for them.
    if (known && double(width) * double(height) > double(1 << 28)) {
        throw Error(what + ": image too large (" + std::to_string(width) + " x " +
                    std::to_string(height) + " pixels)");
    }
    // A JPEG codes each 8 x 8 block of its fullest component in one bit at the least (its DC
    // scan), so N bytes hold at most 512 N pixels: a header claiming more is damaged, refused
    // before stb allocates for it (stb reads missing data as zeros: a 140-byte file claiming
    // 16384 x 16384 decoded to 268 MB of grey pixels).
    if (known && isJpeg(bytes) && double(width) * double(height) > 512.0 * double(bytes.size())) {
        throw Error(what + ": damaged JPEG header (it claims " + std::to_string(width) + " x " +
                    std::to_string(height) + " pixels, more than " + std::to_string(bytes.size()) +
                    " bytes of JPEG can hold)");
    }
    refuseImpossiblePng(bytes, what);
    std::unique_ptr<stbi_uc, void (*)(void*)> data(
        stbi_load_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels,
                              wantChannels),
        stbi_image_free);
    if (!data) throw Error(what + ": " + decodeFailure(bytes));
    // a promise kept whatever stb does (its PNM reader, no longer reached, made 0 x 0 pictures)
    if (width < 1 || height < 1) throw Error(what + ": the image has no pixels");
    Image image{width, height, wantChannels ? wantChannels : channels, {}};
    image.pixels.assign(data.get(),
                        data.get() + size_t(width) * size_t(height) * size_t(image.channels));
    return image;
}

namespace {
// stb's writers hand over the encoded bytes in pieces; they are kept in memory, then written whole.
void appendBytes(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
}
}  // namespace

std::string encodePng(const Image& image, PngEncoding encoding) {
    if (image.width <= 0 || image.height <= 0 || image.channels < 1 || image.channels > 4 ||
        image.pixels.size() !=
            size_t(image.width) * size_t(image.height) * size_t(image.channels)) {
        throw Error("cannot encode an empty or malformed image as PNG");
    }
    // Fast: one filter for every row (Sub, each byte less its left neighbour) and stb's shortest
    // match search: a 1280x720 frame of 01, 05 or 07 encodes in 38-66 ms instead of 87-100 ms
    // with stb's defaults, 1-9 % larger (measured 2026-12-04 on the three frames). Small: stb's
    // defaults, for what is written once and carried often: the 25 maps of the material sets
    // come to 18.5 MB instead of 22.1, and 12.8 MB instead of 16.2 once web/embed.py deflates
    // their rows again (the same filters kept), so the pages that carry them weigh 4 MB less.
    const bool fast = encoding == PngEncoding::Fast;
    stbi_write_force_png_filter = fast ? 1 : -1;
    stbi_write_png_compression_level = fast ? 5 : 8;
    std::string bytes;
    if (!stbi_write_png_to_func(appendBytes, &bytes, image.width, image.height, image.channels,
                                image.pixels.data(), image.width * image.channels)) {
        throw Error("PNG encoding failed");
    }
    return bytes;
}

void writePng(const fs::path& path, const Image& image, PngEncoding encoding) {
    writeFileAtomically(path, [&] { return encodePng(image, encoding); });
}

namespace {
// The Radiance RGBE pixel as a float triple, exactly as stb_image converts it (mantissa times
// 2^(exponent - 136); exponent 0 is black), so that our decoder and stb's agree to the bit.
void rgbeToFloat(const std::uint8_t* rgbe, float* rgb) {
    // 2^(e - 136) for each exponent byte, made once (a call to ldexp per pixel was most of the
    // decoding time in a page); every value is a power of two a float holds exactly
    static const auto scales = [] {
        std::array<float, 256> table{};
        for (int e = 1; e < 256; ++e) table[size_t(e)] = float(std::ldexp(1.0f, e - (128 + 8)));
        return table;
    }();
    const float scale = scales[rgbe[3]];  // exponent 0: black
    for (int c = 0; c < 3; ++c) rgb[c] = float(rgbe[c]) * scale;
}
// One run-length scanline at `at` (its header 2, 2, width first) into `rgb`: nullptr, or what is
// wrong with it. A function of its own, called once a row: a browser compiles a WebAssembly
// function with its fast compiler first and swaps in the optimised code at a later call, so a
// decoder that loops over the whole image in one call runs unoptimised to its end (measured: the
// environment decoded in a third of the time in a page).
[[gnu::noinline]] const char* decodeHdrRow(std::string_view bytes, size_t& at, int width,
                                           std::uint8_t* scanline, float* rgb) {
    constexpr const char* kTruncated = "truncated in the pixel data";
    constexpr const char* kBadRun = "bad run-length data";
    const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
    if (bytes.size() - at < 4) return kTruncated;
    if (data[at] != 2 || data[at + 1] != 2 || ((data[at + 2] << 8) | data[at + 3]) != width) {
        return "bad scanline header";
    }
    at += 4;
    for (int channel = 0; channel < 4; ++channel) {
        for (int x = 0; x < width;) {
            if (at >= bytes.size()) return kTruncated;
            int count = data[at++];
            const bool run = count > 128;
            if (run) count -= 128;
            if (count == 0 || count > width - x) return kBadRun;
            if (run) {
                if (at >= bytes.size()) return kTruncated;
                const std::uint8_t value = data[at++];
                for (int k = 0; k < count; ++k, ++x)
                    scanline[size_t(x) * 4 + size_t(channel)] = value;
            } else {
                if (size_t(count) > bytes.size() - at) return kTruncated;
                for (int k = 0; k < count; ++k, ++x)
                    scanline[size_t(x) * 4 + size_t(channel)] = data[at++];
            }
        }
    }
    for (int x = 0; x < width; ++x) rgbeToFloat(&scanline[size_t(x) * 4], &rgb[size_t(x) * 3]);
    return nullptr;
}

}  // namespace

// A decoder of our own rather than stb_image's: Debian's stb loops forever on a truncated
// run-length scanline (a zero count makes no progress), and a sample must refuse such a file.
HdrImage decodeHdr(std::string_view bytes, const std::string& name) {
    size_t at = 0;
    auto fail = [&](const std::string& reason) { return Error(name + ": " + reason); };
    auto line = [&]() -> std::optional<std::string_view> {
        const size_t end = bytes.find('\n', at);
        if (end == std::string_view::npos) return std::nullopt;
        const std::string_view text = bytes.substr(at, end - at);
        at = end + 1;
        return text;
    };
    const auto magic = line();
    if (!magic || (*magic != "#?RADIANCE" && *magic != "#?RGBE")) {
        throw fail("not a Radiance .hdr file (no #?RADIANCE line)");
    }
    bool rgbe = false;
    for (;;) {
        const auto header = line();
        if (!header) throw fail("truncated in the header");
        if (header->empty()) break;
        if (*header == "FORMAT=32-bit_rle_rgbe") rgbe = true;
        if (header->starts_with("FORMAT=") && !rgbe) {
            throw fail("unsupported pixel format (" + printable(header->substr(0, 60)) +
                       (header->size() > 60 ? "..." : "") + "; only 32-bit_rle_rgbe)");
        }
    }
    if (!rgbe) throw fail("no FORMAT=32-bit_rle_rgbe line in the header");
    const auto resolution = line();
    int width = 0, height = 0;
    char extra = 0;
    if (!resolution || std::sscanf(std::string(*resolution).c_str(), "-Y %d +X %d%c", &height,
                                   &width, &extra) != 2) {
        throw fail("unsupported resolution line (only \"-Y <height> +X <width>\", rows top first)");
    }
    constexpr int kMaxSide = 32768;
    if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide) {
        throw fail("image size " + std::to_string(width) + " x " + std::to_string(height) +
                   " out of range (1 to " + std::to_string(kMaxSide) + " a side)");
    }
    // The fewest bytes the pixels can take (runs of 127 at best): refuse a short file before
    // allocating for the size its header claims.
    const bool runLength = width >= 8 && width < 32768;
    const size_t leastBytes =
        size_t(height) * std::min(size_t(width) * 4, 4 + 8 * ((size_t(width) + 126) / 127));
    if (bytes.size() - at < (runLength ? leastBytes : size_t(width) * size_t(height) * 4)) {
        throw fail("truncated (" + std::to_string(width) + " x " + std::to_string(height) +
                   " pixels need more data than the file holds)");
    }

    HdrImage image{width, height, std::vector<float>(size_t(width) * size_t(height) * 3)};
    auto next = [&]() -> std::uint8_t {
        if (at >= bytes.size()) throw fail("truncated in the pixel data");
        return std::uint8_t(bytes[at++]);
    };
    auto flat = [&](size_t firstPixel) {
        for (size_t i = firstPixel; i < size_t(width) * size_t(height); ++i) {
            std::uint8_t pixel[4];
            for (std::uint8_t& byte : pixel) byte = next();
            rgbeToFloat(pixel, &image.pixels[i * 3]);
        }
    };
    // Uncompressed files start straight with pixels; run-length rows start with 2, 2, width.
    if (!runLength || bytes[at] != 2 || bytes[at + 1] != 2 || (bytes[at + 2] & 0x80)) {
        flat(0);
        return image;
    }
    std::vector<std::uint8_t> scanline(size_t(width) * 4);
    for (int y = 0; y < height; ++y) {
        if (const char* problem = decodeHdrRow(bytes, at, width, scanline.data(),
                                               &image.pixels[size_t(y) * size_t(width) * 3])) {
            throw fail(std::string(problem) + " in row " + std::to_string(y));
        }
    }
    return image;
}

namespace {
// A row's largest value: called once a row, for the browser's optimised code (see decodeHdrRow).
[[gnu::noinline]] float largestOf(const float* values, size_t count) {
    float largest = 0.0f;
    for (size_t i = 0; i < count; ++i) largest = std::max(largest, values[i]);
    return largest;
}
}  // namespace

float maxValue(const HdrImage& image) {
    float largest = 0.0f;
    const size_t row = std::max<size_t>(1, size_t(image.width) * 3);
    for (size_t at = 0; at < image.pixels.size(); at += row) {
        largest = std::max(largest,
                           largestOf(&image.pixels[at], std::min(row, image.pixels.size() - at)));
    }
    return largest;
}

bool fitsHalfFloat(const HdrImage& image) {
    return maxValue(image) <= kMaxHalfFloat;
}

HdrImage readHdr(const fs::path& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Error(displayPath(path) + ": no such file");
    if (fs::is_directory(path, ec)) throw Error(displayPath(path) + ": is a directory, not a file");
    const std::string bytes = readTextFile(path);
    if (bytes.empty()) throw Error(displayPath(path) + ": empty file");
    return decodeHdr(bytes, displayPath(path));
}

std::string encodeHdr(const HdrImage& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != size_t(image.width) * size_t(image.height) * 3) {
        throw Error("cannot write an empty or malformed HDR image");
    }
    std::string bytes;
    if (!stbi_write_hdr_to_func(appendBytes, &bytes, image.width, image.height, 3,
                                image.pixels.data())) {
        throw Error("HDR encoding failed");
    }
    return bytes;
}

void writeHdr(const fs::path& path, const HdrImage& image) {
    writeFileAtomically(path, [&] { return encodeHdr(image); });
}

Image flipRows(const Image& image) {
    Image flipped = image;
    const size_t rowBytes = size_t(image.width) * size_t(image.channels);
    for (int y = 0; y < image.height; ++y) {
        std::copy_n(
            image.pixels.begin() + std::ptrdiff_t(size_t(y) * rowBytes), rowBytes,
            flipped.pixels.begin() + std::ptrdiff_t(size_t(image.height - 1 - y) * rowBytes));
    }
    return flipped;
}

namespace {
int colourChannels(const Image& image) {
    return image.channels >= 3 ? 3 : 1;
}

void requireSameShape(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height) {
        throw Error("images differ in size: " + std::to_string(a.width) + "x" +
                    std::to_string(a.height) + " vs " + std::to_string(b.width) + "x" +
                    std::to_string(b.height));
    }
    if (colourChannels(a) != colourChannels(b)) throw Error("images differ in colour channels");
}
}  // namespace

ImageDiff compareImages(const Image& actual, const Image& expected, int threshold) {
    requireSameShape(actual, expected);
    ImageDiff diff;
    const int channels = colourChannels(actual);
    double squaredSum = 0.0, absSum = 0.0;
    for (int y = 0; y < actual.height; ++y) {
        for (int x = 0; x < actual.width; ++x) {
            int pixelMax = 0;
            for (int c = 0; c < channels; ++c) {
                const int d = std::abs(int(actual.at(x, y, c)) - int(expected.at(x, y, c)));
                pixelMax = std::max(pixelMax, d);
                squaredSum += double(d) * d;
                absSum += d;
            }
            diff.maxChannelDiff = std::max(diff.maxChannelDiff, pixelMax);
            if (pixelMax > threshold) ++diff.pixelsOverThreshold;
        }
    }
    const double samples = double(actual.width) * actual.height * channels;
    const double pixels = double(actual.width) * actual.height;
    diff.fractionOverThreshold = double(diff.pixelsOverThreshold) / pixels;
    diff.meanAbsDiff = absSum / samples;
    const double mse = squaredSum / samples;
    diff.psnr = mse == 0.0 ? std::numeric_limits<double>::infinity()
                           : 10.0 * std::log10(255.0 * 255.0 / mse);
    return diff;
}

Image differenceImage(const Image& actual, const Image& expected, int gain) {
    requireSameShape(actual, expected);
    const int channels = colourChannels(actual);
    Image out{actual.width, actual.height, 3, {}};
    out.pixels.resize(size_t(out.width) * size_t(out.height) * 3);
    for (int y = 0; y < actual.height; ++y) {
        for (int x = 0; x < actual.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const int source = channels == 3 ? c : 0;
                const int d =
                    std::abs(int(actual.at(x, y, source)) - int(expected.at(x, y, source)));
                out.pixels[(size_t(y) * size_t(out.width) + size_t(x)) * 3 + size_t(c)] =
                    std::uint8_t(std::min(255, d * gain));
            }
        }
    }
    return out;
}

}  // namespace pbr
