#pragma once
// Small glTF files written by tests, described in JSON by the test itself (so every expected
// value is read off the test's own text): one square in the XY plane from -h to h facing +Z,
// counter-clockwise seen from +Z, with TEXCOORD_0 = ((x + h) / 2h, (h - y) / 2h) (the image
// upright, as seen from +Z) and TEXCOORD_1 = TEXCOORD_0 / 2. Its buffer is embedded as a data URI.
// Two more accessors for primitives that ask for them: the uvs mirrored in u ((h - x) / 2h,
// (h - y) / 2h) and a TANGENT (0, -1, 0, -1) at every corner.
#include <filesystem>
#include <string>

namespace pbr::test {

// The "buffers", "bufferViews" and "accessors" members (with a trailing comma) for the square:
// accessors 0 POSITION, 1 NORMAL, 2 TEXCOORD_0, 3 TEXCOORD_1, 4 the six indices, 5 the mirrored
// uvs, 6 the tangents.
std::string squareBuffersJson(float halfSize);

// The attributes object of a primitive drawing the square: {"POSITION":0,...}, "indices":4.
std::string squarePrimitiveJson(int material);

// Writes `json` to dir/name and returns the path.
std::filesystem::path writeTextFile(const std::filesystem::path& dir, const std::string& name,
                                    const std::string& json);

}  // namespace pbr::test
