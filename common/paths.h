#pragma once
// Where the executables find their data, from any working directory.
#include <filesystem>
#include <string>

namespace pbr {

// shaders/ of the source tree, or $PBR_SHADER_DIR when set.
std::filesystem::path shaderDir();
// resources/ of the source tree, or $PBR_RESOURCE_DIR when set.
std::filesystem::path resourceDir();
// The material sets the build bakes (build/.../resources/materials), or $PBR_MATERIAL_DIR.
std::filesystem::path materialDir();
// The models the build writes (build/.../resources/models), or $PBR_MODEL_DIR.
std::filesystem::path modelDir();
// The HDR environments the build writes (build/.../resources/environments), or
// $PBR_ENVIRONMENT_DIR.
std::filesystem::path environmentDir();
// A path as a user wants to read it in a message: relative to the working directory when it lies
// below it, absolute otherwise.
std::string displayPath(const std::filesystem::path& path);
// The whole file as a string; throws Error("<path>: <reason>").
std::string readTextFile(const std::filesystem::path& path);

}  // namespace pbr
