#include "base/error.h"

#include <cstdio>
#include <exception>
#include <new>

namespace pbr {

namespace {
// Keep the promise of one line even when a message carries a newline (a driver's log, say), and
// of a line the terminal shows as it is (no carriage return, escape sequence or bell).
std::string oneLine(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    for (char& c : text) {
        if (c == '\n' || c == '\r') c = ' ';
    }
    return printable(text);
}
}  // namespace

int reportFailure() {
    try {
        throw;
    } catch (const ExitRequest& exit) {
        return exit.code;
    } catch (const UsageError& e) {
        // The usage first and the error last, so the line that says what is wrong is the one
        // nearest the prompt (and what `2>&1 | tail -1` shows).
        if (!e.usage().empty()) std::fprintf(stderr, "%s\n", e.usage().c_str());
        std::fprintf(stderr, "error: %s\n", oneLine(e.what()).c_str());
        return 2;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "error: out of memory\n");
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", oneLine(e.what()).c_str());
        return 1;
    } catch (...) {
        std::fprintf(stderr, "error: unknown failure\n");
        return 1;
    }
}

std::string printable(std::string_view text) {
    std::string out;
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '\n') {
            out += "\\n";
        } else if (c == '\t') {
            out += "\\t";
        } else if (byte < 0x20 || byte == 0x7f) {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\x%02x", unsigned(byte));
            out += escape;
        } else {
            out += c;
        }
    }
    return out;
}

}  // namespace pbr
