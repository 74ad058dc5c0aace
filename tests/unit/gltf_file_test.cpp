// The checks of a glTF file before Assimp reads it (common/files/gltf_file.h): well-formed JSON
// is accepted, each kind of damage is named with where it is; a glTF 2.0 file whose parts fit
// together passes the structure check, and each part that would crash Assimp 5.2 is named.
#include <gtest/gtest.h>

#include "support/test_data.h"

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string_view>

#include "files/gltf_file.h"

namespace pbr {
namespace {

std::string fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

TEST(GltfFile, WellFormedJsonPasses) {
    PBR_NEED_ASSIMP_MODELS(kGltf);
    for (const char* text : {"{}", " [1, -2.5e+3, 0.25, true, false, null, \"a\\u00e9\\n\"] ",
                             "{\"a\":{\"b\":[[]]}}", "\xEF\xBB\xBF{}", "0", "\"text\""}) {
        EXPECT_FALSE(jsonSyntaxError(text)) << text << ": " << *jsonSyntaxError(text);
    }
    const std::string box = fileBytes((kGltf / "BoxTextured-glTF/BoxTextured.gltf").string());
    ASSERT_FALSE(box.empty());
    EXPECT_FALSE(gltfContainerError(box));
    const std::string glb = fileBytes((kGltf / "BoxTextured-glTF-Binary/BoxTextured.glb").string());
    ASSERT_FALSE(glb.empty());
    EXPECT_FALSE(gltfContainerError(glb));
}

TEST(GltfFile, DamageIsNamedWithItsPlace) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"{\"asset\": {\"version\": \"2.0\"", "truncated: the JSON ends inside an object"},
        {"{\"a\": [1, 2", "truncated: the JSON ends inside an array"},
        {"{\"a\": \"unfinished", "truncated: the JSON ends inside a string"},
        {"", "truncated: the JSON ends inside a value"},
        {"{\"a\" 1}", "invalid JSON at line 1, column 6: expected ':'"},
        {"{\n  \"a\": 1,\n  \"b\": 2\n  \"c\": 3}",
         "invalid JSON at line 4, column 3: expected ',' or '}'"},
        {"[1, 2,]", "invalid JSON at line 1, column 7: unexpected ']'"},
        {"{\"a\": 01}", "invalid JSON at line 1, column 8: expected ',' or '}'"},
        {"{\"a\": tru}", "invalid JSON at line 1, column 7: expected 'true'"},
        {"{\"a\": \"\\q\"}", "invalid JSON at line 1, column 9: bad escape '\\q'"},
        {"{} {}", "invalid JSON at line 1, column 4: text after the end of the JSON"},
        {"\x89PNG\r\n", "invalid JSON at line 1, column 1: unexpected '\x89'"},
    };
    for (const auto& [text, message] : cases) {
        const auto error = gltfContainerError(text);
        ASSERT_TRUE(error) << text;
        EXPECT_EQ(*error, message) << text;
    }
    EXPECT_EQ(*jsonSyntaxError(std::string(600, '[') + std::string(600, ']')),
              "invalid JSON at line 1, column 514: nested too deeply");
}

TEST(GltfFile, GlbDamage) {
    PBR_NEED_ASSIMP_MODELS(kGltf);
    const std::string glb = fileBytes((kGltf / "BoxTextured-glTF-Binary/BoxTextured.glb").string());
    ASSERT_GT(glb.size(), 1000u);
    EXPECT_EQ(*gltfContainerError(glb.substr(0, 1000)), "truncated: the GLB header says " +
                                                            std::to_string(glb.size()) +
                                                            " bytes, the file has 1000");
    EXPECT_EQ(*gltfContainerError(glb.substr(0, 8)), "truncated: 8 bytes, a GLB header needs 12");
    EXPECT_EQ(*gltfContainerError(glb + "xx"), "the GLB header says " + std::to_string(glb.size()) +
                                                   " bytes, but the file has " +
                                                   std::to_string(glb.size() + 2));
    // The length fields kept consistent, but the JSON chunk cut short inside.
    std::string broken = glb;
    const std::uint32_t jsonLength = std::uint8_t(glb[12]) | std::uint8_t(glb[13]) << 8;
    broken[20 + jsonLength / 2] = '\x01';  // not allowed anywhere in JSON
    const auto error = gltfContainerError(broken);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->rfind("in the GLB's JSON chunk: invalid JSON at line 1", 0), 0u) << *error;
}

