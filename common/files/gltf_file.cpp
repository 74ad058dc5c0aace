#include "files/gltf_file.h"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <functional>

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
                return fail(std::string("unexpected '") + peek() + "'", "a value");
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
                return fail(std::string("bad escape '\\") + escape + "'", "a string");
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

namespace {

std::vector<std::string> strings(const JsonValue* list) {
    std::vector<std::string> out;
    if (!list) return out;
    for (const JsonValue& item : list->items) {
        if (item.type == JsonValue::Type::String) out.push_back(item.text);
    }
    return out;
}

// The index a member holds, or -1 when it is absent or not a non-negative integer.
int indexOf(const JsonValue* value) {
    if (!value || value->type != JsonValue::Type::Number || value->number < 0.0 ||
        value->number != std::floor(value->number) || value->number > 1e9)
        return -1;
    return int(value->number);
}

const JsonValue* item(const JsonValue& document, std::string_view list, int index) {
    const JsonValue* items = document.find(list);
    if (!items || index < 0 || size_t(index) >= items->items.size()) return nullptr;
    return &items->items[size_t(index)];
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
        const JsonValue* node = item(document, "nodes", index);
        if (!node || depth > 256 || !mark(nodeRead, index)) return;
        if (const JsonValue* children = node->find("children")) {
            for (const JsonValue& child : children->items) readNode(indexOf(&child), depth + 1);
        }
        const int meshIndex = indexOf(node->find("mesh"));
        const JsonValue* mesh = item(document, "meshes", meshIndex);
        if (!mesh || !mark(meshRead, meshIndex)) return;
        if (const JsonValue* primitives = mesh->find("primitives")) {
            for (const JsonValue& primitive : primitives->items) {
                const int material = indexOf(primitive.find("material"));
                if (item(document, "materials", material) && mark(materialRead, material))
                    order.push_back(material);
            }
        }
    };
    const JsonValue* sceneIndex = document.find("scene");
    const JsonValue* scene = item(document, "scenes", sceneIndex ? indexOf(sceneIndex) : 0);
    if (const JsonValue* roots = scene ? scene->find("nodes") : nullptr) {
        for (const JsonValue& root : roots->items) readNode(indexOf(&root), 0);
    }
    return order;
}

std::optional<int> texCoordOverride(const JsonValue& textureInfo) {
    const JsonValue* extensions = textureInfo.find("extensions");
    const JsonValue* transform = extensions ? extensions->find("KHR_texture_transform") : nullptr;
    const int set = transform ? indexOf(transform->find("texCoord")) : -1;
    if (set < 0) return std::nullopt;
    return set;
}

std::optional<std::string> gltfContainerError(std::string_view bytes) {
    if (bytes.substr(0, 4) == "glTF") return glbError(bytes);
    return jsonSyntaxError(bytes);
}

}  // namespace pbr
