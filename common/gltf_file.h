#pragma once
// Checks of a glTF file's container before Assimp reads it: Assimp answers a truncated .gltf with
// "No suitable reader found", because its format sniffing fails on broken JSON. These say what is
// wrong instead: the JSON ends early, or is invalid at a line and column; a .glb's header or
// chunks do not add up. Pure: no GL, no Assimp.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pbr {

// Why `text` is not one well-formed JSON value (RFC 8259), or nullopt when it is:
//   "truncated: the JSON ends inside an object"
//   "invalid JSON at line 3, column 14: expected ',' or '}'"
std::optional<std::string> jsonSyntaxError(std::string_view text);

// Why the bytes of a glTF file (.gltf text or .glb binary, told apart by the GLB magic) cannot be
// a glTF asset, or nullopt when the container is sound (the contents are Assimp's to judge).
std::optional<std::string> gltfContainerError(std::string_view bytes);

// The names in a glTF file's top-level "extensionsUsed" and "extensionsRequired" lists (empty
// when absent, or when the container is not sound).
struct GltfExtensions {
    std::vector<std::string> used, required;
};
GltfExtensions gltfExtensions(std::string_view bytes);

}  // namespace pbr
