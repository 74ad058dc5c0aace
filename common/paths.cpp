#include "paths.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "error.h"

namespace pbr {

namespace fs = std::filesystem;

namespace {
fs::path fromEnvOr(const char* variable, const char* fallback) {
    const char* value = std::getenv(variable);
    return fs::path(value && *value ? value : fallback);
}
}  // namespace

fs::path shaderDir() {
    return fromEnvOr("PBR_SHADER_DIR", PBR_SHADER_DIR);
}
fs::path resourceDir() {
    return fromEnvOr("PBR_RESOURCE_DIR", PBR_RESOURCE_DIR);
}
fs::path materialDir() {
    return fromEnvOr("PBR_MATERIAL_DIR", PBR_MATERIAL_DIR);
}
fs::path modelDir() {
    return fromEnvOr("PBR_MODEL_DIR", PBR_MODEL_DIR);
}
fs::path environmentDir() {
    return fromEnvOr("PBR_ENVIRONMENT_DIR", PBR_ENVIRONMENT_DIR);
}

std::string displayPath(const fs::path& path) {
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    if (ec) return path.string();
    absolute = absolute.lexically_normal();
    fs::path relative = absolute.lexically_relative(fs::current_path(ec));
    if (!ec && !relative.empty() && *relative.begin() != "..") return relative.string();
    return absolute.string();
}

std::string readTextFile(const fs::path& path) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw Error(displayPath(path) + ": is a directory, not a file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(displayPath(path) + ": cannot open: " + std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw Error(displayPath(path) + ": read failed");
    return text.str();
}

}  // namespace pbr
