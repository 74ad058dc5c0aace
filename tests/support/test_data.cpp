#include "support/test_data.h"

namespace pbr::test {

std::optional<std::filesystem::path> assimpGltfModels() {
    const std::filesystem::path dir = "/usr/share/assimp/models/glTF2";
    std::error_code ec;
    if (std::filesystem::is_directory(dir / "BoxTextured-glTF", ec)) return dir;
    return std::nullopt;
}

}  // namespace pbr::test