// The structure check of a .gltf's JSON (with `binLength`: a .glb's, whose BIN chunk has that
// many bytes): its reason, or "" when the file passes.
std::string structure(std::string_view json, std::optional<std::uint64_t> binLength = std::nullopt,
                      const GltfBufferBytes& bufferBytes = {}) {
    const std::optional<JsonValue> document = parseJson(json);
    if (!document) {
        ADD_FAILURE() << "not JSON: " << json;
        return "not JSON";
    }
    return gltfStructureError(*document, binLength, bufferBytes).value_or("");
}

// `text` with its one `from` replaced by `to`.
std::string edited(std::string text, std::string_view from, std::string_view to) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    EXPECT_EQ(text.find(from, at + 1), std::string::npos) << from << " is there twice";
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

// A triangle: 3 positions (bytes 0-36) and 3 indices (bytes 36-42) of a 44-byte buffer.
const std::string kTriangle = R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "buffers": [{"uri": "triangle.bin", "byteLength": 44}],
  "bufferViews": [{"buffer": 0, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]})";

// The triangle skinned to node 1: JOINTS_0 (bytes 44-56), WEIGHTS_0 (56-104) and one inverse
// bind matrix (104-168).
const std::string kSkinned = R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0, 1]}],
  "nodes": [{"mesh": 0, "skin": 0}, {"name": "joint"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "JOINTS_0": 2, "WEIGHTS_0": 3},
                              "indices": 1}]}],
  "skins": [{"joints": [1], "inverseBindMatrices": 4}],
  "buffers": [{"uri": "skin.bin", "byteLength": 168}],
  "bufferViews": [{"buffer": 0, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 6},
                  {"buffer": 0, "byteOffset": 44, "byteLength": 12},
                  {"buffer": 0, "byteOffset": 56, "byteLength": 48},
                  {"buffer": 0, "byteOffset": 104, "byteLength": 64}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
                {"bufferView": 2, "componentType": 5121, "count": 3, "type": "VEC4"},
                {"bufferView": 3, "componentType": 5126, "count": 3, "type": "VEC4"},
                {"bufferView": 4, "componentType": 5126, "count": 1, "type": "MAT4"}]})";

// 14 positions, 3 of them replaced by a sparse accessor (glTF's SimpleSparseAccessor): indices
// 0-72, positions 72-240, sparse indices 240-246, sparse values 248-284.
const std::string kSparse = R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 1}, "indices": 0}]}],
  "buffers": [{"uri": "sparse.bin", "byteLength": 284}],
  "bufferViews": [{"buffer": 0, "byteLength": 72},
                  {"buffer": 0, "byteOffset": 72, "byteLength": 168},
                  {"buffer": 0, "byteOffset": 240, "byteLength": 6},
                  {"buffer": 0, "byteOffset": 248, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5123, "count": 36, "type": "SCALAR"},
                {"bufferView": 1, "componentType": 5126, "count": 14, "type": "VEC3",
                 "sparse": {"count": 3, "indices": {"bufferView": 2, "componentType": 5123},
                            "values": {"bufferView": 3}}}]})";

using Cases = std::vector<std::pair<std::string, std::string>>;  // document, its reason

void expectReasons(const Cases& cases) {
    for (const auto& [document, reason] : cases) EXPECT_EQ(structure(document), reason) << document;
}

