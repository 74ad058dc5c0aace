// glTF's JSON and containers (files/gltf_file.h), what a user's model goes through before Assimp:
// the container check says one line or nothing, agrees with the parser on what is sound, refuses
// nesting too deep for the stack, and what is read of a parsed document (Assimp's material order,
// KHR_texture_transform's texCoord, the extension lists) only names what the document holds; the
// structure check refuses in one line or passes.
#include "files/gltf_file.h"
#include "fuzz_check.h"

namespace pbr::fuzz {

// Every object of the document: texCoordOverride on each, as the loader asks of textureInfos.
void visit(const JsonValue& value, int depth) {
    expect(depth <= 513, "no value deeper than the parser takes");
    if (value.type == JsonValue::Type::Object) {
        if (const std::optional<int> set = texCoordOverride(value))
            expect(*set >= 0, "a texture coordinate set is not negative");
    }
    for (const JsonValue& item : value.items) visit(item, depth + 1);
    for (const auto& [name, member] : value.members) visit(member, depth + 1);
}

size_t countOf(const JsonValue& document, std::string_view list) {
    const JsonValue* items = document.find(list);
    return items ? items->items.size() : 0;
}

}  // namespace pbr::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace pbr;
    const std::string_view bytes = fuzz::bytesOf(data, size);
    const bool glb = bytes.substr(0, 4) == "glTF";
    const std::optional<std::string> containerError = gltfContainerError(bytes);
    if (containerError) fuzz::expectOneLine(*containerError, "");
    // The text as JSON: the checker and the parser are one reader, and agree.
    const std::optional<std::string> syntaxError = jsonSyntaxError(bytes);
    if (syntaxError) fuzz::expectOneLine(*syntaxError, "");
    fuzz::expect(syntaxError.has_value() == !parseJson(bytes).has_value(),
                 "jsonSyntaxError and parseJson agree");

    const std::optional<JsonValue> document = gltfJson(bytes);
    if (!glb) {
        fuzz::expect(containerError.has_value() == !document.has_value(),
                     "a .gltf's JSON is read exactly when its container is sound");
    } else if (containerError) {
        fuzz::expect(!document, "no JSON is read from a .glb whose container is unsound");
    }
    const GltfExtensions extensions = gltfExtensions(bytes);
    if (!document) {
        fuzz::expect(extensions.used.empty() && extensions.required.empty(),
                     "no extensions without a document");
        return 0;
    }
    fuzz::visit(*document, 0);
    const std::optional<std::string_view> bin = glbBin(bytes);
    const auto binBytes = [&](size_t index, std::string_view) -> std::optional<std::string> {
        if (bin && index == 0) return std::string(*bin);
        return std::nullopt;
    };
    if (const std::optional<std::string> error = gltfStructureError(
            *document, bin ? std::optional<std::uint64_t>(bin->size()) : std::nullopt, binBytes))
        fuzz::expectOneLine(*error, "");
    const std::vector<int> order = assimpMaterialOrder(*document);
    std::vector<bool> seen(fuzz::countOf(*document, "materials"), false);
    for (const int material : order) {
        fuzz::expect(material >= 0 && size_t(material) < seen.size() && !seen[size_t(material)],
                     "each material of the order is in the file, once");
        seen[size_t(material)] = true;
    }
    return 0;
}
