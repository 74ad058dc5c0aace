#pragma once
// The error policy of the suite: every failure is one line that names the thing and the reason,
// and a non-zero exit code. Code throws; a sample's main() ends in `catch (...) { return
// pbr::reportFailure(); }`, which prints that line and picks the exit code.
#include <stdexcept>
#include <string>
#include <string_view>

namespace pbr {

// A runtime failure (missing file, bad shader, no context): exit code 1.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A bad command line: the usage, then the message as the last line; exit code 2.
class UsageError : public Error {
public:
    UsageError(const std::string& message, std::string usage)
        : Error(message), usage_(std::move(usage)) {}
    const std::string& usage() const { return usage_; }

private:
    std::string usage_;
};

// Not a failure: a clean early exit (after --help) that still unwinds every RAII object.
struct ExitRequest {
    int code = 0;
};

// Prints the current exception as one line on stderr ("error: ...") and returns the exit code.
// Call it only inside a catch block.
int reportFailure();

// `text` (a name read from a file, an argument) as a one-line message shows it: control
// characters written as escapes ("\n", "\t", "\x01"), everything else as it is.
std::string printable(std::string_view text);

}  // namespace pbr
