#include "files/mip_chain.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "base/error.h"

namespace pbr {

namespace {

// The sRGB decoding of a code in [0, 1] (IEC 61966-2-1), in double precision.
double srgbToLinear(double code) {
    return code <= 0.04045 ? code / 12.92 : std::pow((code + 0.055) / 1.055, 2.4);
}

constexpr int kBuckets = 4096;

struct SrgbTables {
    std::array<float, 256> linear{};  // each code's linear light
    // Where the nearest code changes: from linear light rounding[k] up, the sRGB encoding of the
    // light is nearer code k + 1 than code k (the decoding of (k + 0.5) / 255: the encoding rises
    // with the light, so the nearest code is the number of these at or below it).
    std::array<float, 256> rounding{};  // the last one past any light, so that a search stops
    // the nearest code of light kBuckets-th b: the search for light in [b, b + 1) / kBuckets
    // starts there and moves up (a step or two at most)
    std::array<std::uint8_t, kBuckets + 1> bucketStart{};
};

const SrgbTables& srgbTables() {
    static const SrgbTables tables = [] {
        SrgbTables t;
        for (int k = 0; k < 256; ++k) t.linear[size_t(k)] = float(srgbToLinear(k / 255.0));
        for (int k = 0; k < 255; ++k)
            t.rounding[size_t(k)] = float(srgbToLinear((k + 0.5) / 255.0));
        t.rounding[255] = 2.0f;
        for (int b = 0; b <= kBuckets; ++b) {
            const float light = float(b) / kBuckets;
            t.bucketStart[size_t(b)] =
                std::uint8_t(std::upper_bound(t.rounding.begin(), t.rounding.end() - 1, light) -
                             t.rounding.begin());
        }
        return t;
    }();
    return tables;
}

std::uint8_t nearestSrgbCode(const SrgbTables& tables, float light) {
    light = std::clamp(light, 0.0f, 1.0f);
    int code = tables.bucketStart[size_t(light * kBuckets)];
    while (light >= tables.rounding[size_t(code)]) ++code;
    return std::uint8_t(code);
}

std::uint8_t nearestCode(float value) {
    return std::uint8_t(std::clamp(std::floor(value + 0.5f), 0.0f, 255.0f));
}

// One side of the filter, from `from` texels to `to`: for each texel of the smaller level, the
// two texels of the larger one that linear filtering reads at its centre, and their weights
// (clamped to the edge, as the blit's sampler is).
struct Footprint {
    int first = 0;
    int count = 0;
    std::array<float, 2> weight{};
};

std::vector<Footprint> footprints(int from, int to) {
    const double ratio = double(from) / double(to);
    std::vector<Footprint> side(static_cast<size_t>(to));
    for (int i = 0; i < to; ++i) {
        const double at = (i + 0.5) * ratio - 0.5;  // the centre, in texels of the larger level
        const double first = std::floor(at), share = at - first;
        Footprint& f = side[size_t(i)];
        f.first = std::clamp(int(first), 0, from - 1);
        f.count = int(first) + 1 < from && share > 0.0 ? 2 : 1;
        f.weight = {f.count == 2 ? float(1.0 - share) : 1.0f, float(share)};
    }
    return side;
}

// A level `width` x `height` of `channels` values a texel, filtered down to `w` x `h` as floats:
// along the rows first, then the columns. `value(v, channel)` is what each value stands for (a
// level made before as it is; the image's codes through their channel's table).
template <typename T, typename Value>
std::vector<float> shrink(const T* level, const Value& value, int width, int height, int w, int h,
                          int channels) {
    const size_t c = size_t(channels);
    if (width == 2 * w && height == 2 * h) {
        // both sides even: 2x2 blocks, the same sums in the same order as the general case's
        // (0.5 a + 0.5 b is (a + b) / 2 exactly), in a loop the compiler can make wide
        std::vector<float> shrunk(size_t(w) * size_t(h) * c);
        const size_t in = size_t(width) * c, out = size_t(w) * c;
        for (int y = 0; y < h; ++y) {
            const T* top = level + size_t(2 * y) * in;
            const T* bottom = top + in;
            float* to = &shrunk[size_t(y) * out];
            for (size_t x = 0; x < size_t(w); ++x) {
                for (size_t ch = 0; ch < c; ++ch) {
                    const size_t a = 2 * x * c + ch, b = a + c;
                    const float upper = (value(top[a], ch) + value(top[b], ch)) * 0.5f;
                    const float lower = (value(bottom[a], ch) + value(bottom[b], ch)) * 0.5f;
                    to[x * c + ch] = (upper + lower) * 0.5f;
                }
            }
        }
        return shrunk;
    }
    const std::vector<Footprint> across = footprints(width, w), down = footprints(height, h);
    std::vector<float> rows(size_t(w) * size_t(height) * c, 0.0f);
    for (int y = 0; y < height; ++y) {
        const T* in = level + size_t(y) * size_t(width) * c;
        float* out = &rows[size_t(y) * size_t(w) * c];
        for (int x = 0; x < w; ++x) {
            const Footprint& f = across[size_t(x)];
            for (int t = 0; t < f.count; ++t) {
                const T* texel = in + size_t(f.first + t) * c;
                for (size_t ch = 0; ch < c; ++ch) {
                    out[size_t(x) * c + ch] += f.weight[size_t(t)] * value(texel[ch], ch);
                }
            }
        }
    }
    std::vector<float> shrunk(size_t(w) * size_t(h) * c, 0.0f);
    const size_t row = size_t(w) * c;
    for (int y = 0; y < h; ++y) {
        const Footprint& f = down[size_t(y)];
        float* out = &shrunk[size_t(y) * row];
        for (int t = 0; t < f.count; ++t) {
            const float* in = &rows[size_t(f.first + t) * row];
            for (size_t i = 0; i < row; ++i) out[i] += f.weight[size_t(t)] * in[i];
        }
    }
    return shrunk;
}

}  // namespace

std::vector<Image> mipChain(const Image& image, bool srgb) {
    const int channels = image.channels;
    if (channels < 1 || channels > 4 || image.width < 1 || image.height < 1 ||
        image.pixels.size() != size_t(image.width) * size_t(image.height) * size_t(channels)) {
        throw Error("mipChain: the image's size does not match its pixels");
    }
    // the channels that hold sRGB codes: all but alpha
    const int colour = !srgb ? 0 : channels == 2 || channels == 4 ? channels - 1 : channels;
    const SrgbTables& tables = srgbTables();
    // level 0's codes as the values they stand for: sRGB light, or the code itself
    static const std::array<float, 256> codes = [] {
        std::array<float, 256> c{};
        for (int k = 0; k < 256; ++k) c[size_t(k)] = float(k);
        return c;
    }();
    std::array<const float*, 4> tableOf{};
    for (int ch = 0; ch < channels; ++ch) {
        tableOf[size_t(ch)] = ch < colour ? tables.linear.data() : codes.data();
    }
    const auto code = [&](std::uint8_t v, size_t ch) { return tableOf[ch][v]; };
    const auto same = [](float v, size_t) { return v; };
    std::vector<float> level;
    std::vector<Image> chain;
    int width = image.width, height = image.height;
    while (width > 1 || height > 1) {
        const int w = std::max(1, width / 2), h = std::max(1, height / 2);
        level = chain.empty() ? shrink(image.pixels.data(), code, width, height, w, h, channels)
                              : shrink(level.data(), same, width, height, w, h, channels);
        Image next{w, h, channels, std::vector<std::uint8_t>(level.size())};
        for (size_t i = 0; i < size_t(w) * size_t(h); ++i) {
            for (int ch = 0; ch < channels; ++ch) {
                const size_t at = i * size_t(channels) + size_t(ch);
                next.pixels[at] =
                    ch < colour ? nearestSrgbCode(tables, level[at]) : nearestCode(level[at]);
            }
        }
        chain.push_back(std::move(next));
        width = w;
        height = h;
    }
    return chain;
}

}  // namespace pbr
