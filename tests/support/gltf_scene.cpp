#include "support/gltf_scene.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace pbr::test {

namespace {

std::string base64(const std::vector<std::uint8_t>& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t n = std::uint32_t(bytes[i]) << 16 |
                                (i + 1 < bytes.size() ? std::uint32_t(bytes[i + 1]) << 8 : 0) |
                                (i + 2 < bytes.size() ? std::uint32_t(bytes[i + 2]) : 0);
        out += digits[n >> 18 & 63];
        out += digits[n >> 12 & 63];
        out += i + 1 < bytes.size() ? digits[n >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? digits[n & 63] : '=';
    }
    return out;
}

template <class T>
void append(std::vector<std::uint8_t>& bytes, std::initializer_list<T> values) {
    for (T value : values) {
        std::uint8_t raw[sizeof(T)];
        std::memcpy(raw, &value, sizeof(T));
        bytes.insert(bytes.end(), raw, raw + sizeof(T));
    }
}

}  // namespace

std::string squareBuffersJson(float h) {
    std::vector<std::uint8_t> bytes;
    const float corners[4][2] = {{-h, -h}, {h, -h}, {h, h}, {-h, h}};
    for (const auto& c : corners) append<float>(bytes, {c[0], c[1], 0.0f});  // 0: 48 bytes
    for (int i = 0; i < 4; ++i) append<float>(bytes, {0.0f, 0.0f, 1.0f});    // 48: 48 bytes
    for (const auto& c : corners)                                           // 96: 32 bytes
        append<float>(bytes, {(c[0] + h) / (2 * h), (h - c[1]) / (2 * h)});
    for (const auto& c : corners)  // 128: 32 bytes
        append<float>(bytes, {0.5f * (c[0] + h) / (2 * h), 0.5f * (h - c[1]) / (2 * h)});
    append<std::uint16_t>(bytes, {0, 1, 2, 0, 2, 3});  // 160: 12 bytes
    for (const auto& c : corners)                      // 172: 32 bytes, u mirrored
        append<float>(bytes, {(h - c[0]) / (2 * h), (h - c[1]) / (2 * h)});
    for (int i = 0; i < 4; ++i) append<float>(bytes, {0.0f, -1.0f, 0.0f, -1.0f});  // 204: 64
    const std::string hs = std::to_string(h);
    return R"("buffers":[{"byteLength":)" + std::to_string(bytes.size()) +
           R"(,"uri":"data:application/octet-stream;base64,)" + base64(bytes) + R"("}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":160,"target":34962},
  {"buffer":0,"byteOffset":160,"byteLength":12,"target":34963},
  {"buffer":0,"byteOffset":172,"byteLength":96,"target":34962}],
"accessors":[
  {"bufferView":0,"byteOffset":0,"componentType":5126,"count":4,"type":"VEC3","min":[-)" +
           hs + ",-" + hs + R"(,0],"max":[)" + hs + "," + hs + R"(,0]},
  {"bufferView":0,"byteOffset":48,"componentType":5126,"count":4,"type":"VEC3"},
  {"bufferView":0,"byteOffset":96,"componentType":5126,"count":4,"type":"VEC2"},
  {"bufferView":0,"byteOffset":128,"componentType":5126,"count":4,"type":"VEC2"},
  {"bufferView":1,"byteOffset":0,"componentType":5123,"count":6,"type":"SCALAR"},
  {"bufferView":2,"byteOffset":0,"componentType":5126,"count":4,"type":"VEC2"},
  {"bufferView":2,"byteOffset":32,"componentType":5126,"count":4,"type":"VEC4"}],
)";
}

std::string squarePrimitiveJson(int material) {
    return R"({"attributes":{"POSITION":0,"NORMAL":1,"TEXCOORD_0":2,"TEXCOORD_1":3},"indices":4,"material":)" +
           std::to_string(material) + "}";
}

std::filesystem::path writeTextFile(const std::filesystem::path& dir, const std::string& name,
                                    const std::string& json) {
    const std::filesystem::path path = dir / name;
    std::ofstream out(path, std::ios::binary);
    out << json;
    if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
    return path;
}

}  // namespace pbr::test
