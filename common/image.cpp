#include "image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>

#include "error.h"
#include "paths.h"

namespace pbr {

namespace fs = std::filesystem;

Image readImage(const fs::path& path, int wantChannels) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Error(displayPath(path) + ": no such file");
    if (fs::is_directory(path, ec)) throw Error(displayPath(path) + ": is a directory");
    if (fs::file_size(path, ec) == 0) throw Error(displayPath(path) + ": empty file");
    int width = 0, height = 0, channels = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> data(
        stbi_load(path.c_str(), &width, &height, &channels, wantChannels), stbi_image_free);
    if (!data) {
        const char* reason = stbi_failure_reason();
        throw Error(displayPath(path) + ": cannot decode image (" +
                    (reason ? reason : "unknown reason") + ")");
    }
    Image image;
    image.width = width;
    image.height = height;
    image.channels = wantChannels ? wantChannels : channels;
    image.pixels.assign(data.get(),
                        data.get() + size_t(width) * size_t(height) * size_t(image.channels));
    return image;
}

Image decodeImage(const std::vector<std::uint8_t>& bytes, const std::string& what,
                  int wantChannels) {
    if (bytes.empty()) throw Error(what + ": empty image");
    int width = 0, height = 0, channels = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> data(
        stbi_load_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels,
                              wantChannels),
        stbi_image_free);
    if (!data) {
        const char* reason = stbi_failure_reason();
        throw Error(what + ": cannot decode image (" + (reason ? reason : "unknown reason") + ")");
    }
    Image image{width, height, wantChannels ? wantChannels : channels, {}};
    image.pixels.assign(data.get(),
                        data.get() + size_t(width) * size_t(height) * size_t(image.channels));
    return image;
}

void writePng(const fs::path& path, const Image& image) {
    if (image.width <= 0 || image.height <= 0 || image.channels < 1 || image.channels > 4 ||
        image.pixels.size() !=
            size_t(image.width) * size_t(image.height) * size_t(image.channels)) {
        throw Error(displayPath(path) + ": cannot write an empty or malformed image");
    }
    std::error_code ec;
    if (path.has_parent_path()) fs::create_directories(path.parent_path(), ec);
    const int ok = stbi_write_png(path.c_str(), image.width, image.height, image.channels,
                                  image.pixels.data(), image.width * image.channels);
    if (!ok) throw Error(displayPath(path) + ": cannot write PNG (is the folder writable?)");
}

HdrImage readHdr(const fs::path& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Error(displayPath(path) + ": no such file");
    if (fs::file_size(path, ec) == 0) throw Error(displayPath(path) + ": empty file");
    if (!stbi_is_hdr(path.c_str())) throw Error(displayPath(path) + ": not a Radiance .hdr file");
    int width = 0, height = 0, channels = 0;
    std::unique_ptr<float, void (*)(void*)> data(
        stbi_loadf(path.c_str(), &width, &height, &channels, 3), stbi_image_free);
    if (!data) {
        const char* reason = stbi_failure_reason();
        throw Error(displayPath(path) + ": cannot decode HDR image (" +
                    (reason ? reason : "unknown reason") + ")");
    }
    HdrImage image{width, height, {}};
    image.pixels.assign(data.get(), data.get() + size_t(width) * size_t(height) * 3);
    return image;
}

void writeHdr(const fs::path& path, const HdrImage& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != size_t(image.width) * size_t(image.height) * 3) {
        throw Error(displayPath(path) + ": cannot write an empty or malformed HDR image");
    }
    std::error_code ec;
    if (path.has_parent_path()) fs::create_directories(path.parent_path(), ec);
    if (!stbi_write_hdr(path.c_str(), image.width, image.height, 3, image.pixels.data())) {
        throw Error(displayPath(path) + ": cannot write HDR (is the folder writable?)");
    }
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