TEST(GltfStructure, SoundFilesPass) {
    EXPECT_EQ(structure(kTriangle), "");
    EXPECT_EQ(structure(kSkinned), "");
    EXPECT_EQ(structure(kSparse), "");
    EXPECT_EQ(structure(kTriangle, 44), "");  // as a .glb's JSON: buffer 0 is the BIN chunk
    EXPECT_EQ(structure(edited(kTriangle, "\"2.0\"", "\"2.1\"")), "");  // minor versions read
    // A skin without inverseBindMatrices (identities, in glTF) on no node with a mesh: Assimp
    // 5.2 reads them only for a skinned mesh.
    EXPECT_EQ(structure(edited(edited(kSkinned, R"("mesh": 0, "skin": 0)", R"("mesh": 0)"),
                               R"(, "inverseBindMatrices": 4)", "")),
              "");
    // Strips, fans and loops of enough vertices.
    EXPECT_EQ(structure(edited(kTriangle, R"("indices": 1)", R"("indices": 1, "mode": 5)")), "");
    EXPECT_EQ(structure(edited(kTriangle, R"(, "indices": 1)", R"(, "mode": 2)")), "");
    // A view past its buffer and an accessor past its view that nothing uses: Assimp reads only
    // what is used (Debian's IncorrectVertexArrays/Cube.gltf has such views, and loads).
    EXPECT_EQ(structure(edited(edited(kTriangle, R"("byteOffset": 36, "byteLength": 6})",
                                      R"("byteOffset": 36, "byteLength": 6},
                                         {"buffer": 0, "byteOffset": 40, "byteLength": 400})"),
                               R"("count": 3, "type": "SCALAR"})",
                               R"("count": 3, "type": "SCALAR"},
                                  {"bufferView": 0, "componentType": 5126, "count": 99,
                                   "type": "VEC3"})")),
              "");
}

// Every glTF 2.0 file of Debian's corpus passes, the broken ones too: they are broken in ways
// Assimp refuses itself (a missing .bin, a recursive node, a wrong type, indices out of range).
TEST(GltfStructure, DebiansCorpusPasses) {
    PBR_NEED_ASSIMP_MODELS(kGltf);
    int files = 0, buffersRead = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kGltf)) {
        const std::string extension = entry.path().extension().string();
        if (extension != ".gltf" && extension != ".glb") continue;
        const std::string bytes = fileBytes(entry.path().string());
        const std::optional<JsonValue> document = gltfJson(bytes);
        ASSERT_TRUE(document) << entry.path();
        // with the bytes of its buffers, as loadModel gives them: the indices of its line loops
        // (Mesh_PrimitiveMode_09) are read
        const std::optional<std::string_view> bin = glbBin(bytes);
        const auto bufferBytes = [&](size_t index,
                                     std::string_view uri) -> std::optional<std::string> {
            if (bin && index == 0) return std::string(*bin);
            const std::filesystem::path file = entry.path().parent_path() / uri;
            if (uri.empty() || !std::filesystem::is_regular_file(file)) return std::nullopt;
            ++buffersRead;
            return fileBytes(file.string());
        };
        const std::optional<std::string> error =
            gltfStructureError(*document, glbBinLength(bytes), bufferBytes);
        EXPECT_FALSE(error) << entry.path() << ": " << *error;
        ++files;
    }
    EXPECT_GT(files, 40);
    EXPECT_GT(buffersRead, 0);  // Mesh_PrimitiveMode_09's line loops, read from its .bin
    const std::string glb = fileBytes((kGltf / "BoxTextured-glTF-Binary/BoxTextured.glb").string());
    EXPECT_EQ(glbBinLength(glb), 3276u);  // its mesh and its PNG
    EXPECT_EQ(glbBinLength("{}"), std::nullopt);
}

TEST(GltfStructure, OnlyGltf20IsRead) {
    const std::string asset = R"("asset": {"version": "2.0"})";
    expectReasons({
        {edited(kTriangle, asset, R"("asset": {"version": "1.0"})"),
         "glTF 1.0 is not read: the samples take glTF 2.0"},
        {edited(kTriangle, asset, R"("asset": {"version": 1})"),
         "glTF 1.0 is not read: the samples take glTF 2.0"},
        {edited(kTriangle, asset, R"("asset": {"version": "3.0"})"),
         "glTF 3.0 is not read: the samples take glTF 2.0"},
        {R"({"meshes": {"box": {"primitives": []}}})",
         "glTF 1.0 is not read: the samples take glTF 2.0 (there is no asset.version, and "
         "meshes is an object, as in glTF 1.0)"},
        {edited(kTriangle, asset, R"("asset": {})"),
         "asset.version is missing: a glTF 2.0 file says \"2.0\" there"},
        {edited(kTriangle, asset, R"("asset": {"version": "2"})"),
         "asset.version is '2', not a version such as \"2.0\""},
        {edited(kTriangle, asset, R"("asset": {"version": 2})"),
         "asset.version is 2, not the string \"2.0\""},
        {"[1, 2]", "the JSON is an array, not an object as in a glTF file"},
        {edited(kTriangle, R"("nodes": [{"mesh": 0}])", R"("nodes": {"a": {"mesh": 0}})"),
         "nodes is an object, not an array"},
    });
}

