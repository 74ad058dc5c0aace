#pragma once
// Where the executables find their data, from any working directory, and the environment
// variables that move it. Pure: no GL.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pbr {

// shaders/ of the source tree, or $PBR_SHADER_DIR when set.
std::filesystem::path shaderDir();
// The assets the build makes from the recipes in resources/ (build/<preset>/resources), or
// $PBR_RESOURCE_DIR when set; it holds materials/, models/ and environments/.
std::filesystem::path resourceDir();
std::filesystem::path materialDir();     // resourceDir() / "materials": the PBR material sets
std::filesystem::path modelDir();        // resourceDir() / "models": the project's glTF assets
std::filesystem::path environmentDir();  // resourceDir() / "environments": its HDR environments
std::filesystem::path iblDir();          // resourceDir() / "ibl": the BRDF LUTs the build bakes
// Where the IBL samples keep their precomputed maps: $PBR_CACHE_DIR, else
// $XDG_CACHE_HOME/pbr-samples, else $HOME/.cache/pbr-samples (on Windows
// %LOCALAPPDATA%\pbr-samples); nullopt when none is set.
std::optional<std::filesystem::path> defaultCacheDir();

// Whether a window needs a display named in the environment (DISPLAY or WAYLAND_DISPLAY), as on
// X11 and Wayland; Windows and macOS always have their desktop, and have no such variable.
#if defined(_WIN32) || defined(__APPLE__)
inline constexpr bool kDisplayVariables = false;
#else
inline constexpr bool kDisplayVariables = true;
#endif

// Every environment variable the samples read, with what it does, for --help and the README.
struct EnvironmentVariable {
    std::string name;
    std::string meaning;
};
std::vector<EnvironmentVariable> environmentVariables();

// A path as a user wants to read it in a message: relative to the working directory when it lies
// below it, absolute otherwise; one line (control characters escaped, as printable() does).
std::string displayPath(const std::filesystem::path& path);
// The path in UTF-8, as libraries that take a char path (Assimp) expect on every platform.
std::string utf8Path(const std::filesystem::path& path);
// A path from UTF-8 text (a glTF file's uri, a flag), on every platform.
std::filesystem::path pathFromUtf8(std::string_view text);
// The whole file as a string; throws Error("<path>: <reason>").
std::string readTextFile(const std::filesystem::path& path);

}  // namespace pbr
