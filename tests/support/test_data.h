#pragma once
// Test data from packages a machine may lack, found or skipped visibly: a test that needs it says
// GTEST_SKIP with the package's name instead of failing on a missing file.
#include <filesystem>
#include <optional>

#include <gtest/gtest.h>

namespace pbr::test {

// Debian's assimp-testmodels glTF 2.0 corpus (/usr/share/assimp/models/glTF2), when installed.
std::optional<std::filesystem::path> assimpGltfModels();

}  // namespace pbr::test

// Declares `name` as the corpus folder, or skips the test, saying why.
#define PBR_NEED_ASSIMP_MODELS(name)                                                          \
    const std::optional<std::filesystem::path> name##Found = ::pbr::test::assimpGltfModels(); \
    if (!name##Found)                                                                         \
        GTEST_SKIP() << "assimp-testmodels is not installed (no "                             \
                     << "/usr/share/assimp/models/glTF2): this test needs its glTF files";    \
    const std::filesystem::path name = *name##Found
