#pragma once
// What every fuzz target of tests/fuzz checks, the contract that makes a finding: a reader given
// any bytes either returns a value that keeps its format's promises, or throws pbr::Error (a
// command line: pbr::UsageError) whose message is one line naming the input. Anything else (an
// exception of another type such as std::bad_alloc or std::out_of_range, a message of several
// lines or one that does not say which input, a broken promise) is printed and abort()s, which
// libFuzzer records as a crash with its input, and the replay driver (replay_main.cpp) as a
// failed test. AddressSanitizer and UBSan add their own findings to these.
#include <cxxabi.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>
#include <typeinfo>
#include <vector>

#include "base/error.h"

namespace pbr::fuzz {

// The input as the readers take it.
inline std::string_view bytesOf(const std::uint8_t* data, size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

// `text` cut at every `separator` (a command line at '\0', names at '\n'); an empty text is no
// parts, and a separator at the end starts no part after it.
inline std::vector<std::string> split(std::string_view text, char separator) {
    std::vector<std::string> parts;
    for (size_t at = 0; at < text.size();) {
        const size_t end = std::min(text.find(separator, at), text.size());
        parts.emplace_back(text.substr(at, end - at));
        at = end + 1;
    }
    return parts;
}

// A type's name as the source spells it ("pbr::Error", "std::bad_alloc").
inline std::string typeName(const std::type_info& type) {
    int status = 0;
    char* name = abi::__cxa_demangle(type.name(), nullptr, nullptr, &status);
    const std::string readable = status == 0 && name ? name : type.name();
    std::free(name);
    return readable;
}

// A finding: says what, then abort() (libFuzzer keeps the input that did it).
[[noreturn]] inline void finding(const std::string& what) {
    std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

// A promise of the format that a returned value must keep.
inline void expect(bool kept, const std::string& promise) {
    if (!kept) finding("the reader returned a value that breaks a promise: " + promise);
}

inline bool finite(float value) {
    return std::isfinite(value);
}

// A refusal's message: one line, and it names the input (`name`; empty: not checked) and says
// more than that.
inline void expectOneLine(const std::string& message, const std::string& name) {
    if (message.find('\n') != std::string::npos) finding("a message of several lines: " + message);
    // a carriage return, an escape sequence or a bell would garble the line it is printed on
    if (std::any_of(message.begin(), message.end(),
                    [](char c) { return (unsigned char)c < 0x20 || c == 0x7f; }))
        finding("a message with a control character: " + printable(message));
    if (!name.empty() && message.find(name) == std::string::npos)
        finding("a message that does not name '" + name + "': " + message);
    if (message.size() <= name.size() + 2) finding("a message without a reason: " + message);
}

// Runs `read()`: true when it returned, false when it refused as the contract allows (a
// `Refusal` whose message is one line naming `name`). Anything else is a finding.
template <typename Refusal = Error, typename Read>
bool reads(const std::string& name, Read&& read) {
    try {
        read();
        return true;
    } catch (const Refusal& refusal) {
        expectOneLine(refusal.what(), name);
        return false;
    } catch (const std::exception& e) {
        finding("not a " + typeName(typeid(Refusal)) + " but " + typeName(typeid(e)) + ": " +
                e.what());
    } catch (...) {
        finding("an exception that is no std::exception");
    }
}

}  // namespace pbr::fuzz
