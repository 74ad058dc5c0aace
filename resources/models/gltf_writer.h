#pragma once
// A small glTF 2.0 writer for the project's own asset recipes (make_unlit_showcase,
// make_pbr_showcase): the binary buffer with its buffer views and accessors, mesh primitives
// written from MeshData, and the JSON text around them. Deterministic: the same calls give the
// same bytes.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "gl/mesh.h"

namespace pbr::gltf {

inline constexpr int kArrayBuffer = 34962;         // bufferView.target: vertex attributes
inline constexpr int kElementArrayBuffer = 34963;  // bufferView.target: indices
inline constexpr int kFloat = 5126;
inline constexpr int kUnsignedShort = 5123;

// The shortest text that reads back as the same float ("0.45", "-1", "0.76599997").
std::string number(float value);
// "[a,b,c]" from numbers.
std::string numbers(std::initializer_list<float> values);
// "[item,item]": `separator` between the items (",", or ",\n" for one a line).
std::string array(const std::vector<std::string>& items, const char* separator = ",");
// A whole .gltf file: "{", the members ("\"key\":value") one a line, "}".
std::string document(const std::vector<std::pair<std::string, std::string>>& members);

// "\"text\"" (the text is ours: no escaping needed).
std::string quoted(const std::string& text);
// "[x,y,z]", "[x,y,z,w]", and a rotation as glTF writes it ("[x,y,z,w]").
std::string vec(glm::vec3 v);
std::string vec(glm::vec4 v);
std::string rotation(const glm::quat& q);

// The sphere of the samples' grids (48 x 24), radius `radius`, without the triangles that
// collapse to a point at the poles; POSITION, NORMAL, TEXCOORD_0 only.
MeshData gridSphere(float radius);

// The binary buffer: each addition is one buffer view at a 4-byte aligned offset.
class Buffer {
public:
    // Appends `bytes` as one buffer view with `target`; returns the view's index.
    int addView(const void* data, std::size_t bytes, int target);
    // One accessor on a view; `extra` is JSON appended inside the object (",\"min\":[...]").
    int addAccessor(int view, int componentType, std::size_t count, const char* type,
                    const std::string& extra = "");
    // A view and a float accessor of `type` ("VEC3") over `values`.
    int addFloats(const float* values, std::size_t floats, const char* type,
                  const std::string& extra = "");

    // A triangle-list primitive: the attributes the mesh has (POSITION with min/max, NORMAL,
    // TANGENT, TEXCOORD_0, TEXCOORD_1, COLOR_0, in this order) and its indices as unsigned
    // shorts. Returns the primitive's JSON without its closing brace
    // ("{\"attributes\":{...},\"indices\":N"), so a material can follow.
    std::string addPrimitive(const MeshData& mesh);

    // The buffer's bytes, padded to a multiple of 4.
    std::string bytes() const;
    // The members "buffers" (one, at `uri`), "bufferViews" and "accessors".
    std::vector<std::pair<std::string, std::string>> members(const std::string& uri) const;

private:
    std::string bytes_;
    std::vector<std::string> views_, accessors_;
};

}  // namespace pbr::gltf
