// What the build baked from the recipes in resources/ is what the recipe gives, byte for byte,
// and the pictures of it in the READMEs are current.
#include <gtest/gtest.h>
#include <stb_image.h>

#include <cstring>
#include <memory>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "base/paths.h"
#include "files/image.h"
#include "support/build_paths.h"
#include "support/process.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

TEST(Resources, BakingAgainGivesTheBuildsBytes) {
    const fs::path dir = testOutputDir("resources_rebake");
    const RunResult run = runSample(
        {PBR_PATH(PBR_MATERIAL_BAKER), dir.string(), "--size", "1024", "--set", "rusted_iron"});
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
    const std::string committed = readBytes(fs::path(PBR_PATH(PBR_SOURCE_DIR)) /
                                            "samples/02_lighting_textured/contact_sheet.png");
    const std::string built = readBytes(materialDir() / "contact_sheet.png");
    ASSERT_FALSE(built.empty());
    EXPECT_TRUE(committed == built)
        << "samples/02_lighting_textured/contact_sheet.png is out of date: copy it from "
        << materialDir().string();
}

// The HDR environment has real dynamic range and its sun where the recipe puts it.
TEST(Resources, EnvironmentHasASunHundredsOfTimesBrighterThanTheRest) {
    const HdrImage env = readHdr(fs::path(PBR_PATH(PBR_ENVIRONMENT_DIR)) / "sunny_courtyard.hdr");
    ASSERT_EQ(env.width, 2048);
    ASSERT_EQ(env.height, 1024);
    std::vector<float> luminance;
    float brightest = 0.0f;
    for (int y = 0; y < env.height; ++y) {
        for (int x = 0; x < env.width; ++x) {
            const glm::vec3 c = env.at(x, y);
            const float l = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
            luminance.push_back(l);
            brightest = std::max(brightest, l);
        }
    }
    std::nth_element(luminance.begin(), luminance.begin() + luminance.size() / 2, luminance.end());
    const float median = luminance[luminance.size() / 2];
    EXPECT_GT(brightest / median, 1000.0f) << "brightest " << brightest << ", median " << median;
    // the sun's centroid: 35 degrees up (rows from the top: (90 - 35) / 180 of the height),
    // towards -X (left of the centre column), and a disc about 2.6 degrees wide
    double sumX = 0, sumY = 0;
    int count = 0;
    for (int y = 0; y < env.height; ++y) {
        for (int x = 0; x < env.width; ++x) {
            const glm::vec3 c = env.at(x, y);
            if (0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b > 0.5f * brightest)
                sumX += x, sumY += y, ++count;
        }
    }
    EXPECT_NEAR(sumY / count + 0.5, (90.0 - 35.0) / 180.0 * env.height, 1.5);
    EXPECT_LT(sumX / count, env.width / 2.0);
    const double discTexels =
        M_PI * std::pow(1.3 / 180.0 * env.height, 2) / std::cos(35.0 * M_PI / 180.0);
    EXPECT_NEAR(count, discTexels, 0.25 * discTexels);
    // the top row is sky blue, the bottom row is the ground
    EXPECT_GT(env.at(10, 0).b, env.at(10, 0).r);
    EXPECT_GT(env.at(10, env.height - 1).r, env.at(10, env.height - 1).b);
}

TEST(Resources, EnvironmentPictureInTheReadmeIsCurrent) {
    const std::string committed =
        readBytes(fs::path(PBR_PATH(PBR_SOURCE_DIR)) / "samples/04_ibl_irradiance/environment.png");
    const std::string built =
        readBytes(fs::path(PBR_PATH(PBR_ENVIRONMENT_DIR)) / "sunny_courtyard_preview.png");
    ASSERT_FALSE(built.empty());
    EXPECT_TRUE(committed == built) << "samples/04_ibl_irradiance/environment.png is out of date";
}

TEST(Resources, HdrRoundTrip) {
    const fs::path dir = testOutputDir("resources_hdr");
    HdrImage image{3,
                   2,
                   {0.0f, 0.5f, 1.0f, 2.0f, 4.0f, 8.0f, 100.0f, 1000.0f, 5000.0f, 0.25f, 0.125f,
                    0.0625f, 1.0f, 1.0f, 1.0f, 3.0f, 2.0f, 1.0f}};
    writeHdr(dir / "tiny.hdr", image);
    const HdrImage back = readHdr(dir / "tiny.hdr");
    ASSERT_EQ(back.width, 3);
    ASSERT_EQ(back.height, 2);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        // RGBE keeps 8 bits of mantissa relative to the pixel's largest channel
        const float largest = std::max(
            {image.pixels[i / 3 * 3], image.pixels[i / 3 * 3 + 1], image.pixels[i / 3 * 3 + 2]});
        EXPECT_NEAR(back.pixels[i], image.pixels[i], largest / 128.0f) << i;
    }
    std::ofstream(dir / "not.hdr") << "not an hdr\n";
    EXPECT_THROW(readHdr(dir / "not.hdr"), std::exception);
}

