// The checks of a glTF container before Assimp reads it (common/files/gltf_file.h): well-formed
// JSON is accepted, each kind of damage is named with where it is.
#include <gtest/gtest.h>

#include "support/test_data.h"

#include <cstdint>
#include <fstream>
#include <sstream>

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

}  // namespace
}  // namespace pbr
