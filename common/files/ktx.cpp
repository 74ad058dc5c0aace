#include "files/ktx.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "base/error.h"
#include "base/output.h"
#include "base/paths.h"

namespace pbr {

namespace fs = std::filesystem;

namespace {

constexpr std::uint8_t kIdentifier[12] = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x31,
                                          0x31, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
constexpr std::uint32_t kEndianness = 0x04030201;
constexpr std::uint32_t GL_HALF_FLOAT_ = 0x140B, GL_FLOAT_ = 0x1406;
constexpr std::uint32_t GL_RG_ = 0x8227, GL_RGB_ = 0x1907, GL_RGBA_ = 0x1908;
constexpr std::uint32_t GL_RG16F_ = 0x822F, GL_RGB16F_ = 0x881B, GL_RGBA16F_ = 0x881A,
                        GL_RGBA32F_ = 0x8814;

struct FormatInfo {
    KtxFormat format;
    std::uint32_t type, typeSize, glFormat, internalFormat;
};
constexpr FormatInfo kFormats[] = {
    {KtxFormat::RG16F, GL_HALF_FLOAT_, 2, GL_RG_, GL_RG16F_},
    {KtxFormat::RGB16F, GL_HALF_FLOAT_, 2, GL_RGB_, GL_RGB16F_},
    {KtxFormat::RGBA16F, GL_HALF_FLOAT_, 2, GL_RGBA_, GL_RGBA16F_},
    {KtxFormat::RGBA32F, GL_FLOAT_, 4, GL_RGBA_, GL_RGBA32F_},
};

const FormatInfo& info(KtxFormat format) {
    for (const FormatInfo& f : kFormats) {
        if (f.format == format) return f;
    }
    throw Error("KTX: unknown format");
}

size_t padTo4(size_t n) {
    return (n + 3) & ~size_t(3);
}

void put32(std::string& out, std::uint32_t v) {
    out.append(reinterpret_cast<const char*>(&v), 4);
}

// The shape checks both directions share; `where` names the file.
void check(const KtxImage& image, const std::string& where) {
    if (image.width < 1 || image.height < 1) throw Error(where + "empty image");
    if (image.faces != 1 && image.faces != 6) throw Error(where + "faces must be 1 or 6");
    if (image.faces == 6 && image.width != image.height)
        throw Error(where + "cube map faces must be square");
    const int maxLevels = 1 + int(std::log2(double(std::max(image.width, image.height))));
    if (image.levels < 1 || image.levels > maxLevels) throw Error(where + "bad mip level count");
    if (image.images.size() != size_t(image.levels) * size_t(image.faces)) {
        throw Error(where + "image count does not match levels x faces");
    }
    for (int level = 0; level < image.levels; ++level) {
        for (int face = 0; face < image.faces; ++face) {
            if (image.images[size_t(level * image.faces + face)].size() !=
                image.imageBytes(level)) {
                throw Error(where + "level " + std::to_string(level) + " has the wrong size");
            }
        }
    }
}

}  // namespace

int KtxImage::channels() const {
    switch (format) {
        case KtxFormat::RG16F:
            return 2;
        case KtxFormat::RGB16F:
            return 3;
        default:
            return 4;
    }
}

int KtxImage::bytesPerChannel() const {
    return int(info(format).typeSize);
}

size_t KtxImage::imageBytes(int level) const {
    const size_t w = size_t(std::max(1, width >> level)), h = size_t(std::max(1, height >> level));
    return w * h * size_t(channels()) * size_t(bytesPerChannel());
}

std::string encodeKtx(const KtxImage& image) {
    check(image, "");
    const FormatInfo& f = info(image.format);
    std::string out(reinterpret_cast<const char*>(kIdentifier), 12);
    std::string keyValues;
    for (const auto& [key, value] : image.metadata) {
        const std::string pair = key + '\0' + value + '\0';
        put32(keyValues, std::uint32_t(pair.size()));
        keyValues += pair;
        keyValues.append(padTo4(pair.size()) - pair.size(), '\0');
    }
    for (std::uint32_t v : {kEndianness, f.type, f.typeSize, f.glFormat, f.internalFormat,
                            f.glFormat, std::uint32_t(image.width), std::uint32_t(image.height), 0u,
                            0u, std::uint32_t(image.faces), std::uint32_t(image.levels),
                            std::uint32_t(keyValues.size())}) {
        put32(out, v);
    }
    out += keyValues;
    for (int level = 0; level < image.levels; ++level) {
        put32(out, std::uint32_t(image.imageBytes(level)));  // one face, for cube maps too
        for (int face = 0; face < image.faces; ++face) {
            const auto& data = image.images[size_t(level * image.faces + face)];
            out.append(reinterpret_cast<const char*>(data.data()), data.size());
            out.append(padTo4(data.size()) - data.size(), '\0');
        }
    }
    return out;
}

void writeKtx(const fs::path& path, const KtxImage& image) {
    writeFileAtomically(path, [&] { return encodeKtx(image); });
}

KtxImage readKtx(const fs::path& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Error(displayPath(path) + ": no such file");
    return decodeKtx(readTextFile(path), displayPath(path));
}

KtxImage decodeKtx(std::string_view bytes, const std::string& name) {
    const std::string where = name + ": ";
    size_t at = 0;
    auto need = [&](size_t n) {
        if (bytes.size() - at < n) throw Error(where + "truncated KTX file");
    };
    auto get32 = [&]() {
        need(4);
        std::uint32_t v;
        std::memcpy(&v, bytes.data() + at, 4);
        at += 4;
        return v;
    };
    if (bytes.size() < 64 || std::memcmp(bytes.data(), kIdentifier, 12) != 0) {
        throw Error(where + "not a KTX 1 file");
    }
    at = 12;
    if (get32() != kEndianness) throw Error(where + "KTX file of the other byte order");
    const std::uint32_t type = get32(), typeSize = get32(), glFormat = get32(),
                        internalFormat = get32();
    get32();  // base internal format
    // Every field is checked as the unsigned number it is before it becomes an int.
    const std::uint32_t width = get32(), height = get32(), depth = get32(), arrayElements = get32(),
                        faces = get32(), levels = get32(), keyValueBytes = get32();
    KtxImage image;
    bool known = false;
    for (const FormatInfo& f : kFormats) {
        if (f.type == type && f.typeSize == typeSize && f.glFormat == glFormat &&
            f.internalFormat == internalFormat) {
            image.format = f.format;
            known = true;
        }
    }
    if (!known)
        throw Error(where + "unsupported KTX format (want RG16F, RGB16F, RGBA16F or RGBA32F)");
    if (depth > 1 || arrayElements != 0)
        throw Error(where + "3D and array KTX textures are not supported");
    if (width < 1 || height < 1 || width > 65536 || height > 65536) {
        throw Error(where + "bad KTX image size " + std::to_string(width) + " x " +
                    std::to_string(height));
    }
    if (faces != 1 && faces != 6)
        throw Error(where + "faces must be 1 or 6, not " + std::to_string(faces));
    image.width = int(width);
    image.height = int(height);
    image.faces = int(faces);
    if (image.faces == 6 && image.width != image.height)
        throw Error(where + "cube map faces must be square");
    // 0 asks a loader to make the mip chain itself: level 0 is all the file holds.
    const std::uint32_t maxLevels =
        1 + std::uint32_t(std::log2(double(std::max(image.width, image.height))));
    if (levels > maxLevels) {
        throw Error(where + "bad mip level count " + std::to_string(levels) + " (at most " +
                    std::to_string(maxLevels) + " for this size)");
    }
    image.levels = int(std::max(1u, levels));

    need(keyValueBytes);
    const size_t keyValueEnd = at + keyValueBytes;
    while (at < keyValueEnd) {
        // a pair's size field lies inside the block too (reading it past the end wrapped
        // keyValueEnd - at: the fuzz build's unsigned-overflow check found it)
        if (keyValueEnd - at < 4) throw Error(where + "bad KTX key/value data");
        const std::uint32_t size = get32();
        if (size > keyValueEnd - at) throw Error(where + "bad KTX key/value data");
        const std::string pair(bytes.substr(at, size));
        const size_t nul = pair.find('\0');
        if (nul == std::string::npos) throw Error(where + "bad KTX key/value data");
        std::string value = pair.substr(nul + 1);
        while (!value.empty() && value.back() == '\0') value.pop_back();
        image.metadata[pair.substr(0, nul)] = value;
        at += padTo4(size);
    }
    at = keyValueEnd;

    for (int level = 0; level < image.levels; ++level) {
        const std::uint32_t imageSize = get32();
        if (imageSize != image.imageBytes(level)) {
            throw Error(where + "level " + std::to_string(level) +
                        " size does not match its dimensions");
        }
        for (int face = 0; face < image.faces; ++face) {
            need(padTo4(imageSize));
            image.images.emplace_back(bytes.begin() + std::ptrdiff_t(at),
                                      bytes.begin() + std::ptrdiff_t(at + imageSize));
            at += padTo4(imageSize);
        }
    }
    if (at != bytes.size()) throw Error(where + "trailing data after the last KTX level");
    check(image, where);  // what the writer demands, the reader demands too
    return image;
}

std::optional<std::string> ktxShapeError(const KtxImage& image, bool cube) {
    if (!cube) {
        if (image.faces != 1) return "a cube map where a 2D texture was expected";
        return std::nullopt;
    }
    if (image.faces != 6 || image.width != image.height || image.width < 1)
        return "not a cube map of square faces";
    if (image.format == KtxFormat::RG16F) return "a cube map must be RGB or RGBA";
    const int expectedLevels = int(std::floor(std::log2(double(image.width)))) + 1;
    if (image.levels > expectedLevels) return "more mip levels than the size allows";
    return std::nullopt;
}

std::uint16_t floatToHalf(float value) {
    std::uint32_t bits;
    std::memcpy(&bits, &value, 4);
    const std::uint32_t sign = (bits >> 16) & 0x8000u;
    const std::int32_t exponent = std::int32_t((bits >> 23) & 0xff) - 127 + 15;
    std::uint32_t mantissa = bits & 0x7fffffu;
    if (((bits >> 23) & 0xff) == 0xff)
        return std::uint16_t(sign | 0x7c00u | (mantissa ? 0x200u : 0u));  // inf, NaN
    if (exponent >= 31) return std::uint16_t(sign | 0x7c00u);             // overflow
    if (exponent <= 0) {                                                  // subnormal or zero
        if (exponent < -10) return std::uint16_t(sign);
        mantissa |= 0x800000u;
        const int shift = 14 - exponent;
        std::uint32_t half = mantissa >> shift;
        if ((mantissa >> (shift - 1)) & 1u) ++half;  // round half up
        return std::uint16_t(sign | half);
    }
    std::uint32_t half = sign | (std::uint32_t(exponent) << 10) | (mantissa >> 13);
    if (mantissa & 0x1000u) ++half;  // round half up (may carry into the exponent, as it should)
    return std::uint16_t(half);
}

float halfToFloat(std::uint16_t half) {
    const std::uint32_t sign = std::uint32_t(half & 0x8000u) << 16;
    const std::uint32_t exponent = (half >> 10) & 0x1fu, mantissa = half & 0x3ffu;
    std::uint32_t bits;
    if (exponent == 0) {
        if (mantissa == 0) {
            bits = sign;
        } else {  // subnormal: normalise
            int e = -1;
            std::uint32_t m = mantissa;
            do {
                ++e;
                m <<= 1;
            } while (!(m & 0x400u));
            bits = sign | (std::uint32_t(127 - 15 - e) << 23) | ((m & 0x3ffu) << 13);
        }
    } else if (exponent == 31) {
        bits = sign | 0x7f800000u | (mantissa << 13);
    } else {
        bits = sign | ((exponent + 127 - 15) << 23) | (mantissa << 13);
    }
    float value;
    std::memcpy(&value, &bits, 4);
    return value;
}

}  // namespace pbr