// Our Radiance decoder (readHdr) against stb_image's, which it replaces because stb hangs on some
// damaged files: on valid files the two agree to the bit, run-length encoded (the project's
// environment, 2048 wide; a 40-wide image) and flat (widths under 8 are stored uncompressed).
TEST(Resources, HdrDecoderAgreesWithStbOnValidFiles) {
    const fs::path dir = testOutputDir("resources_hdr_decoder");
    HdrImage narrow{5, 3, {}}, wide{40, 7, {}};
    for (HdrImage* image : {&narrow, &wide}) {
        for (int i = 0; i < image->width * image->height * 3; ++i) {
            image->pixels.push_back(float(std::pow(1.37, double(i % 41) - 12.0)) * float(i % 7));
        }
    }
    writeHdr(dir / "narrow.hdr", narrow);
    writeHdr(dir / "wide.hdr", wide);
    for (const fs::path& file : {fs::path(PBR_PATH(PBR_ENVIRONMENT_DIR)) / "sunny_courtyard.hdr",
                                 dir / "narrow.hdr", dir / "wide.hdr"}) {
        const HdrImage ours = readHdr(file);
        int width = 0, height = 0, channels = 0;
        std::unique_ptr<float, void (*)(void*)> theirs(
            stbi_loadf(file.c_str(), &width, &height, &channels, 3), stbi_image_free);
        ASSERT_TRUE(theirs) << file;
        ASSERT_EQ(ours.width, width) << file;
        ASSERT_EQ(ours.height, height) << file;
        EXPECT_EQ(std::memcmp(ours.pixels.data(), theirs.get(), ours.pixels.size() * sizeof(float)),
                  0)
            << file;
    }
}

// Khronos' validator (tests/resources/validate_gltf.js) on one of our own glTF assets, where node
// and the validator are installed (./build.sh installs gltf-validator into build/node-tools when
// npm is there). `skipped` says why it could not run; `run` is what the script printed.
struct ValidatorRun {
    std::string skipped;
    RunResult run;
};
ValidatorRun validateGltf(const fs::path& file, const std::vector<std::string>& flags = {}) {
    const fs::path validator =
        fs::path(PBR_PATH(PBR_NODE_TOOLS_DIR)) / "node_modules" / "gltf-validator";
    const std::optional<fs::path> node = onPath("node");
    if (!node) return {"node is not installed: the glTF validator check is skipped", {}};
    if (!fs::exists(validator)) {
        return {"gltf-validator is not installed in " + std::string(PBR_PATH(PBR_NODE_TOOLS_DIR)) +
                    " (./build.sh installs it with npm): the check is skipped",
                {}};
    }
    std::vector<std::string> argv = {
        node->string(),
        (fs::path(PBR_PATH(PBR_SOURCE_DIR)) / "tests/resources/validate_gltf.js").string(),
        validator.string(), file.string()};
    argv.insert(argv.end(), flags.begin(), flags.end());
    return {"", runSample(argv)};
}

TEST(Resources, ShowcaseGltfPassesKhronosValidator) {
    const ValidatorRun v = validateGltf(modelDir() / "unlit_showcase.gltf");
    if (!v.skipped.empty()) GTEST_SKIP() << v.skipped;
    EXPECT_EQ(v.run.exitCode, 0) << v.run.out << v.run.err;
    EXPECT_NE(v.run.out.find("errors 0 "), std::string::npos) << v.run.out;
    std::printf("gltf-validator: %s", v.run.out.c_str());
}

// Sample 07's asset: no errors and no warnings (--strict makes every warning count). Infos and
// hints are printed. The renderer's own tangents are tested on a file of the test's making
// (GltfFeatures.MissingTangentsAreMadeAlongTheTextureCoordinates).
TEST(Resources, PbrShowcaseGltfPassesKhronosValidatorWithoutWarnings) {
    const ValidatorRun v = validateGltf(modelDir() / "pbr_showcase.gltf", {"--strict"});
    if (!v.skipped.empty()) GTEST_SKIP() << v.skipped;
    EXPECT_EQ(v.run.exitCode, 0) << v.run.out << v.run.err;
    EXPECT_NE(v.run.out.find("errors 0 "), std::string::npos) << v.run.out;
    EXPECT_NE(v.run.out.find("unexpected warnings 0\n"), std::string::npos) << v.run.out;
    std::printf("gltf-validator: %s", v.run.out.c_str());
}

// Sample 08's asset in its four files (both halves, the required copy, each half alone): no
// errors, no warnings.
TEST(Resources, PbrWorkflowsGltfPassesKhronosValidatorWithoutWarnings) {
    for (const char* file : {"pbr_workflows.gltf", "pbr_workflows_required.gltf",
                             "pbr_workflows_mr.gltf", "pbr_workflows_sg.gltf"}) {
        const ValidatorRun v = validateGltf(modelDir() / file, {"--strict"});
        if (!v.skipped.empty()) GTEST_SKIP() << v.skipped;
        EXPECT_EQ(v.run.exitCode, 0) << file << v.run.out << v.run.err;
        EXPECT_NE(v.run.out.find("errors 0 "), std::string::npos) << file << v.run.out;
        EXPECT_NE(v.run.out.find("unexpected warnings 0\n"), std::string::npos)
            << file << v.run.out;
        std::printf("gltf-validator %s: %s", file, v.run.out.c_str());
    }
}

// Sample 10's asset, every layer's extension in it: no errors, no warnings.
TEST(Resources, AdvancedMaterialsGltfPassesKhronosValidatorWithoutWarnings) {
    const ValidatorRun v = validateGltf(modelDir() / "advanced_materials.gltf", {"--strict"});
    if (!v.skipped.empty()) GTEST_SKIP() << v.skipped;
    EXPECT_EQ(v.run.exitCode, 0) << v.run.out << v.run.err;
    EXPECT_NE(v.run.out.find("errors 0 "), std::string::npos) << v.run.out;
    EXPECT_NE(v.run.out.find("unexpected warnings 0\n"), std::string::npos) << v.run.out;
    std::printf("gltf-validator advanced_materials.gltf: %s", v.run.out.c_str());
}

}  // namespace
}  // namespace pbr::test
