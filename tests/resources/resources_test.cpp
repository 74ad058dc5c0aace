// What the build baked from the recipes in resources/ is what the recipe gives, byte for byte,
// and the pictures of it in the READMEs are current.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "paths.h"
#include "support/process.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

TEST(Resources, BakingAgainGivesTheBuildsBytes) {
    const fs::path dir = testOutputDir("resources_rebake");
    const RunResult run =
        runSample({PBR_MATERIAL_BAKER, dir.string(), "--size", "1024", "--set", "rusted_iron"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    for (const char* map : {"albedo", "normal", "metallic", "roughness", "ao"}) {
        const std::string fresh = readBytes(dir / "rusted_iron" / (std::string(map) + ".png"));
        const std::string built =
            readBytes(materialDir() / "rusted_iron" / (std::string(map) + ".png"));
        ASSERT_FALSE(fresh.empty()) << map;
        EXPECT_TRUE(fresh == built) << map << ".png differs from the build's";
    }
}

TEST(Resources, ContactSheetInTheReadmeIsCurrent) {
    const std::string committed =
        readBytes(fs::path(PBR_SOURCE_DIR) / "samples/02_lighting_textured/contact_sheet.png");
    const std::string built = readBytes(materialDir() / "contact_sheet.png");
    ASSERT_FALSE(built.empty());
    EXPECT_TRUE(committed == built)
        << "samples/02_lighting_textured/contact_sheet.png is out of date: copy it from "
        << materialDir().string();
}

// Khronos' validator on our own glTF asset, where node and the validator are installed
// (./build.sh installs gltf-validator into build/node-tools when npm is there).
TEST(Resources, ShowcaseGltfPassesKhronosValidator) {
    const fs::path validator = fs::path(PBR_NODE_TOOLS_DIR) / "node_modules" / "gltf-validator";
    std::string nodePath;  // the first node on PATH
    std::istringstream path(std::getenv("PATH") ? std::getenv("PATH") : "");
    for (std::string dir; nodePath.empty() && std::getline(path, dir, ':');) {
        if (!dir.empty() && fs::exists(fs::path(dir) / "node"))
            nodePath = (fs::path(dir) / "node").string();
    }
    if (nodePath.empty())
        GTEST_SKIP() << "node is not installed: the glTF validator check is skipped";
    if (!fs::exists(validator)) {
        GTEST_SKIP() << "gltf-validator is not installed in " << PBR_NODE_TOOLS_DIR
                     << " (./build.sh installs it with npm): the check is skipped";
    }
    const RunResult run =
        runSample({nodePath, fs::path(PBR_SOURCE_DIR "/tests/resources/validate_gltf.js").string(),
                   validator.string(), (modelDir() / "unlit_showcase.gltf").string()});
    EXPECT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_NE(run.out.find("errors 0 "), std::string::npos) << run.out;
    std::printf("gltf-validator: %s", run.out.c_str());
}

}  // namespace
}  // namespace pbr::test
