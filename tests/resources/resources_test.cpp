// What the build baked from the recipes in resources/ is what the recipe gives, byte for byte,
// and the pictures of it in the READMEs are current.
#include <gtest/gtest.h>

#include <fstream>

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

}  // namespace
}  // namespace pbr::test
