#include "gltf_file.h"

#include <cctype>
#include <cstdint>
#include <cstring>

namespace pbr {

namespace {

// A recursive-descent reader of the JSON grammar that only checks: no values are kept.
class JsonChecker {
public:
    explicit JsonChecker(std::string_view text, GltfExtensions* extensions = nullptr)
        : text_(text), extensions_(extensions) {}

    std::optional<std::string> check() {
        if (text_.substr(0, 3) == "\xEF\xBB\xBF") at_ = 3;  // a byte-order mark, tolerated
        skipSpace();
        if (!value(0)) return error_;
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

    bool value(int depth) {
        if (depth > kMaxDepth) return fail("nested too deeply", "a value");
        if (atEnd()) return fail("", "a value");
        switch (peek()) {
            case '{':
                return object(depth);
            case '[':
                return array(depth);
            case '"':
                return string();
            case 't':
                return literal("true");
            case 'f':
                return literal("false");
            case 'n':
                return literal("null");
            default:
                if (peek() == '-' || (peek() >= '0' && peek() <= '9')) return number();
                return fail(std::string("unexpected '") + peek() + "'", "a value");
        }
    }

    bool object(int depth) {
        ++at_;  // {
        skipSpace();
        if (!atEnd() && peek() == '}') return ++at_, true;
        for (;;) {
            skipSpace();
            if (atEnd() || peek() != '"') return fail("expected a name in quotes", "an object");
            const size_t keyStart = at_ + 1;
            if (!string()) return false;
            const std::string_view key = text_.substr(keyStart, at_ - 1 - keyStart);
            skipSpace();
            if (atEnd() || peek() != ':') return fail("expected ':'", "an object");
            ++at_;
            skipSpace();
            const size_t valueStart = at_;
            if (!value(depth + 1)) return false;
            if (extensions_ && depth == 0) {
                if (key == "extensionsUsed") extensions_->used = strings(valueStart);
                if (key == "extensionsRequired") extensions_->required = strings(valueStart);
            }
            skipSpace();
            if (atEnd() || (peek() != ',' && peek() != '}'))
                return fail("expected ',' or '}'", "an object");
            if (text_[at_++] == '}') return true;
        }
    }

    bool array(int depth) {
        ++at_;  // [
        skipSpace();
        if (!atEnd() && peek() == ']') return ++at_, true;
        for (;;) {
            skipSpace();
            if (!value(depth + 1)) return false;
            skipSpace();
            if (atEnd() || (peek() != ',' && peek() != ']'))
                return fail("expected ',' or ']'", "an array");
            if (text_[at_++] == ']') return true;
        }
    }

    bool string() {
        ++at_;  // "
        while (!atEnd()) {
            const unsigned char c = static_cast<unsigned char>(text_[at_]);
            if (c == '"') return ++at_, true;
            if (c < 0x20) return fail("control character inside a string", "a string");
            if (c == '\\') {
                ++at_;
                if (atEnd()) break;
                const char escape = peek();
                if (escape == 'u') {
                    for (int i = 0; i < 4; ++i) {
                        ++at_;
                        if (atEnd()) return fail("", "a string");
                        if (!std::isxdigit(static_cast<unsigned char>(peek())))
                            return fail("bad \\u escape", "a string");
                    }
                } else if (!std::strchr("\"\\/bfnrt", escape)) {
                    return fail(std::string("bad escape '\\") + escape + "'", "a string");
                }
            }
            ++at_;
        }
        return fail("", "a string");
    }

    // The strings of the (checked) value that starts at `from` and ends here, as written: the
    // names of glTF's extension lists need no unescaping.
    std::vector<std::string> strings(size_t from) const {
        std::vector<std::string> out;
        for (size_t i = from; i < at_; ++i) {
            if (text_[i] != '"') continue;
            const size_t end = text_.find('"', i + 1);
            out.emplace_back(text_.substr(i + 1, end - i - 1));
            i = end;
        }
        return out;
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
    GltfExtensions* extensions_;
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

GltfExtensions gltfExtensions(std::string_view bytes) {
    std::string_view json = bytes;
    if (bytes.substr(0, 4) == "glTF") {
        if (glbError(bytes) || bytes.size() < 20) return {};
        json = bytes.substr(20, read32(bytes, 12));
    }
    GltfExtensions extensions;
    if (JsonChecker(json, &extensions).check()) return {};
    return extensions;
}

std::optional<std::string> gltfContainerError(std::string_view bytes) {
    if (bytes.substr(0, 4) == "glTF") return glbError(bytes);
    return jsonSyntaxError(bytes);
}

}  // namespace pbr
