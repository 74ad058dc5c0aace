#include "support/gltf_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "files/image.h"

namespace pbr::test {

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

namespace {

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
    for (const auto& c : corners)                                            // 96: 32 bytes
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

// ---- Arbitrary meshes and JSON written back (the scene-graph tests) ----

namespace pbr::test {

namespace {

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

}  // namespace

std::string meshBuffersJson(const std::vector<GltfMeshArrays>& meshes) {
    std::vector<std::uint8_t> bytes;
    std::string views, accessors;
    int viewCount = 0;
    auto view = [&](size_t offset, size_t length, int target) {
        if (viewCount > 0) views += ",\n  ";
        views += R"({"buffer":0,"byteOffset":)" + std::to_string(offset) + R"(,"byteLength":)" +
                 std::to_string(length) + R"(,"target":)" + std::to_string(target) + "}";
        return viewCount++;
    };
    auto accessor = [&](int bufferView, int componentType, size_t count, const char* type,
                        const std::string& extra) {
        if (!accessors.empty()) accessors += ",\n  ";
        accessors += R"({"bufferView":)" + std::to_string(bufferView) + R"(,"componentType":)" +
                     std::to_string(componentType) + R"(,"count":)" + std::to_string(count) +
                     R"(,"type":")" + type + "\"" + extra + "}";
    };
    for (const GltfMeshArrays& mesh : meshes) {
        const size_t n = mesh.positions.size();
        if (mesh.normals.size() != n || mesh.uvs.size() != n || mesh.tangents.size() != n)
            throw std::runtime_error("meshBuffersJson: attribute counts differ");
        glm::vec3 low(INFINITY), high(-INFINITY);
        size_t start = bytes.size();
        for (const glm::vec3& p : mesh.positions) {
            append<float>(bytes, {p.x, p.y, p.z});
            low = glm::min(low, p);
            high = glm::max(high, p);
        }
        accessor(view(start, bytes.size() - start, 34962), 5126, n, "VEC3",
                 R"(,"min":[)" + number(low.x) + "," + number(low.y) + "," + number(low.z) +
                     R"(],"max":[)" + number(high.x) + "," + number(high.y) + "," + number(high.z) +
                     "]");
        start = bytes.size();
        for (const glm::vec3& v : mesh.normals) append<float>(bytes, {v.x, v.y, v.z});
        accessor(view(start, bytes.size() - start, 34962), 5126, n, "VEC3", "");
        start = bytes.size();
        for (const glm::vec2& v : mesh.uvs) append<float>(bytes, {v.x, v.y});
        accessor(view(start, bytes.size() - start, 34962), 5126, n, "VEC2", "");
        start = bytes.size();
        for (const glm::vec4& v : mesh.tangents) append<float>(bytes, {v.x, v.y, v.z, v.w});
        accessor(view(start, bytes.size() - start, 34962), 5126, n, "VEC4", "");
        start = bytes.size();
        for (std::uint32_t i : mesh.indices) append<std::uint32_t>(bytes, {i});
        accessor(view(start, bytes.size() - start, 34963), 5125, mesh.indices.size(), "SCALAR", "");
    }
    return R"("buffers":[{"byteLength":)" + std::to_string(bytes.size()) +
           R"(,"uri":"data:application/octet-stream;base64,)" + base64(bytes) +
           "\"}],\n\"bufferViews\":[" + views + "],\n\"accessors\":[" + accessors + "],\n";
}

std::string meshPrimitiveJson(int mesh, int material) {
    const int a = 5 * mesh;
    return R"({"attributes":{"POSITION":)" + std::to_string(a) + R"(,"NORMAL":)" +
           std::to_string(a + 1) + R"(,"TEXCOORD_0":)" + std::to_string(a + 2) + R"(,"TANGENT":)" +
           std::to_string(a + 3) + R"(},"indices":)" + std::to_string(a + 4) + R"(,"material":)" +
           std::to_string(material) + "}";
}

std::string matrixJson(const glm::dmat4& matrix) {
    std::string out = "[";
    for (int column = 0; column < 4; ++column) {
        for (int row = 0; row < 4; ++row)
            out += number(matrix[column][row]) + (column == 3 && row == 3 ? "]" : ",");
    }
    return out;
}

std::string jsonText(const JsonValue& value) {
    auto quoted = [](const std::string& text) {
        std::string out = "\"";
        for (const char c : text) {
            if (c == '"' || c == '\\') {
                out += '\\';
                out += c;
            } else if (static_cast<unsigned char>(c) < 0x20) {
                char escape[8];
                std::snprintf(escape, sizeof escape, "\\u%04x", unsigned(c));
                out += escape;
            } else {
                out += c;
            }
        }
        return out + "\"";
    };
    switch (value.type) {
        case JsonValue::Type::Null:
            return "null";
        case JsonValue::Type::Bool:
            return value.boolean ? "true" : "false";
        case JsonValue::Type::Number:
            return number(value.number);
        case JsonValue::Type::String:
            return quoted(value.text);
        case JsonValue::Type::Array: {
            std::string out = "[";
            for (size_t i = 0; i < value.items.size(); ++i)
                out += (i ? "," : "") + jsonText(value.items[i]);
            return out + "]";
        }
        case JsonValue::Type::Object: {
            std::string out = "{";
            for (size_t i = 0; i < value.members.size(); ++i) {
                out += (i ? "," : "") + quoted(value.members[i].first) + ":" +
                       jsonText(value.members[i].second);
            }
            return out + "}";
        }
    }
    return "null";
}

std::filesystem::path writeMaterialExtensionsFile(const std::filesystem::path& dir) {
    writePng(dir / "a.png", pbr::Image{1, 1, 4, {10, 20, 30, 40}});
    const std::string png = encodePng(pbr::Image{1, 1, 4, {50, 60, 70, 80}});
    const std::string inside =
        "data:image/png;base64," + base64(std::vector<std::uint8_t>(png.begin(), png.end()));
    return writeTextFile(dir, "extensions.gltf",
                         R"({"asset":{"version":"2.0"},
"extensionsUsed":["KHR_materials_clearcoat","KHR_materials_sheen","KHR_materials_transmission",
  "KHR_materials_volume","KHR_materials_ior","KHR_materials_specular",
  "KHR_materials_emissive_strength","KHR_texture_transform"],
)" + squareBuffersJson(1.0f) +
                             R"(
"images":[{"uri":"a.png"},{"uri":")" +
                             inside + R"("}],
"samplers":[{"wrapS":33071,"wrapT":33648,"magFilter":9728,"minFilter":9984}],
"textures":[{"source":0},{"source":1,"sampler":0}],
"materials":[{"name":"layers","emissiveFactor":[1,0.5,0.25],
  "extensions":{
    "KHR_materials_clearcoat":{"clearcoatFactor":0.7,"clearcoatTexture":{"index":0},
      "clearcoatRoughnessFactor":0.3,"clearcoatRoughnessTexture":{"index":1,"texCoord":1},
      "clearcoatNormalTexture":{"index":0,"scale":0.6}},
    "KHR_materials_sheen":{"sheenColorFactor":[0.1,0.2,0.3],"sheenColorTexture":{"index":1},
      "sheenRoughnessFactor":0.4,"sheenRoughnessTexture":{"index":0}},
    "KHR_materials_transmission":{"transmissionFactor":0.8,"transmissionTexture":{"index":0}},
    "KHR_materials_volume":{"thicknessFactor":0.5,"thicknessTexture":{"index":1},
      "attenuationDistance":2.5,"attenuationColor":[0.9,0.8,0.7]},
    "KHR_materials_ior":{"ior":1.7},
    "KHR_materials_specular":{"specularFactor":0.6,"specularTexture":{"index":0,"texCoord":1},
      "specularColorFactor":[0.5,0.6,0.7],"specularColorTexture":{"index":1,"extensions":{
        "KHR_texture_transform":{"offset":[0.25,0.5],"scale":[2,4]}}}},
    "KHR_materials_emissive_strength":{"emissiveStrength":5}}},
  {"name":"plain"}],
"meshes":[{"primitives":[)" + squarePrimitiveJson(0) +
                             "," + squarePrimitiveJson(1) + R"(]}],
"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})");
}

}  // namespace pbr::test

// ---- Additions for tests/khronos (see gltf_scene.h) ---------------------------------------------
#include <algorithm>
#include <limits>

namespace pbr::test {

namespace {

int componentsOf(const std::string& type) {
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4") return 4;
    throw std::invalid_argument("accessor type " + type);
}

std::string numberList(const std::vector<float>& values) {
    std::string out;
    for (float v : values) {
        if (!out.empty()) out += ',';  // not "," + std::to_string(v): GCC 12 warns falsely
        out += std::to_string(v);
    }
    return out;
}

}  // namespace

int GltfBufferBuilder::floats(const std::vector<float>& values, const std::string& type,
                              bool bounds) {
    const int components = componentsOf(type);
    const size_t offset = bytes_.size();
    for (float v : values) append<float>(bytes_, {v});
    std::string extra;
    if (bounds) {
        std::vector<float> lo(components, std::numeric_limits<float>::max());
        std::vector<float> hi(components, std::numeric_limits<float>::lowest());
        for (size_t i = 0; i < values.size(); ++i) {
            lo[i % components] = std::min(lo[i % components], values[i]);
            hi[i % components] = std::max(hi[i % components], values[i]);
        }
        extra = R"(,"min":[)" + numberList(lo) + R"(],"max":[)" + numberList(hi) + "]";
    }
    views_ += (views_.empty() ? "" : ",\n  ") + std::string(R"({"buffer":0,"byteOffset":)") +
              std::to_string(offset) + R"(,"byteLength":)" + std::to_string(4 * values.size()) +
              R"(,"target":34962})";
    accessors_ += (accessors_.empty() ? "" : ",\n  ") + std::string(R"({"bufferView":)") +
                  std::to_string(count_) + R"(,"componentType":5126,"count":)" +
                  std::to_string(values.size() / size_t(components)) + R"(,"type":")" + type +
                  "\"" + extra + "}";
    return count_++;
}

int GltfBufferBuilder::indices(const std::vector<std::uint16_t>& values) {
    const size_t offset = bytes_.size();
    for (std::uint16_t v : values) append<std::uint16_t>(bytes_, {v});
    while (bytes_.size() % 4 != 0) bytes_.push_back(0);  // the next float view stays aligned
    views_ += (views_.empty() ? "" : ",\n  ") + std::string(R"({"buffer":0,"byteOffset":)") +
              std::to_string(offset) + R"(,"byteLength":)" + std::to_string(2 * values.size()) +
              R"(,"target":34963})";
    accessors_ += (accessors_.empty() ? "" : ",\n  ") + std::string(R"({"bufferView":)") +
                  std::to_string(count_) + R"(,"componentType":5123,"count":)" +
                  std::to_string(values.size()) + R"(,"type":"SCALAR"})";
    return count_++;
}

std::string GltfBufferBuilder::json() const {
    return R"("buffers":[{"byteLength":)" + std::to_string(bytes_.size()) +
           R"(,"uri":"data:application/octet-stream;base64,)" + base64(bytes_) +
           "\"}],\n\"bufferViews\":[" + views_ + "],\n\"accessors\":[" + accessors_ + "],\n";
}

}  // namespace pbr::test
