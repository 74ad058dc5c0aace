#include "files/gltf_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <set>

#include "base/error.h"

namespace pbr {

namespace {

// A recursive-descent reader of the JSON grammar: it checks, and keeps the values when asked.
class JsonChecker {
public:
    explicit JsonChecker(std::string_view text, JsonValue* root = nullptr)
        : text_(text), root_(root) {}

    std::optional<std::string> check() {
        if (text_.substr(0, 3) == "\xEF\xBB\xBF") at_ = 3;  // a byte-order mark, tolerated
        skipSpace();
        if (!value(0, root_)) return error_;
        skipSpace();
        if (at_ != text_.size()) {
            return "invalid JSON at " + position() + ": text after the end of the JSON";
        }
        return std::nullopt;
    }

private:
    static constexpr int kMaxDepth = 512;  // deeper nesting is refused, not recursed into

    bool atEnd() const { return at_ >= text_.size(); }
    char peek() const { return text_[at_]; }

    void skipSpace() {
        while (!atEnd() && (peek() == ' ' || peek() == '\t' || peek() == '\n' || peek() == '\r'))
            ++at_;
    }

    // Where the reader stands, as a person counts: line and column from 1.
    std::string position() const {
        size_t line = 1, column = 1;
        for (size_t i = 0; i < at_ && i < text_.size(); ++i) {
            if (text_[i] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        return "line " + std::to_string(line) + ", column " + std::to_string(column);
    }

    bool fail(const std::string& what, const char* inside) {
        error_ = atEnd() ? std::string("truncated: the JSON ends inside ") + inside
                         : "invalid JSON at " + position() + ": " + what;
        return false;
    }

    // Reads one value; keeps it in `out` unless that is null.
    bool value(int depth, JsonValue* out) {
        if (depth > kMaxDepth) return fail("nested too deeply", "a value");
        if (atEnd()) return fail("", "a value");
        const size_t start = at_;
        bool ok = false;
        switch (peek()) {
            case '{':
                if (out) out->type = JsonValue::Type::Object;
                return object(depth, out);
            case '[':
                if (out) out->type = JsonValue::Type::Array;
                return array(depth, out);
            case '"':
                if (out) out->type = JsonValue::Type::String;
                return string(out ? &out->text : nullptr);
            case 't':
            case 'f':
                ok = literal(peek() == 't' ? "true" : "false");
                if (out) {
                    out->type = JsonValue::Type::Bool;
                    out->boolean = text_[start] == 't';
                }
                return ok;
            case 'n':
                return literal("null");
            default:
                if (peek() == '-' || (peek() >= '0' && peek() <= '9')) {
                    ok = number();
                    if (ok && out) {
                        out->type = JsonValue::Type::Number;
                        out->number = std::strtod(
                            std::string(text_.substr(start, at_ - start)).c_str(), nullptr);
                    }
                    return ok;
                }
                return fail("unexpected '" + printable(text_.substr(at_, 1)) + "'", "a value");
        }
    }

    bool object(int depth, JsonValue* out) {
        ++at_;  // {
        skipSpace();
        if (!atEnd() && peek() == '}') return ++at_, true;
        for (;;) {
            skipSpace();
            if (atEnd() || peek() != '"') return fail("expected a name in quotes", "an object");
            std::string key;
            if (!string(out ? &key : nullptr)) return false;
            skipSpace();
            if (atEnd() || peek() != ':') return fail("expected ':'", "an object");
            ++at_;
            skipSpace();
            JsonValue* member = nullptr;
            if (out) member = &out->members.emplace_back(std::move(key), JsonValue{}).second;
            if (!value(depth + 1, member)) return false;
            skipSpace();
            if (atEnd() || (peek() != ',' && peek() != '}'))
                return fail("expected ',' or '}'", "an object");
            if (text_[at_++] == '}') return true;
        }
    }

    bool array(int depth, JsonValue* out) {
        ++at_;  // [
        skipSpace();
        if (!atEnd() && peek() == ']') return ++at_, true;
        for (;;) {
            skipSpace();
            if (!value(depth + 1, out ? &out->items.emplace_back() : nullptr)) return false;
            skipSpace();
            if (atEnd() || (peek() != ',' && peek() != ']'))
                return fail("expected ',' or ']'", "an array");
            if (text_[at_++] == ']') return true;
        }
    }

    // A string's text, unescaped into `out` (UTF-8) unless that is null.
    bool string(std::string* out) {
        ++at_;  // "
        while (!atEnd()) {
            const unsigned char c = static_cast<unsigned char>(text_[at_]);
            if (c == '"') return ++at_, true;
            if (c < 0x20) return fail("control character inside a string", "a string");
            if (c != '\\') {
                if (out) out->push_back(char(c));
                ++at_;
                continue;
            }
            ++at_;
            if (atEnd()) break;
            const char escape = peek();
            if (escape == 'u') {
                unsigned code = 0;
                for (int i = 0; i < 4; ++i) {
                    ++at_;
                    if (atEnd()) return fail("", "a string");
                    if (!std::isxdigit(static_cast<unsigned char>(peek())))
                        return fail("bad \\u escape", "a string");
                    code = code * 16 + unsigned(std::stoi(std::string(1, peek()), nullptr, 16));
                }
                if (out) appendUtf8(*out, code);
            } else if (const char* known = std::strchr("\"\\/bfnrt", escape)) {
                if (out) out->push_back("\"\\/\b\f\n\r\t"[known - "\"\\/bfnrt"]);
            } else {
                return fail("bad escape '\\" + printable(text_.substr(at_, 1)) + "'", "a string");
            }
            ++at_;
        }
        return fail("", "a string");
    }

    // A \uXXXX escape as UTF-8 (surrogate halves are kept one by one: names only need to compare
    // equal with themselves).
    static void appendUtf8(std::string& out, unsigned code) {
        if (code < 0x80) {
            out.push_back(char(code));
        } else if (code < 0x800) {
            out.push_back(char(0xC0 | (code >> 6)));
            out.push_back(char(0x80 | (code & 0x3F)));
        } else {
            out.push_back(char(0xE0 | (code >> 12)));
            out.push_back(char(0x80 | ((code >> 6) & 0x3F)));
            out.push_back(char(0x80 | (code & 0x3F)));
        }
    }

    bool digits() {
        const size_t start = at_;
        while (!atEnd() && peek() >= '0' && peek() <= '9') ++at_;
        return at_ > start;
    }

    bool number() {
        if (peek() == '-') ++at_;
        if (!atEnd() && peek() == '0') {
            ++at_;
        } else if (!digits()) {
            return fail("expected a digit", "a number");
        }
        if (!atEnd() && peek() == '.') {
            ++at_;
            if (!digits()) return fail("expected a digit after '.'", "a number");
        }
        if (!atEnd() && (peek() == 'e' || peek() == 'E')) {
            ++at_;
            if (!atEnd() && (peek() == '+' || peek() == '-')) ++at_;
            if (!digits()) return fail("expected a digit in the exponent", "a number");
        }
        return true;
    }

    bool literal(std::string_view word) {
        const size_t start = at_;
        for (char c : word) {
            if (atEnd()) return fail("", "a value");
            if (peek() != c) {
                at_ = start;  // the message points at the word, not into it
                return fail("expected '" + std::string(word) + "'", "a value");
            }
            ++at_;
        }
        return true;
    }

    std::string_view text_;
    JsonValue* root_;
    size_t at_ = 0;
    std::string error_;
};

std::uint32_t read32(std::string_view bytes, size_t at) {
    std::uint32_t value = 0;
    for (int i = 3; i >= 0; --i) value = (value << 8) | std::uint8_t(bytes[at + size_t(i)]);
    return value;  // little-endian, whatever the machine
}

constexpr std::uint32_t kChunkJson = 0x4E4F534A, kChunkBin = 0x004E4942;

std::optional<std::string> glbError(std::string_view bytes) {
    const size_t size = bytes.size();
    if (size < 12) return "truncated: " + std::to_string(size) + " bytes, a GLB header needs 12";
    const std::uint32_t version = read32(bytes, 4), length = read32(bytes, 8);
    if (length > size) {
        return "truncated: the GLB header says " + std::to_string(length) +
               " bytes, the file has " + std::to_string(size);
    }
    if (length < size) {
        return "the GLB header says " + std::to_string(length) + " bytes, but the file has " +
               std::to_string(size);
    }
    if (version != 2) return std::nullopt;  // glTF 1.0 binary: Assimp's own reader checks it
    size_t at = 12;
    for (int chunk = 0; at < size; ++chunk) {
        if (size - at < 8)
            return "truncated inside the header of GLB chunk " + std::to_string(chunk);
        const std::uint32_t chunkLength = read32(bytes, at), type = read32(bytes, at + 4);
        at += 8;
        if (chunkLength > size - at) {
            return "truncated: GLB chunk " + std::to_string(chunk) + " needs " +
                   std::to_string(chunkLength) + " bytes, " + std::to_string(size - at) +
                   " are left";
        }
        if (chunk == 0 && type != kChunkJson) return "the first GLB chunk is not JSON";
        // glTF 2.0 4.4.3: chunks end on 4-byte boundaries (Assimp 5.2 looks for the BIN chunk at
        // the next one)
        if (chunk == 0 && chunkLength % 4 != 0) {
            return "GLB chunk 0 (JSON) is " + std::to_string(chunkLength) +
                   " bytes, not a multiple of 4";
        }
        if (chunk == 0) {
            if (auto error = jsonSyntaxError(bytes.substr(at, chunkLength)))
                return "in the GLB's JSON chunk: " + *error;
        } else if (chunk == 1 && type != kChunkBin) {
            return "the second GLB chunk is not BIN";
        }
        at += chunkLength;
    }
    if (at == 12) return "the GLB has no JSON chunk";
    return std::nullopt;
}

}  // namespace

std::optional<std::string> jsonSyntaxError(std::string_view text) {
    return JsonChecker(text).check();
}

const JsonValue* JsonValue::find(std::string_view key) const {
    for (const auto& [name, member] : members) {
        if (name == key) return &member;
    }
    return nullptr;
}

std::optional<JsonValue> parseJson(std::string_view text) {
    JsonValue root;
    if (JsonChecker(text, &root).check()) return std::nullopt;
    return root;
}

std::optional<JsonValue> gltfJson(std::string_view bytes) {
    std::string_view json = bytes;
    if (bytes.substr(0, 4) == "glTF") {
        if (glbError(bytes) || bytes.size() < 20) return std::nullopt;
        json = bytes.substr(20, read32(bytes, 12));
    }
    return parseJson(json);
}

int jsonIndex(const JsonValue* value) {
    if (!value || value->type != JsonValue::Type::Number || value->number < 0.0 ||
        value->number != std::floor(value->number) || value->number > 1e9)
        return -1;
    return int(value->number);
}

const JsonValue* jsonItem(const JsonValue& document, std::string_view list, int index) {
    const JsonValue* items = document.find(list);
    if (!items || index < 0 || size_t(index) >= items->items.size()) return nullptr;
    return &items->items[size_t(index)];
}

namespace {

std::vector<std::string> strings(const JsonValue* list) {
    std::vector<std::string> out;
    if (!list) return out;
    for (const JsonValue& item : list->items) {
        if (item.type == JsonValue::Type::String) out.push_back(item.text);
    }
    return out;
}

}  // namespace

GltfExtensions gltfExtensions(std::string_view bytes) {
    const std::optional<JsonValue> document = gltfJson(bytes);
    if (!document) return {};
    return {strings(document->find("extensionsUsed")),
            strings(document->find("extensionsRequired"))};
}

std::vector<int> assimpMaterialOrder(const JsonValue& document) {
    std::vector<int> order;
    std::vector<bool> nodeRead, meshRead, materialRead;
    auto mark = [](std::vector<bool>& read, int index) {
        if (size_t(index) >= read.size()) read.resize(size_t(index) + 1, false);
        const bool first = !read[size_t(index)];
        read[size_t(index)] = true;
        return first;
    };
    // Assimp reads a node's children before its mesh, and a mesh's primitives in order.
    std::function<void(int, int)> readNode = [&](int index, int depth) {
        const JsonValue* node = jsonItem(document, "nodes", index);
        if (!node || depth > 256 || !mark(nodeRead, index)) return;
        if (const JsonValue* children = node->find("children")) {
            for (const JsonValue& child : children->items) readNode(jsonIndex(&child), depth + 1);
        }
        const int meshIndex = jsonIndex(node->find("mesh"));
        const JsonValue* mesh = jsonItem(document, "meshes", meshIndex);
        if (!mesh || !mark(meshRead, meshIndex)) return;
        if (const JsonValue* primitives = mesh->find("primitives")) {
            for (const JsonValue& primitive : primitives->items) {
                const int material = jsonIndex(primitive.find("material"));
                if (jsonItem(document, "materials", material) && mark(materialRead, material))
                    order.push_back(material);
            }
        }
    };
    const JsonValue* sceneIndex = document.find("scene");
    const JsonValue* scene = jsonItem(document, "scenes", sceneIndex ? jsonIndex(sceneIndex) : 0);
    if (const JsonValue* roots = scene ? scene->find("nodes") : nullptr) {
        for (const JsonValue& root : roots->items) readNode(jsonIndex(&root), 0);
    }
    return order;
}

std::optional<int> texCoordOverride(const JsonValue& textureInfo) {
    const JsonValue* extensions = textureInfo.find("extensions");
    const JsonValue* transform = extensions ? extensions->find("KHR_texture_transform") : nullptr;
    const int set = transform ? jsonIndex(transform->find("texCoord")) : -1;
    if (set < 0) return std::nullopt;
    return set;
}

std::optional<std::string> gltfContainerError(std::string_view bytes) {
    if (bytes.substr(0, 4) == "glTF") return glbError(bytes);
    return jsonSyntaxError(bytes);
}

std::optional<std::string_view> glbBin(std::string_view bytes) {
    if (bytes.substr(0, 4) != "glTF" || glbError(bytes) || read32(bytes, 4) != 2)
        return std::nullopt;
    const size_t bin = 20 + size_t(read32(bytes, 12));  // the chunk after the JSON chunk
    if (bytes.size() - bin < 8) return std::string_view();
    return bytes.substr(bin + 8, read32(bytes, bin));  // glbError: the chunk lies in the file
}

std::optional<std::uint64_t> glbBinLength(std::string_view bytes) {
    const std::optional<std::string_view> bin = glbBin(bytes);
    if (!bin) return std::nullopt;
    return bin->size();
}

namespace {

// JSON numbers are exact whole numbers below 2^53: larger sizes and counts are refused, so that
// the sums below fit in 64 bits (at most 2^53 * 252 + 2^54).
constexpr std::uint64_t kLargestWhole = std::uint64_t(1) << 53;

constexpr std::string_view kBase64Digits =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

std::string numberText(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", value);
    return text;
}

// A JSON value as a message quotes it.
std::string describe(const JsonValue& value) {
    switch (value.type) {
        case JsonValue::Type::Null:
            return "null";
        case JsonValue::Type::Bool:
            return value.boolean ? "true" : "false";
        case JsonValue::Type::Number:
            return numberText(value.number);
        case JsonValue::Type::String: {
            const std::string_view text = value.text;
            return "'" + printable(text.substr(0, 40)) + (text.size() > 40 ? "...'" : "'");
        }
        case JsonValue::Type::Array:
            return "an array";
        case JsonValue::Type::Object:
            return "an object";
    }
    return "a value";
}

// Bytes of one component of a glTF componentType, or 0 for a code glTF does not have.
std::uint64_t componentSize(std::uint64_t componentType) {
    switch (componentType) {
        case 5120:  // BYTE
        case 5121:  // UNSIGNED_BYTE
            return 1;
        case 5122:  // SHORT
        case 5123:  // UNSIGNED_SHORT
            return 2;
        case 5125:  // UNSIGNED_INT
        case 5126:  // FLOAT
            return 4;
        default:
            return 0;
    }
}

// Components of an accessor type, or 0 for a type glTF does not have.
std::uint64_t componentCount(std::string_view type) {
    const std::pair<std::string_view, std::uint64_t> types[] = {
        {"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4},
        {"MAT2", 4},   {"MAT3", 9}, {"MAT4", 16}};
    for (const auto& [name, count] : types) {
        if (type == name) return count;
    }
    return 0;
}

// glTF 2.0 3.6.2.4: each column of a matrix starts at a multiple of 4 bytes, so MAT2 and MAT3
// of 1-byte components and MAT3 of 2-byte ones have padding in each element.
std::uint64_t elementSize(std::string_view type, std::uint64_t component) {
    if (type == "MAT2" && component == 1) return 8;
    if (type == "MAT3" && component == 1) return 12;
    if (type == "MAT3" && component == 2) return 24;
    return componentCount(type) * component;
}

// Assimp 5.2's set of a JOINTS or WEIGHTS attribute (it reads "JOINTS_2" and "JOINTSX" as sets 2
// and 0), or -1 for other attributes.
int skinSet(std::string_view attribute, std::string_view semantic) {
    if (!attribute.starts_with(semantic)) return -1;
    const std::string_view rest = attribute.substr(semantic.size());
    if (!rest.starts_with("_")) return 0;
    const long set = std::strtol(std::string(rest.substr(1)).c_str(), nullptr, 10);
    return int(std::clamp(set, 0L, 1000000L));  // atoi's, without its overflow
}

// What a message calls a part of the file: "accessor 3", whose members read "accessor 3's count";
// or "accessor 3's sparse.indices", whose members read "accessor 3's sparse.indices.byteOffset".
struct Part {
    std::string name, members;
    explicit Part(std::string partName) : name(std::move(partName)), members(name + "'s ") {}
    Part(const Part& owner, std::string_view path)
        : name(owner.members + std::string(path)), members(name + ".") {}
};

// The checks of gltfStructureError. Assimp 5.2 reads a buffer, buffer view or accessor only when
// something it reads names it (a file with a broken view nothing uses loads, as Debian's
// IncorrectVertexArrays/Cube.gltf does), so these check them the same way, each once, starting
// from what names them: the meshes of the nodes, every skin, animation and image. A refusal
// keeps the first reason found and returns false.
class StructureChecker {
public:
    StructureChecker(const JsonValue& document, std::optional<std::uint64_t> binLength,
                     const GltfBufferBytes& bufferBytes)
        : document_(document), binLength_(binLength), bufferBytes_(bufferBytes) {}

    std::optional<std::string> check() {
        if (!version() || !list("buffers", buffers_) || !list("bufferViews", views_) ||
            !list("accessors", accessors_) || !list("meshes", meshes_) || !list("nodes", nodes_) ||
            !list("skins", skins_) || !list("animations", animations_) ||
            !list("images", images_) || !meshes() || !skins() || !animations() || !images() ||
            !skinnedNodes())
            return error_;
        return std::nullopt;
    }

private:
    struct View {
        std::uint64_t buffer, offset, length, stride;  // stride 0: none given
    };
    struct Accessor {
        std::uint64_t count, componentType;
        std::string type;
        int view = -1;             // none: its elements are zeros
        std::uint64_t offset = 0;  // in its view
        bool sparse = false;
    };

    bool fail(std::string reason) {
        error_ = std::move(reason);
        return false;
    }

    static size_t sizeOf(const JsonValue* list) { return list ? list->items.size() : 0; }

    bool version() {
        if (document_.type != JsonValue::Type::Object)
            return fail("the JSON is " + describe(document_) + ", not an object as in a glTF file");
        const JsonValue* asset = document_.find("asset");
        const JsonValue* version = asset ? asset->find("version") : nullptr;
        if (!version) {
            // glTF 1.0 kept its parts in objects keyed by name, where glTF 2.0 has arrays.
            for (const char* list : {"accessors", "bufferViews", "buffers", "meshes", "nodes",
                                     "materials", "scenes"}) {
                const JsonValue* items = document_.find(list);
                if (items && items->type == JsonValue::Type::Object) {
                    return fail(
                        "glTF 1.0 is not read: the samples take glTF 2.0 (there is no "
                        "asset.version, and " +
                        std::string(list) + " is an object, as in glTF 1.0)");
                }
            }
            return fail("asset.version is missing: a glTF 2.0 file says \"2.0\" there");
        }
        if (version->type == JsonValue::Type::Number) {
            // as Assimp's glTF 1.0 reader takes it; its glTF 2.0 reader takes only a string
            char text[32];
            std::snprintf(text, sizeof text, "%.1f", version->number);
            if (std::string_view(text).starts_with("2."))
                return fail("asset.version is " + describe(*version) + ", not the string \"2.0\"");
            return fail("glTF " + std::string(text) + " is not read: the samples take glTF 2.0");
        }
        // glTF 2.0 3.2: "<major>.<minor>"
        const std::string& text = version->text;
        const size_t dot = text.find('.');
        const bool number = version->type == JsonValue::Type::String && dot != 0 &&
                            dot != std::string::npos && dot + 1 < text.size() &&
                            text.find_first_not_of("0123456789.") == std::string::npos &&
                            text.find('.', dot + 1) == std::string::npos;
        if (!number) {
            return fail("asset.version is " + describe(*version) +
                        ", not a version such as \"2.0\"");
        }
        if (text.substr(0, dot) != "2")
            return fail("glTF " + text + " is not read: the samples take glTF 2.0");
        return true;
    }

    // The top-level list `name` (nullptr when the file has none): Assimp refuses one that is
    // not an array, but only after it read those it reads first.
    bool list(const char* name, const JsonValue*& out) {
        out = document_.find(name);
        if (out && out->type != JsonValue::Type::Array)
            return fail(std::string(name) + " is " + describe(*out) + ", not an array");
        return true;
    }

    // Item `index` of a top-level list, known to be in it, as an object (nullptr: refused).
    const JsonValue* object(const JsonValue* list, const std::string& name, int index) {
        const JsonValue& item = list->items[size_t(index)];
        if (item.type == JsonValue::Type::Object) return &item;
        fail(name + " is " + describe(item) + ", not an object");
        return nullptr;
    }

    // A size or count: `member` of `owner`, or `fallback` when absent (nullopt: required).
    bool whole(const JsonValue& owner, const Part& part, const char* member,
               std::optional<std::uint64_t> fallback, std::uint64_t least, std::uint64_t& out) {
        const JsonValue* value = owner.find(member);
        if (!value) {
            if (!fallback) return fail(part.name + " has no " + member);
            out = *fallback;
            return true;
        }
        const std::string what = part.members + member + " is " + describe(*value);
        if (value->type != JsonValue::Type::Number || value->number < 0.0 ||
            value->number != std::floor(value->number))
            return fail(what + ", not a whole number");
        if (value->number >= double(kLargestWhole)) return fail(what + ", too large");
        out = std::uint64_t(value->number);
        if (out < least) return fail(what + ": it must be " + std::to_string(least) + " or more");
        return true;
    }

    // An index into the file's list of `kind`s (`count` of them): `member` of `owner`, -1 when
    // absent and not `required`.
    bool reference(const JsonValue& owner, const Part& part, const std::string& member,
                   const char* kind, size_t count, bool required, int& out) {
        out = -1;
        const JsonValue* value = owner.find(member);
        if (!value) return !required || fail(part.name + " has no " + member);
        return index(*value, part.name + " names " + kind + " ",
                     member == kind ? std::string() : " as its " + member, part.members + member,
                     kind, count, out);
    }

    // `value` as an index of one of the `count` items of a list of `kind`s, said as
    // "<names><index><as>, but the file has ..." or "<what> is ..., not an index".
    bool index(const JsonValue& value, const std::string& names, const std::string& as,
               const std::string& what, const char* kind, size_t count, int& out) {
        out = jsonIndex(&value);
        if (out < 0) return fail(what + " is " + describe(value) + ", not an index");
        if (size_t(out) >= count) {
            const std::string kinds = kind + std::string(count == 1                         ? ""
                                                         : kind == std::string_view("mesh") ? "es"
                                                                                            : "s");
            return fail(names + std::to_string(out) + as + ", but the file has " +
                        (count ? "only " + std::to_string(count) : std::string("no")) + " " +
                        kinds);
        }
        return true;
    }

    // How many bytes of buffer `index` Assimp holds.
    bool buffer(int index, std::uint64_t& size) {
        if (bufferSizes_.empty()) bufferSizes_.resize(sizeOf(buffers_));
        std::optional<std::uint64_t>& known = bufferSizes_[size_t(index)];
        if (known) return size = *known, true;
        const Part part("buffer " + std::to_string(index));
        const JsonValue* buffer = object(buffers_, part.name, index);
        if (!buffer || !whole(*buffer, part, "byteLength", std::nullopt, 1, size)) return false;
        const JsonValue* uri = buffer->find("uri");
        if (binLength_ && index == 0) {
            // Assimp 5.2 reads a .glb's buffer 0 from the BIN chunk, whatever its uri says
            if (size > *binLength_) {
                return fail(part.name + " says " + std::to_string(size) + " bytes, " +
                            (*binLength_ ? "the GLB's BIN chunk has " + std::to_string(*binLength_)
                                         : std::string("and the GLB has no BIN chunk")));
            }
        } else if (uri && uri->type == JsonValue::Type::String && uri->text.starts_with("data:") &&
                   !base64(part, uri->text, size)) {
            return false;
        }
        known = size;
        return true;
    }

    // Whether a data URI's text before its comma says base64: Assimp 5.2 takes it so when a
    // parameter after the media type starts with "base64".
    static bool isBase64(std::string_view head) {
        for (size_t at = head.find(';'); at != std::string_view::npos; at = head.find(';', at + 1))
            if (head.substr(at + 1).starts_with("base64")) return true;
        return false;
    }

    // A data URI's base64 text: Assimp 5.2 decodes only characters below 0x80 (it leaks the
    // buffer when it meets another) and throws on a length that is not a multiple of 4.
    bool base64(const Part& part, std::string_view uri, std::uint64_t length) {
        const size_t comma = uri.find(',');
        if (comma == std::string_view::npos) return true;  // not data: Assimp's to judge
        if (!isBase64(uri.substr(0, comma))) return true;
        const std::string_view text = uri.substr(comma + 1);
        const std::string what = part.name + "'s base64 data";
        if (text.size() % 4 != 0) {
            return fail(what + " is " + std::to_string(text.size()) +
                        " characters, not a multiple of 4");
        }
        const size_t bad = text.find_first_not_of(kBase64Digits);
        size_t padding = 0;
        if (bad != std::string_view::npos) {
            padding = text.size() - bad;
            if (padding > 2 || text.substr(bad).find_first_not_of('=') != std::string_view::npos) {
                const auto c = static_cast<unsigned char>(text[bad]);
                char shown[16];
                if (c > 0x20 && c < 0x7f)
                    std::snprintf(shown, sizeof shown, "'%c'", c);
                else
                    std::snprintf(shown, sizeof shown, "byte 0x%02x", unsigned(c));
                return fail(what + " has " + shown + " at character " + std::to_string(bad) +
                            (c == '=' ? ", before its end" : ""));
            }
        }
        const std::uint64_t decoded = text.size() / 4 * 3 - padding;
        if (decoded != length) {
            return fail(what + " holds " + std::to_string(decoded) +
                        " bytes, its byteLength says " + std::to_string(length));
        }
        return true;
    }

    // Buffer view `index`, inside its buffer.
    bool view(int index, View& out) {
        if (viewsRead_.empty()) viewsRead_.resize(sizeOf(views_));
        std::optional<View>& known = viewsRead_[size_t(index)];
        if (known) return out = *known, true;
        const Part part("bufferView " + std::to_string(index));
        const JsonValue* view = object(views_, part.name, index);
        int buffer = -1;
        std::uint64_t size = 0;
        if (!view || !reference(*view, part, "buffer", "buffer", sizeOf(buffers_), true, buffer) ||
            !this->buffer(buffer, size) || !whole(*view, part, "byteOffset", 0, 0, out.offset) ||
            !whole(*view, part, "byteLength", std::nullopt, 1, out.length) ||
            !whole(*view, part, "byteStride", 0, 0, out.stride))
            return false;
        if (view->find("byteStride") && (out.stride < 4 || out.stride > 252 || out.stride % 4)) {
            return fail(part.members + "byteStride is " + std::to_string(out.stride) +
                        ", not a multiple of 4 from 4 to 252");
        }
        out.buffer = std::uint64_t(buffer);
        const std::uint64_t end = out.offset + out.length;
        if (end > size) {
            return fail(part.name + " reads bytes " + std::to_string(out.offset) + "-" +
                        std::to_string(end) + " of buffer " + std::to_string(buffer) +
                        ", which has " + std::to_string(size));
        }
        known = out;
        return true;
    }

    // Accessor `index`: a known component type and type, inside its buffer view, aligned.
    bool accessor(int index, Accessor& out) {
        if (accessorsRead_.empty()) accessorsRead_.resize(sizeOf(accessors_));
        std::optional<Accessor>& known = accessorsRead_[size_t(index)];
        if (known) return out = *known, true;
        const Part part("accessor " + std::to_string(index));
        const JsonValue* accessor = object(accessors_, part.name, index);
        if (!accessor ||
            !whole(*accessor, part, "componentType", std::nullopt, 0, out.componentType))
            return false;
        const std::uint64_t component = componentSize(out.componentType);
        if (component == 0) {
            return fail(part.members + "componentType is " + std::to_string(out.componentType) +
                        ", not one of glTF's (5120-5123, 5125, 5126)");
        }
        const JsonValue* type = accessor->find("type");
        if (!type) return fail(part.name + " has no type");
        if (type->type != JsonValue::Type::String || componentCount(type->text) == 0) {
            return fail(part.members + "type is " + describe(*type) +
                        ", not SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3 or MAT4");
        }
        out.type = type->text;
        const std::uint64_t element = elementSize(out.type, component);
        std::uint64_t offset = 0;
        int viewIndex = -1;
        if (!whole(*accessor, part, "count", std::nullopt, 1, out.count) ||
            !whole(*accessor, part, "byteOffset", 0, 0, offset) ||
            !reference(*accessor, part, "bufferView", "bufferView", sizeOf(views_), false,
                       viewIndex))
            return false;
        if (viewIndex >= 0) {
            // glTF 2.0 3.6.2.4: aligned to the component's size, inside the buffer view
            View view{};
            if (!this->view(viewIndex, view)) return false;
            const std::string viewName = "bufferView " + std::to_string(viewIndex);
            if (offset % component != 0) {
                return fail(part.members + "byteOffset " + std::to_string(offset) +
                            " is not a multiple of its component size, " +
                            std::to_string(component) + " bytes");
            }
            if ((view.offset + offset) % component != 0) {
                return fail(part.name + " starts at byte " + std::to_string(view.offset + offset) +
                            " of buffer " + std::to_string(view.buffer) +
                            ", not a multiple of its component size, " + std::to_string(component) +
                            " bytes");
            }
            const std::uint64_t stride = view.stride ? view.stride : element;
            if (stride < element) {
                return fail(viewName + "'s byteStride of " + std::to_string(stride) +
                            " bytes is less than the " + std::to_string(element) +
                            " bytes of an element of " + part.name);
            }
            const std::uint64_t end = offset + (out.count - 1) * stride + element;
            if (end > view.length) {
                return fail(part.name + " reads bytes " + std::to_string(offset) + "-" +
                            std::to_string(end) + " of " + viewName + ", which has " +
                            std::to_string(view.length));
            }
        }
        if (const JsonValue* sparse = accessor->find("sparse")) {
            if (!sparseValues(*sparse, part, out.count, element)) return false;
            out.sparse = true;
        }
        out.view = viewIndex;
        out.offset = offset;
        known = out;
        return true;
    }

    // Assimp 5.2 patches a sparse accessor as it reads it, from both views unchecked.
    bool sparseValues(const JsonValue& sparse, const Part& accessor, std::uint64_t count,
                      std::uint64_t element) {
        const Part part(accessor, "sparse");
        if (sparse.type != JsonValue::Type::Object)
            return fail(part.name + " is " + describe(sparse) + ", not an object");
        std::uint64_t values = 0;
        if (!whole(sparse, part, "count", std::nullopt, 1, values)) return false;
        if (values > count) {
            return fail(part.members + "count is " + std::to_string(values) + ", more than the " +
                        std::to_string(count) + " elements of " + accessor.name);
        }
        for (const char* member : {"indices", "values"}) {
            const JsonValue* at = sparse.find(member);
            if (!at) return fail(part.name + " has no " + member);
            const Part where(part, member);
            if (at->type != JsonValue::Type::Object)
                return fail(where.name + " is " + describe(*at) + ", not an object");
            int viewIndex = -1;
            View view{};
            std::uint64_t offset = 0, size = element;
            if (!reference(*at, where, "bufferView", "bufferView", sizeOf(views_), true,
                           viewIndex) ||
                !this->view(viewIndex, view) || !whole(*at, where, "byteOffset", 0, 0, offset))
                return false;
            if (member == std::string_view("indices")) {
                std::uint64_t type = 0;
                if (!whole(*at, where, "componentType", std::nullopt, 0, type)) return false;
                if (type != 5121 && type != 5123 && type != 5125) {
                    return fail(where.members + "componentType is " + std::to_string(type) +
                                ", not an unsigned integer's (5121, 5123, 5125)");
                }
                size = componentSize(type);
            }
            const std::uint64_t end = offset + values * size;
            if (end > view.length) {
                return fail(where.name + " reads bytes " + std::to_string(offset) + "-" +
                            std::to_string(end) + " of bufferView " + std::to_string(viewIndex) +
                            ", which has " + std::to_string(view.length));
            }
        }
        return true;
    }

    // An accessor `member` of `owner` names (-1 when absent), checked.
    bool usedAccessor(const JsonValue& owner, const Part& part, const std::string& member,
                      int& out) {
        Accessor read;
        return reference(owner, part, member, "accessor", sizeOf(accessors_), false, out) &&
               (out < 0 || accessor(out, read));
    }

    // The meshes of the nodes: each primitive's accessors (its morph targets' too), and enough
    // vertices for a strip, fan or loop (Assimp 5.2 counts its faces as vertices - 2 or - 1,
    // unsigned).
    bool meshes() {
        for (size_t n = 0; n < sizeOf(nodes_); ++n) {
            const JsonValue& node = nodes_->items[n];
            int mesh = -1;
            if (!reference(node, Part("node " + std::to_string(n)), "mesh", "mesh", sizeOf(meshes_),
                           false, mesh))
                return false;
            if (mesh < 0 || meshesRead_.contains(mesh)) continue;
            meshesRead_.insert(mesh);
            const JsonValue* primitives = meshes_->items[size_t(mesh)].find("primitives");
            if (!primitives || primitives->type != JsonValue::Type::Array) continue;  // Assimp's
            for (size_t p = 0; p < primitives->items.size(); ++p) {
                if (!primitive(primitives->items[p], Part("primitive " + std::to_string(p) +
                                                          " of mesh " + std::to_string(mesh))))
                    return false;
            }
        }
        return true;
    }

    bool primitive(const JsonValue& primitive, const Part& part) {
        int indices = -1, position = -1;
        if (!usedAccessor(primitive, part, "indices", indices)) return false;
        std::vector<const JsonValue*> sets = {primitive.find("attributes")};
        if (const JsonValue* targets = primitive.find("targets")) {
            for (const JsonValue& target : targets->items) sets.push_back(&target);
        }
        for (const JsonValue* attributes : sets) {
            for (const auto& [name, value] : attributes ? attributes->members : kNoMembers) {
                int index = -1;
                Accessor read;
                if (!this->index(value, part.name + " names accessor ", " as its " + name,
                                 part.members + name, "accessor", sizeOf(accessors_), index) ||
                    !accessor(index, read))
                    return false;
                if (attributes == sets[0] && name == "POSITION" && position < 0) position = index;
            }
        }
        std::uint64_t mode = 4;
        if (!whole(primitive, part, "mode", 4, 0, mode)) return false;
        const char* modes[] = {
            "", "", "line loop", "line strip", "", "triangle strip", "triangle fan"};
        std::uint64_t needed = 0;
        if (mode == 2 || mode == 3) needed = 2;
        if (mode == 5 || mode == 6) needed = 3;
        const int counted = indices >= 0 ? indices : position;
        const std::uint64_t count = counted >= 0 ? accessorsRead_[size_t(counted)]->count : 0;
        if (count < needed) {
            const char* what = indices >= 0 ? (count == 1 ? " index" : " indices")
                                            : (count == 1 ? " vertex" : " vertices");
            return fail(part.name + " is a " + modes[mode] + " of " + std::to_string(count) + what +
                        ", fewer than " + std::to_string(needed));
        }
        return mode != 2 || indices < 0 || lineLoop(part, indices, position);
    }

    // Assimp 5.2 drops a line naming a vertex past the primitive's, then closes an indexed line
    // loop with the first index of its first line, read from that line even when it was dropped:
    // through a null pointer. So the first two indices must name vertices of the primitive.
    bool lineLoop(const Part& part, int indices, int position) {
        if (position < 0)
            return fail(part.name +
                        " is a line loop of indices without POSITION: it has no vertices");
        const Accessor& read = *accessorsRead_[size_t(indices)];
        if (read.sparse) return true;     // Assimp patches them as it reads them: not read here
        std::uint64_t first[2] = {0, 0};  // an accessor without a view holds zeros
        if (read.view >= 0) {
            const View& view = *viewsRead_[size_t(read.view)];
            const std::optional<std::string>& bytes = bufferBytes(int(view.buffer));
            if (!bytes) return true;  // Assimp's to read
            const std::uint64_t size = componentSize(read.componentType);
            const std::uint64_t stride = view.stride ? view.stride : size;
            for (std::uint64_t i = 0; i < 2; ++i) {
                const std::uint64_t at = view.offset + read.offset + i * stride;
                if (at + size > bytes->size()) return true;  // Assimp's to judge
                for (std::uint64_t b = 0; b < size; ++b)     // little-endian
                    first[i] |= std::uint64_t(std::uint8_t((*bytes)[size_t(at + b)])) << (8 * b);
            }
        }
        const std::uint64_t vertices = accessorsRead_[size_t(position)]->count;
        if (first[0] < vertices && first[1] < vertices) return true;
        return fail(part.name + " is a line loop whose first line joins vertices " +
                    std::to_string(first[0]) + " and " + std::to_string(first[1]) +
                    ", but its POSITION has " + std::to_string(vertices) +
                    (vertices == 1 ? " vertex" : " vertices"));
    }

    // The bytes of buffer `index` (its byteLength checked), where they can be had: a data URI's
    // own, or the caller's (a .glb's BIN chunk, a file beside the .gltf).
    const std::optional<std::string>& bufferBytes(int index) {
        const auto [at, added] = bytesRead_.try_emplace(index);
        if (!added) return at->second;
        const JsonValue* uri = buffers_->items[size_t(index)].find("uri");
        const std::string_view text =
            uri && uri->type == JsonValue::Type::String ? std::string_view(uri->text) : "";
        if (!(binLength_ && index == 0) && text.starts_with("data:"))
            at->second = base64Bytes(text);
        else if (bufferBytes_)
            at->second = bufferBytes_(size_t(index), text);
        return at->second;
    }

    // A data URI's bytes, when base64 (checked by base64() above), else nullopt.
    static std::optional<std::string> base64Bytes(std::string_view uri) {
        const size_t comma = uri.find(',');
        if (comma == std::string_view::npos || !isBase64(uri.substr(0, comma))) return std::nullopt;
        std::string bytes;
        std::uint32_t bits = 0;
        int held = 0;
        for (const char c : uri.substr(comma + 1)) {
            const size_t digit = kBase64Digits.find(c);
            if (digit == std::string_view::npos) break;  // '=' ends it
            bits = (bits << 6) | std::uint32_t(digit);
            held += 6;
            if (held >= 8) {
                held -= 8;
                bytes.push_back(char((bits >> held) & 0xFF));
            }
        }
        return bytes;
    }

    // Every skin (Assimp 5.2 reads them all): joints that are nodes, and inverseBindMatrices,
    // when given, of one MAT4 float a joint.
    bool skins() {
        for (size_t s = 0; s < sizeOf(skins_); ++s) {
            const Part part("skin " + std::to_string(s));
            const JsonValue* skin = object(skins_, part.name, int(s));
            if (!skin) return false;
            const JsonValue* joints = skin->find("joints");
            if (!joints || joints->type != JsonValue::Type::Array || joints->items.empty())
                return fail(part.name + " has no joints");
            for (size_t j = 0; j < joints->items.size(); ++j) {
                const std::string joint = part.members + "joint " + std::to_string(j);
                int node = -1;
                if (!index(joints->items[j], joint + " is node ", "", joint, "node", sizeOf(nodes_),
                           node))
                    return false;
            }
            int matrices = -1;
            if (!usedAccessor(*skin, part, "inverseBindMatrices", matrices)) return false;
            if (matrices < 0) continue;
            const Accessor& accessor = *accessorsRead_[size_t(matrices)];
            const std::string what =
                part.members + "inverseBindMatrices (accessor " + std::to_string(matrices) + ")";
            if (accessor.type != "MAT4" || accessor.componentType != 5126) {
                return fail(what + " are " + accessor.type + " of " +
                            std::to_string(accessor.componentType) + ", not MAT4 of FLOAT (5126)");
            }
            if (accessor.count < joints->items.size()) {
                return fail(what + " hold " + std::to_string(accessor.count) +
                            (accessor.count == 1 ? " matrix for " : " matrices for ") +
                            std::to_string(joints->items.size()) + " joints");
            }
        }
        return true;
    }

    // Every animation's samplers (Assimp 5.2 reads them all).
    bool animations() {
        for (size_t a = 0; a < sizeOf(animations_); ++a) {
            const JsonValue* samplers = animations_->items[a].find("samplers");
            for (size_t s = 0; samplers && s < samplers->items.size(); ++s) {
                const Part part("sampler " + std::to_string(s) + " of animation " +
                                std::to_string(a));
                int input = -1, output = -1;
                if (!usedAccessor(samplers->items[s], part, "input", input) ||
                    !usedAccessor(samplers->items[s], part, "output", output))
                    return false;
            }
        }
        return true;
    }

    // Every image kept in a buffer view (Assimp 5.2 reads them all).
    bool images() {
        for (size_t i = 0; i < sizeOf(images_); ++i) {
            int viewIndex = -1;
            View read{};
            if (!reference(images_->items[i], Part("image " + std::to_string(i)), "bufferView",
                           "bufferView", sizeOf(views_), false, viewIndex) ||
                (viewIndex >= 0 && !view(viewIndex, read)))
                return false;
        }
        return true;
    }

    // A node with a skin and a mesh: Assimp 5.2 reads its primitives' JOINTS_n and WEIGHTS_n as
    // pairs of WEIGHTS_0's count, and its skin's inverseBindMatrices without looking whether
    // there are any.
    bool skinnedNodes() {
        for (size_t n = 0; n < sizeOf(nodes_); ++n) {
            const JsonValue& node = nodes_->items[n];
            const Part part("node " + std::to_string(n));
            int skin = -1, mesh = -1;
            if (!reference(node, part, "skin", "skin", sizeOf(skins_), false, skin) ||
                !reference(node, part, "mesh", "mesh", sizeOf(meshes_), false, mesh))
                return false;
            if (skin < 0 || mesh < 0) continue;
            const JsonValue* primitives = meshes_->items[size_t(mesh)].find("primitives");
            for (size_t p = 0; primitives && p < primitives->items.size(); ++p) {
                const std::string what = part.name + " has skin " + std::to_string(skin) +
                                         ", but primitive " + std::to_string(p) + " of mesh " +
                                         std::to_string(mesh);
                if (!skinned(primitives->items[p], what)) return false;
            }
            if (!skins_->items[size_t(skin)].find("inverseBindMatrices")) {
                return fail("skin " + std::to_string(skin) + " of " + part.name +
                            " has no inverseBindMatrices, which Assimp 5.2 cannot do without");
            }
        }
        return true;
    }

    // glTF 2.0 3.7.3.3: a skinned mesh's primitives have JOINTS_0 and WEIGHTS_0, the same sets
    // of each, every accessor of a primitive the same count. (Their accessors are read by now.)
    bool skinned(const JsonValue& primitive, const std::string& what) {
        const JsonValue* attributes = primitive.find("attributes");
        for (const char* needed : {"JOINTS_0", "WEIGHTS_0"}) {
            if (!attributes || !attributes->find(needed)) return fail(what + " has no " + needed);
        }
        const auto countOf = [&](const JsonValue* value) {
            return accessorsRead_[size_t(jsonIndex(value))]->count;
        };
        const std::uint64_t count = countOf(attributes->find("WEIGHTS_0"));
        for (const auto& [name, value] : attributes->members) {
            const int joints = skinSet(name, "JOINTS"), weights = skinSet(name, "WEIGHTS");
            if (joints < 0 && weights < 0) continue;
            const std::string pair = joints >= 0 ? "WEIGHTS_" + std::to_string(joints)
                                                 : "JOINTS_" + std::to_string(weights);
            if (!attributes->find(pair)) return fail(what + " has " + name + " without " + pair);
            if (countOf(&value) != count) {
                return fail(what + " has " + std::to_string(countOf(&value)) + " " + name +
                            " for " + std::to_string(count) + " WEIGHTS_0");
            }
        }
        return true;
    }

    static inline const std::vector<std::pair<std::string, JsonValue>> kNoMembers{};

    const JsonValue& document_;
    const std::optional<std::uint64_t> binLength_;
    const GltfBufferBytes& bufferBytes_;
    std::string error_;
    const JsonValue *buffers_ = nullptr, *views_ = nullptr, *accessors_ = nullptr,
                    *meshes_ = nullptr, *nodes_ = nullptr, *skins_ = nullptr,
                    *animations_ = nullptr, *images_ = nullptr;
    // What has been read, by index: what Assimp holds of each buffer, the views, the accessors
    std::vector<std::optional<std::uint64_t>> bufferSizes_;
    std::vector<std::optional<View>> viewsRead_;
    std::vector<std::optional<Accessor>> accessorsRead_;
    std::set<int> meshesRead_;
    std::map<int, std::optional<std::string>> bytesRead_;  // bufferBytes(), by buffer
};

}  // namespace

std::optional<std::string> gltfStructureError(const JsonValue& document,
                                              std::optional<std::uint64_t> glbBinLength,
                                              const GltfBufferBytes& bufferBytes) {
    return StructureChecker(document, glbBinLength, bufferBytes).check();
}

}  // namespace pbr