TEST(GltfStructure, SkinnedMeshesNeedJointsWeightsAndMatrices) {
    const std::string what = "node 0 has skin 0, but primitive 0 of mesh 0 has ";
    expectReasons({
        {edited(kSkinned, R"("JOINTS_0": 2, )", ""), what + "no JOINTS_0"},
        {edited(kSkinned, R"(, "WEIGHTS_0": 3)", ""), what + "no WEIGHTS_0"},
        {edited(kSkinned, R"("WEIGHTS_0": 3)", R"("WEIGHTS_0": 3, "WEIGHTS_1": 3)"),
         what + "WEIGHTS_1 without JOINTS_1"},
        {edited(kSkinned, R"("componentType": 5121, "count": 3)",
                R"("componentType": 5121, "count": 2)"),
         what + "2 JOINTS_0 for 3 WEIGHTS_0"},
        {edited(kSkinned, R"(, "inverseBindMatrices": 4)", ""),
         "skin 0 of node 0 has no inverseBindMatrices, which Assimp 5.2 cannot do without"},
        {edited(kSkinned, R"("count": 1, "type": "MAT4")", R"("count": 1, "type": "VEC4")"),
         "skin 0's inverseBindMatrices (accessor 4) are VEC4 of 5126, not MAT4 of FLOAT (5126)"},
        {edited(kSkinned, R"("joints": [1])", R"("joints": [1, 0])"),
         "skin 0's inverseBindMatrices (accessor 4) hold 1 matrix for 2 joints"},
        {edited(kSkinned, R"("joints": [1], )", ""), "skin 0 has no joints"},
        {edited(kSkinned, R"("joints": [1])", R"("joints": [5])"),
         "skin 0's joint 0 is node 5, but the file has only 2 nodes"},
        {edited(kSkinned, R"("skin": 0)", R"("skin": 3)"),
         "node 0 names skin 3, but the file has only 1 skin"},
    });
}

TEST(GltfStructure, AccessorsStayInsideTheirBuffers) {
    const std::string vec3 = R"("count": 3, "type": "VEC3")";
    const std::string scalar = R"("componentType": 5123, "count": 3, "type": "SCALAR")";
    expectReasons({
        {edited(kTriangle, vec3, R"("count": 4, "type": "VEC3")"),
         "accessor 0 reads bytes 0-48 of bufferView 0, which has 36"},
        {edited(kTriangle, R"({"buffer": 0, "byteLength": 36})",
                R"({"buffer": 0, "byteLength": 48})"),
         "bufferView 0 reads bytes 0-48 of buffer 0, which has 44"},
        {edited(kTriangle, R"({"buffer": 0, "byteLength": 36})",
                R"({"buffer": 0, "byteLength": 36, "byteStride": 16})"),
         "accessor 0 reads bytes 0-44 of bufferView 0, which has 36"},
        {edited(kTriangle, R"({"buffer": 0, "byteLength": 36})",
                R"({"buffer": 0, "byteLength": 36, "byteStride": 8})"),
         "bufferView 0's byteStride of 8 bytes is less than the 12 bytes of an element of "
         "accessor 0"},
        {edited(kTriangle, R"({"buffer": 0, "byteLength": 36})",
                R"({"buffer": 0, "byteLength": 36, "byteStride": 6})"),
         "bufferView 0's byteStride is 6, not a multiple of 4 from 4 to 252"},
        {edited(kTriangle, R"({"buffer": 0, "byteLength": 36})",
                R"({"buffer": 1, "byteLength": 36})"),
         "bufferView 0 names buffer 1, but the file has only 1 buffer"},
        {edited(kTriangle, R"("bufferView": 1,)", R"("bufferView": 2,)"),
         "accessor 1 names bufferView 2, but the file has only 2 bufferViews"},
        {edited(kTriangle, R"("indices": 1)", R"("indices": 7)"),
         "primitive 0 of mesh 0 names accessor 7 as its indices, but the file has only 2 "
         "accessors"},
        {edited(kTriangle, R"("POSITION": 0)", R"("POSITION": -1)"),
         "primitive 0 of mesh 0's POSITION is -1, not an index"},
        {edited(kTriangle, R"("uri": "triangle.bin", "byteLength": 44)",
                R"("uri": "triangle.bin")"),
         "buffer 0 has no byteLength"},
        {edited(kTriangle, scalar, R"("componentType": 5124, "count": 3, "type": "SCALAR")"),
         "accessor 1's componentType is 5124, not one of glTF's (5120-5123, 5125, 5126)"},
        {edited(kTriangle, scalar, R"("count": 3, "type": "SCALAR")"),
         "accessor 1 has no componentType"},
        {edited(kTriangle, scalar, R"("componentType": 5123, "count": 3, "type": "VEC5")"),
         "accessor 1's type is 'VEC5', not SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3 or MAT4"},
        {edited(kTriangle, scalar, R"("componentType": 5123, "count": 3)"),
         "accessor 1 has no type"},
        {edited(kTriangle, scalar, R"("componentType": 5123, "count": 0, "type": "SCALAR")"),
         "accessor 1's count is 0: it must be 1 or more"},
        {edited(kTriangle, scalar, R"("componentType": 5123, "count": 1.5, "type": "SCALAR")"),
         "accessor 1's count is 1.5, not a whole number"},
        {edited(kTriangle, scalar, scalar + R"(, "byteOffset": -4)"),
         "accessor 1's byteOffset is -4, not a whole number"},
        {edited(kTriangle, vec3, R"("count": 1e300, "type": "VEC3")"),
         "accessor 0's count is 1e+300, too large"},
        // 2^52 elements of 12 bytes: 64-bit arithmetic, no overflow
        {edited(kTriangle, vec3, R"("count": 4503599627370496, "type": "VEC3")"),
         "accessor 0 reads bytes 0-54043195528445952 of bufferView 0, which has 36"},
        // glTF 2.0 3.6.2.4: aligned to the component size in the view, and in the buffer
        {edited(kTriangle, scalar, scalar + R"(, "byteOffset": 1)"),
         "accessor 1's byteOffset 1 is not a multiple of its component size, 2 bytes"},
        {edited(kTriangle, R"("byteOffset": 36)", R"("byteOffset": 37)"),
         "accessor 1 starts at byte 37 of buffer 0, not a multiple of its component size, 2 "
         "bytes"},
    });
    // A .glb's buffer 0 is its BIN chunk.
    EXPECT_EQ(structure(kTriangle, 40), "buffer 0 says 44 bytes, the GLB's BIN chunk has 40");
    EXPECT_EQ(structure(kTriangle, 0), "buffer 0 says 44 bytes, and the GLB has no BIN chunk");
}

