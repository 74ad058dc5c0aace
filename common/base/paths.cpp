#include "base/paths.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "base/error.h"

namespace pbr {

namespace fs = std::filesystem;

namespace {
const char* variable(const char* name) {
    const char* value = std::getenv(name);
    return value && *value ? value : nullptr;
}
// The environment's text is UTF-8 on every platform (on Windows by the samples' manifest,
// cmake/windows.manifest), as the flags are.
fs::path fromEnvOr(const char* name, const char* fallback) {
    const char* value = variable(name);
    return pathFromUtf8(value ? value : fallback);
}
}  // namespace

fs::path shaderDir() {
    return fromEnvOr("PBR_SHADER_DIR", PBR_SHADER_DIR);
}
fs::path resourceDir() {
    return fromEnvOr("PBR_RESOURCE_DIR", PBR_RESOURCE_DIR);
}
fs::path materialDir() {
    return resourceDir() / "materials";
}
fs::path modelDir() {
    return resourceDir() / "models";
}
fs::path environmentDir() {
    return resourceDir() / "environments";
}
fs::path iblDir() {
    return resourceDir() / "ibl";
}

std::optional<fs::path> defaultCacheDir() {
    if (const char* dir = variable("PBR_CACHE_DIR")) return pathFromUtf8(dir);
#if defined(_WIN32)
    // Windows' place for a program's data that is not roamed to other machines
    if (const char* dir = variable("LOCALAPPDATA")) return pathFromUtf8(dir) / "pbr-samples";
#else
    if (const char* dir = variable("XDG_CACHE_HOME")) return pathFromUtf8(dir) / "pbr-samples";
    if (const char* home = variable("HOME")) return pathFromUtf8(home) / ".cache" / "pbr-samples";
#endif
    return std::nullopt;
}

std::vector<EnvironmentVariable> environmentVariables() {
    std::vector<EnvironmentVariable> variables{
        // The defaults in words, not as the build's paths: a checkout's path is as long as its
        // owner made it, and the usage must read the same from any of them.
        {"PBR_SHADER_DIR", "the GLSL files (default: shaders/ of the source tree built)"},
        {"PBR_RESOURCE_DIR",
         "the assets the build makes: materials/, models/, environments/ (default: the "
         "build's resources/ folder)"},
        {"PBR_CACHE_DIR",
         "the IBL samples' precomputed maps (default: "
         "$XDG_CACHE_HOME/pbr-samples, else $HOME/.cache/pbr-samples; on Windows "
         "%LOCALAPPDATA%\\pbr-samples)"},
    };
    if (kDisplayVariables) {
        variables.push_back({"DISPLAY, WAYLAND_DISPLAY",
                             "a window needs one of them; without, the sample renders "
                             "offscreen and says so"});
    }
    variables.push_back({"PBR_PANEL_SCRIPT",
                         "the tests' way to drive the live panel headless: a file of the mouse in "
                         "each frame, \"x y button\" or \"-\" a line"});
    return variables;
}

std::string displayPath(const fs::path& path) {
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    if (ec) return printable(path.string());
    absolute = absolute.lexically_normal();
    fs::path relative = absolute.lexically_relative(fs::current_path(ec));
    if (!ec && !relative.empty() && *relative.begin() != "..") return printable(relative.string());
    return printable(absolute.string());
}

std::string utf8Path(const fs::path& path) {
    const std::u8string text = path.u8string();
    return std::string(text.begin(), text.end());
}

fs::path pathFromUtf8(std::string_view text) {
    return fs::path(std::u8string(text.begin(), text.end()));
}

std::string readTextFile(const fs::path& path) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (fs::is_directory(status)) throw Error(displayPath(path) + ": is a directory, not a file");
    // A device or a pipe has no end to read to (/dev/zero, /dev/urandom: the fuzzing of shader
    // includes found it, reading until memory ran out): files only.
    if (fs::exists(status) && !fs::is_regular_file(status)) {
        throw Error(displayPath(path) + ": not a file (a device, a pipe or a socket)");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(displayPath(path) + ": cannot open: " + std::strerror(errno));
    // One read of the whole size (a stream copied through its buffer took 0.25 s for 1.6 MB in
    // a page); a file still growing or shrinking is read to its end.
    std::string text;
    const std::uintmax_t size = fs::file_size(path, ec);
    if (!ec && size < std::uintmax_t(std::numeric_limits<std::streamsize>::max())) {
        text.resize(size_t(size));
        in.read(text.data(), std::streamsize(size));
        text.resize(size_t(in.gcount()));
        if (in.bad()) throw Error(displayPath(path) + ": read failed");
        if (in.eof()) return text;
        in.clear();
    }
    std::ostringstream rest;
    rest << in.rdbuf();
    if (in.bad()) throw Error(displayPath(path) + ": read failed");
    return text + rest.str();
}

}  // namespace pbr
