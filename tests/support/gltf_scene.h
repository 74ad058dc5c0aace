#pragma once
// Small glTF files written by tests, described in JSON by the test itself (so every expected
// value is read off the test's own text): one square in the XY plane from -h to h facing +Z,
// counter-clockwise seen from +Z, with TEXCOORD_0 = ((x + h) / 2h, (h - y) / 2h) (the image
// upright, as seen from +Z) and TEXCOORD_1 = TEXCOORD_0 / 2. Its buffer is embedded as a data URI.
// Two more accessors for primitives that ask for them: the uvs mirrored in u ((h - x) / 2h,
// (h - y) / 2h) and a TANGENT (0, -1, 0, -1) at every corner.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "files/gltf_file.h"

namespace pbr::test {

// The "buffers", "bufferViews" and "accessors" members (with a trailing comma) for the square:
// accessors 0 POSITION, 1 NORMAL, 2 TEXCOORD_0, 3 TEXCOORD_1, 4 the six indices, 5 the mirrored
// uvs, 6 the tangents.
std::string squareBuffersJson(float halfSize);

// The attributes object of a primitive drawing the square: {"POSITION":0,...}, "indices":4.
std::string squarePrimitiveJson(int material);

// Writes dir/extensions.gltf (with dir/a.png): the square twice, material "layers" using every
// extension sample 10 draws (clearcoat, sheen, transmission, volume, ior, specular, emissive
// strength) with a texture in each slot, half of them an image inside the file (a data: URI),
// and material "plain" using none. Returns its path.
std::filesystem::path writeMaterialExtensionsFile(const std::filesystem::path& dir);

// The bytes in base64 (RFC 4648, padded), as a data: URI holds them.
std::string base64(const std::vector<std::uint8_t>& bytes);

// Writes `json` to dir/name and returns the path.
std::filesystem::path writeTextFile(const std::filesystem::path& dir, const std::string& name,
                                    const std::string& json);

// ---- Arbitrary meshes and JSON written back (the scene-graph tests,
// tests/reference/scene_graph_test.cpp) ----

// One triangle mesh as plain arrays: every vertex has a position, a normal, a TEXCOORD_0 and a
// TANGENT (xyz along +u, w the handedness, as glTF has it).
struct GltfMeshArrays {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<glm::vec4> tangents;
    std::vector<std::uint32_t> indices;
};

// The "buffers", "bufferViews" and "accessors" members (with a trailing comma) for `meshes` in one
// embedded buffer: mesh i has accessors 5i POSITION (with min and max), 5i + 1 NORMAL, 5i + 2
// TEXCOORD_0, 5i + 3 TANGENT, 5i + 4 its indices (unsigned int).
std::string meshBuffersJson(const std::vector<GltfMeshArrays>& meshes);

// A primitive drawing mesh i of meshBuffersJson with `material`.
std::string meshPrimitiveJson(int mesh, int material);

// A glTF matrix, column-major, as the JSON array a node's "matrix" holds (17 significant digits).
std::string matrixJson(const glm::dmat4& matrix);

// A parsed JSON value written back as JSON text (numbers with 17 significant digits, so a
// document read with parseJson and written back holds the same values).
std::string jsonText(const JsonValue& value);

}  // namespace pbr::test

// ---- Additions for tests/khronos (the Khronos glTF Sample Viewer as a reference) --------------
// A glTF file's binary data built up accessor by accessor, each in a bufferView of its own, the
// buffer embedded as a data URI (as squareBuffersJson's), for meshes a test shapes itself.
#include <cstdint>
#include <vector>

namespace pbr::test {

class GltfBufferBuilder {
public:
    // A float accessor of `type` ("SCALAR", "VEC2", "VEC3", "VEC4"); a POSITION accessor needs
    // `bounds` (min and max). Returns its index.
    int floats(const std::vector<float>& values, const std::string& type, bool bounds = false);
    // An unsigned-short index accessor; returns its index.
    int indices(const std::vector<std::uint16_t>& values);
    // The "buffers", "bufferViews" and "accessors" members, with a trailing comma.
    std::string json() const;

private:
    std::vector<std::uint8_t> bytes_;
    std::string views_, accessors_;
    int count_ = 0;
};

}  // namespace pbr::test
