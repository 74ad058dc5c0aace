#include "gltf_writer.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <limits>

#include "base/error.h"

namespace pbr::gltf {

std::string number(float value) {
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value + 0.0f);  // no "-0"
    return std::string(text, result.ptr);
}

std::string numbers(std::initializer_list<float> values) {
    std::vector<std::string> items;
    for (float v : values) items.push_back(number(v));
    return array(items);
}

std::string array(const std::vector<std::string>& items, const char* separator) {
    std::string out = "[";
    for (std::size_t i = 0; i < items.size(); ++i) out += (i ? separator : "") + items[i];
    return out + "]";
}

std::string document(const std::vector<std::pair<std::string, std::string>>& members) {
    std::string out = "{\n";
    for (std::size_t i = 0; i < members.size(); ++i) {
        out += (i ? ",\n\"" : "\"") + members[i].first + "\":" + members[i].second;
    }
    return out + "\n}\n";
}

int Buffer::addView(const void* data, std::size_t bytes, int target) {
    while (bytes_.size() % 4) bytes_ += '\0';
    views_.push_back("{\"buffer\":0,\"byteOffset\":" + std::to_string(bytes_.size()) +
                     ",\"byteLength\":" + std::to_string(bytes) +
                     ",\"target\":" + std::to_string(target) + "}");
    bytes_.append(static_cast<const char*>(data), bytes);
    return int(views_.size()) - 1;
}

int Buffer::addAccessor(int view, int componentType, std::size_t count, const char* type,
                        const std::string& extra) {
    accessors_.push_back("{\"bufferView\":" + std::to_string(view) + ",\"componentType\":" +
                         std::to_string(componentType) + ",\"count\":" + std::to_string(count) +
                         ",\"type\":\"" + type + "\"" + extra + "}");
    return int(accessors_.size()) - 1;
}

int Buffer::addFloats(const float* values, std::size_t floats, const char* type,
                      const std::string& extra) {
    const std::size_t components = std::string(type) == "SCALAR" ? 1 : std::size_t(type[3] - '0');
    return addAccessor(addView(values, floats * sizeof(float), kArrayBuffer), kFloat,
                       floats / components, type, extra);
}

std::string Buffer::addPrimitive(const MeshData& mesh) {
    const std::size_t n = mesh.positions.size();
    auto sized = [&](std::size_t count, const char* what) {
        if (count != 0 && count != n) {
            throw Error(std::string("glTF writer: ") + what + " count differs from positions'");
        }
        return count == n && n != 0;
    };
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const std::string bounds =
        ",\"min\":" + numbers({lo.x, lo.y, lo.z}) + ",\"max\":" + numbers({hi.x, hi.y, hi.z});
    std::string attributes =
        "\"POSITION\":" + std::to_string(addFloats(&mesh.positions[0].x, 3 * n, "VEC3", bounds));
    if (sized(mesh.normals.size(), "normal")) {
        attributes += ",\"NORMAL\":" + std::to_string(addFloats(&mesh.normals[0].x, 3 * n, "VEC3"));
    }
    if (sized(mesh.tangents.size(), "tangent")) {
        attributes +=
            ",\"TANGENT\":" + std::to_string(addFloats(&mesh.tangents[0].x, 4 * n, "VEC4"));
    }
    if (sized(mesh.uvs.size(), "uv")) {
        attributes += ",\"TEXCOORD_0\":" + std::to_string(addFloats(&mesh.uvs[0].x, 2 * n, "VEC2"));
    }
    if (sized(mesh.uvs1.size(), "second uv")) {
        attributes +=
            ",\"TEXCOORD_1\":" + std::to_string(addFloats(&mesh.uvs1[0].x, 2 * n, "VEC2"));
    }
    if (sized(mesh.colors.size(), "colour")) {
        attributes += ",\"COLOR_0\":" + std::to_string(addFloats(&mesh.colors[0].x, 4 * n, "VEC4"));
    }
    std::vector<std::uint16_t> indices;
    for (std::uint32_t i : mesh.indices) {
        if (i >= n || n > 65536) throw Error("glTF writer: an index does not fit");
        indices.push_back(std::uint16_t(i));
    }
    const int view = addView(indices.data(), indices.size() * 2, kElementArrayBuffer);
    const int accessor = addAccessor(view, kUnsignedShort, indices.size(), "SCALAR");
    return "{\"attributes\":{" + attributes + "},\"indices\":" + std::to_string(accessor);
}

std::string Buffer::bytes() const {
    std::string out = bytes_;
    while (out.size() % 4) out += '\0';
    return out;
}

std::vector<std::pair<std::string, std::string>> Buffer::members(const std::string& uri) const {
    return {{"buffers",
             "[{\"uri\":\"" + uri + "\",\"byteLength\":" + std::to_string(bytes().size()) + "}]"},
            {"bufferViews", array(views_)},
            {"accessors", array(accessors_)}};
}

std::string quoted(const std::string& text) {
    return "\"" + text + "\"";
}
std::string vec(glm::vec3 v) {
    return numbers({v.x, v.y, v.z});
}
std::string vec(glm::vec4 v) {
    return numbers({v.x, v.y, v.z, v.w});
}
std::string rotation(const glm::quat& q) {
    return numbers({q.x, q.y, q.z, q.w});
}

MeshData gridSphere(float radius) {
    MeshData mesh = uvSphereTriangles(48, 24);
    mesh.tangents.clear();
    for (glm::vec3& p : mesh.positions) p *= radius;
    std::vector<std::uint32_t> kept;
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        const glm::vec3 &a = mesh.positions[mesh.indices[i]],
                        &b = mesh.positions[mesh.indices[i + 1]],
                        &c = mesh.positions[mesh.indices[i + 2]];
        if (glm::length(glm::cross(b - a, c - a)) > 1e-9f)
            kept.insert(kept.end(), mesh.indices.begin() + long(i),
                        mesh.indices.begin() + long(i) + 3);
    }
    mesh.indices = kept;
    return mesh;
}

}  // namespace pbr::gltf
