#include "support/png16.h"

#include <array>
#include <fstream>
#include <stdexcept>
#include <string>

namespace pbr::test {

namespace {

std::uint32_t crc32(const std::string& bytes) {
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
            t[n] = c;
        }
        return t;
    }();
    std::uint32_t c = 0xffffffffu;
    for (unsigned char byte : bytes) c = table[(c ^ byte) & 0xff] ^ (c >> 8);
    return c ^ 0xffffffffu;
}

void put32(std::string& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out += char((v >> shift) & 0xff);
}

void chunk(std::string& out, const char* type, const std::string& data) {
    put32(out, std::uint32_t(data.size()));
    const std::string body = std::string(type, 4) + data;
    out += body;
    put32(out, crc32(body));
}

}  // namespace

void writePng16(const std::filesystem::path& path, int width, int height, int channels,
                const std::vector<std::uint16_t>& samples) {
    if (channels != 1 && channels != 3) throw std::invalid_argument("writePng16: 1 or 3 channels");
    std::string raw;  // filter byte 0, then the row's big-endian samples
    for (int y = 0; y < height; ++y) {
        raw += '\0';
        for (int i = 0; i < width * channels; ++i) {
            const std::uint16_t v = samples[size_t(y) * size_t(width * channels) + size_t(i)];
            raw += char(v >> 8);
            raw += char(v & 0xff);
        }
    }
    std::string zlib = "\x78\x01";  // deflate, no compression
    std::uint32_t a = 1, b = 0;
    for (unsigned char byte : raw) {
        a = (a + byte) % 65521;
        b = (b + a) % 65521;
    }
    for (size_t at = 0; at < raw.size(); at += 65535) {
        const size_t length = std::min<size_t>(65535, raw.size() - at);
        zlib += char(at + length == raw.size() ? 1 : 0);
        zlib += char(length & 0xff);
        zlib += char(length >> 8);
        zlib += char(~length & 0xff);
        zlib += char((~length >> 8) & 0xff);
        zlib += raw.substr(at, length);
    }
    put32(zlib, (b << 16) | a);

    std::string png = "\x89PNG\r\n\x1a\n";
    std::string header;
    put32(header, std::uint32_t(width));
    put32(header, std::uint32_t(height));
    header += char(16);                     // bit depth
    header += char(channels == 1 ? 0 : 2);  // grey or RGB
    header += std::string(3, '\0');         // deflate, adaptive filtering, no interlace
    chunk(png, "IHDR", header);
    chunk(png, "IDAT", zlib);
    chunk(png, "IEND", "");
    std::ofstream(path, std::ios::binary) << png;
}

}  // namespace pbr::test
