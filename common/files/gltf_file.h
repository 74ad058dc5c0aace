#pragma once
// Checks of a glTF file's container before Assimp reads it: Assimp answers a truncated .gltf with
// "No suitable reader found", because its format sniffing fails on broken JSON. These say what is
// wrong instead: the JSON ends early, or is invalid at a line and column; a .glb's header or
// chunks do not add up. Then the parts the JSON describes, where Assimp 5.2 would crash on them
// (gltfStructureError). Pure: no GL, no Assimp.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace pbr {

// Why `text` is not one well-formed JSON value (RFC 8259), or nullopt when it is:
//   "truncated: the JSON ends inside an object"
//   "invalid JSON at line 3, column 14: expected ',' or '}'"
std::optional<std::string> jsonSyntaxError(std::string_view text);

// Why the bytes of a glTF file (.gltf text or .glb binary, told apart by the GLB magic) cannot be
// a glTF asset, or nullopt when the container is sound (the contents are Assimp's to judge).
std::optional<std::string> gltfContainerError(std::string_view bytes);

// A JSON value, as parsed: what the glTF loader reads itself where Assimp does not.
struct JsonValue {
    // Declared, so that clang (with libstdc++) does not need std::pair<std::string, JsonValue>
    // whole while it checks whether JsonValue is default-constructible inside its own definition.
    JsonValue() = default;
    enum class Type { Null, Bool, Number, String, Array, Object };
    Type type = Type::Null;
    bool boolean = false;
    double number = 0.0;
    std::string text;                                        // a string's, unescaped
    std::vector<JsonValue> items;                            // an array's
    std::vector<std::pair<std::string, JsonValue>> members;  // an object's, in the file's order
    // An object's member of that name (the first, as Assimp's reader takes it), or nullptr.
    const JsonValue* find(std::string_view key) const;
};

// A glTF index a member holds (a whole number, 0 to 1e9), or -1 when it is absent or not one.
int jsonIndex(const JsonValue* value);
// Item `index` of the document's top-level list `list` ("textures", "images"...), or nullptr.
const JsonValue* jsonItem(const JsonValue& document, std::string_view list, int index);

// The value `text` holds, or nullopt when it is not well-formed JSON.
std::optional<JsonValue> parseJson(std::string_view text);
// The JSON of a glTF file (.gltf text, or a .glb's JSON chunk), or nullopt when unsound.
std::optional<JsonValue> gltfJson(std::string_view bytes);

// The indices of the file's materials in the order Assimp 5.2 lists them in aiScene: it reads a
// material when a primitive first names it, walking the default scene's nodes depth first, a
// node's children before its own mesh (its glTF dictionaries fill as they are read). Materials
// no primitive of that scene names are not imported; Assimp appends a default one after these.
std::vector<int> assimpMaterialOrder(const JsonValue& document);

// The bytes of a .glb's BIN chunk (empty when it has none), or nullopt when `bytes` is not a
// sound glTF 2.0 binary container; glbBinLength, their number.
std::optional<std::string_view> glbBin(std::string_view bytes);
std::optional<std::uint64_t> glbBinLength(std::string_view bytes);

// The bytes of a buffer that the JSON does not hold itself, buffer `index` of the file, its `uri`
// ("" when it has none): a .glb's buffer 0 (the BIN chunk), or a file beside the .gltf; nullopt
// when the caller cannot give them.
using GltfBufferBytes =
    std::function<std::optional<std::string>(std::size_t index, std::string_view uri)>;

// Why a glTF file's JSON cannot be handed to Assimp 5.2, or nullopt when its parts fit together.
// Assimp crashes, where it should refuse, on files that break some of glTF 2.0's rules; these
// are refused first, each in one line naming the part and what is wrong with it:
//   - a file that is not glTF 2.0 ("glTF 1.0 is not read: the samples take glTF 2.0");
//   - buffers, buffer views and accessors (sparse ones too) whose bytes do not lie inside what
//     they read from ("accessor 3 reads bytes 0-1024 of bufferView 1, which has 512"), misaligned
//     ones, unknown component types or types, references to parts the file does not have;
//   - base64 buffers that are not base64, or whose bytes differ from their byteLength;
//   - skinned meshes without JOINTS_0 and WEIGHTS_0 (or with unpaired or uneven sets), skins
//     without enough MAT4 float inverseBindMatrices (Assimp 5.2 needs them: glTF does not);
//   - line loops and strips of fewer than 2 vertices, triangle strips and fans of fewer than 3;
//   - indexed line loops whose first line names a vertex the primitive does not have (or that
//     have no POSITION): Assimp drops that line and then closes the loop with its first index,
//     read through a null pointer. The indices are read where their bytes can be had: a data
//     URI's, and what `bufferBytes` gives (a .glb's BIN chunk, a file beside the .gltf).
// Only what Assimp reads is checked: a broken part nothing names (a view no accessor uses) passes,
// as the file loads today.
// `glbBinLength` is the BIN chunk's length for a .glb (Assimp reads buffer 0 from it), nullopt
// for a .gltf, whose buffers are as long as their byteLength says (Assimp checks that).
std::optional<std::string> gltfStructureError(const JsonValue& document,
                                              std::optional<std::uint64_t> glbBinLength,
                                              const GltfBufferBytes& bufferBytes = {});

// KHR_texture_transform's `texCoord` of a textureInfo object (it overrides the textureInfo's
// own; Assimp 5.2 ignores it), or nullopt when the transform does not set one.
std::optional<int> texCoordOverride(const JsonValue& textureInfo);

// The names in a glTF file's top-level "extensionsUsed" and "extensionsRequired" lists (empty
// when absent, or when the container is not sound).
struct GltfExtensions {
    std::vector<std::string> used, required;
};
GltfExtensions gltfExtensions(std::string_view bytes);

}  // namespace pbr