TEST(GltfStructure, SparseAccessorsStayInsideTheirViews) {
    const std::string sparse = R"("sparse": {"count": 3, )";
    expectReasons({
        {edited(kSparse, R"("values": {"bufferView": 3})",
                R"("values": {"bufferView": 3, "byteOffset": 4})"),
         "accessor 1's sparse.values reads bytes 4-40 of bufferView 3, which has 36"},
        {edited(kSparse, sparse, R"("sparse": {"count": 4, )"),
         "accessor 1's sparse.indices reads bytes 0-8 of bufferView 2, which has 6"},
        {edited(kSparse, sparse, R"("sparse": {"count": 15, )"),
         "accessor 1's sparse.count is 15, more than the 14 elements of accessor 1"},
        {edited(kSparse, R"("indices": {"bufferView": 2, )", R"("indices": {)"),
         "accessor 1's sparse.indices has no bufferView"},
        {edited(kSparse, R"("bufferView": 2, "componentType": 5123)",
                R"("bufferView": 2, "componentType": 5126)"),
         "accessor 1's sparse.indices.componentType is 5126, not an unsigned integer's (5121, "
         "5123, 5125)"},
        {edited(kSparse, R"("values": {"bufferView": 3})", R"("valuez": {"bufferView": 3})"),
         "accessor 1's sparse has no values"},
    });
}

// Assimp 5.2 decodes base64 itself: what it cannot decode is named first.
TEST(GltfStructure, Base64BuffersAreBase64) {
    const std::string uri = R"("uri": "triangle.bin")";
    const std::string zeros(59, 'A');  // 44 zero bytes: 59 characters and one '='
    const auto data = [&](const std::string& text) {
        return edited(kTriangle, uri,
                      R"("uri": "data:application/octet-stream;base64,)" + text + "\"");
    };
    EXPECT_EQ(structure(data(zeros + "=")), "");
    expectReasons({
        {data("AA|" + zeros.substr(3) + "="), "buffer 0's base64 data has '|' at character 2"},
        {data("AA\xC2\x80" + zeros.substr(4) + "="),
         "buffer 0's base64 data has byte 0xc2 at character 2"},
        {data("AA=" + zeros.substr(3) + "="),
         "buffer 0's base64 data has '=' at character 2, before its end"},
        {data(zeros), "buffer 0's base64 data is 59 characters, not a multiple of 4"},
        {data(zeros + "AAAAA"), "buffer 0's base64 data holds 48 bytes, its byteLength says 44"},
    });
    // In a .glb, Assimp reads buffer 0 from the BIN chunk, not from its uri.
    EXPECT_EQ(structure(data(zeros), 44), "");
}

// Assimp 5.2 counts a strip's or fan's faces as vertices - 2, a loop's or line strip's as
// vertices - 1, in unsigned arithmetic.
TEST(GltfStructure, StripsFansAndLoopsHaveEnoughVertices) {
    const std::string indices = R"("indices": 1)";
    const std::string count = R"("componentType": 5123, "count": 3)";
    expectReasons({
        {edited(edited(kTriangle, indices, R"("indices": 1, "mode": 5)"), count,
                R"("componentType": 5123, "count": 2)"),
         "primitive 0 of mesh 0 is a triangle strip of 2 indices, fewer than 3"},
        {edited(edited(kTriangle, indices, R"("indices": 1, "mode": 2)"), count,
                R"("componentType": 5123, "count": 1)"),
         "primitive 0 of mesh 0 is a line loop of 1 index, fewer than 2"},
        {edited(edited(kTriangle, R"(, "indices": 1)", R"(, "mode": 6)"),
                R"("count": 3, "type": "VEC3")", R"("count": 2, "type": "VEC3")"),
         "primitive 0 of mesh 0 is a triangle fan of 2 vertices, fewer than 3"},
    });
}

// Assimp 5.2 closes an indexed line loop with the first index of its first line, read through a
// null pointer when it dropped that line for a vertex out of range: the first two indices are
// read, from a data URI, a .glb's BIN chunk or a file the loader gives. (The bytes: 3 positions
// (0,0,0), (1,0,0), (0,1,0) and 3 16-bit indices, encoded by Python's base64.)
TEST(GltfStructure, IndexedLineLoopsStartOnVertices) {
    const std::string loop = edited(kTriangle, R"("indices": 1)", R"("indices": 1, "mode": 2)");
    const auto inline_ = [&](const char* base64) {
        return edited(
            loop, R"("uri": "triangle.bin")",
            std::string(R"("uri": "data:application/octet-stream;base64,)") + base64 + "\"");
    };
    const std::string first =
        "primitive 0 of mesh 0 is a line loop whose first line joins vertices ";
    expectReasons({
        {inline_("AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA="), ""},  // 0 1 2
        {inline_("AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAABQAAAAEAAAA="),       // 5 0 1
         first + "5 and 0, but its POSITION has 3 vertices"},
        // a later line past the vertices is dropped, and does not close the loop
        {inline_("AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAcAAAA="), ""},  // 0 1 7
        {edited(loop, R"("attributes": {"POSITION": 0})", R"("attributes": {})"),
         "primitive 0 of mesh 0 is a line loop of indices without POSITION: it has no vertices"},
    });
    // The loader's bytes: a .glb's buffer 0 (its BIN chunk), or the file a uri names. Indices 2
    // and 3 of 3 vertices, little-endian, from byte 36.
    std::string bytes(44, '\0');
    bytes[36] = 2;
    bytes[38] = 3;
    std::vector<std::pair<size_t, std::string>> asked;
    const auto give = [&](size_t index, std::string_view uri) -> std::optional<std::string> {
        asked.emplace_back(index, std::string(uri));
        return bytes;
    };
    EXPECT_EQ(structure(loop, std::nullopt, give),
              first + "2 and 3, but its POSITION has 3 vertices");
    EXPECT_EQ(structure(loop, 44, give), first + "2 and 3, but its POSITION has 3 vertices");
    EXPECT_EQ(asked, (std::vector<std::pair<size_t, std::string>>{{0, "triangle.bin"},
                                                                  {0, "triangle.bin"}}));
    bytes[38] = 1;
    EXPECT_EQ(structure(loop, 44, give), "");
    // what cannot be read is Assimp's: no bytes given, or a triangle list
    EXPECT_EQ(structure(loop), "");
    bytes[38] = 3;
    EXPECT_EQ(structure(kTriangle, std::nullopt, give), "");
}

}  // namespace
}  // namespace pbr
