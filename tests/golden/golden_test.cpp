// Golden images of the samples, and the proofs that the comparison means something: it rejects a
// small change, headless output repeats bit for bit, and MSAA changes edges only.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <tuple>

#include "base/paths.h"
#include "context/context.h"
#include "support/build_paths.h"
#include "support/golden.h"
#include "support/golden_cases.h"
#include "support/test_data.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

// A sample's headless run must succeed with zero GL errors reported and no GL object leaked.
void expectCleanRun(const SampleRender& render) {
    EXPECT_EQ(render.run.exitCode, 0) << render.run.err;
    EXPECT_EQ(render.run.err.find("GL error"), std::string::npos) << render.run.err;
    EXPECT_EQ(render.run.err.find("leaked"), std::string::npos) << render.run.err;
    EXPECT_FALSE(render.renderer.empty()) << "no 'wrote' line in: " << render.run.out;
}

// The picture is not blank: at least `minShare` of the pixels differ from the top-left corner
// (the clear colour) by more than a few levels.
void expectNotBlank(const Image& image, double minShare) {
    EXPECT_GT(double(pixelsUnlikeCorner(image)) / (double(image.width) * image.height), minShare);
}

class GoldenImage : public ::testing::TestWithParam<std::tuple<GoldenCase, std::string>> {};

TEST_P(GoldenImage, MatchesGolden) {
    const auto& [golden, backend] = GetParam();
    if (golden.needsAssimpModels) {
        PBR_NEED_ASSIMP_MODELS(models);
    }
    const fs::path dir = testOutputDir("golden_" + golden.golden + "_" + backend);
    std::string unavailable;
    auto render = [&](std::vector<std::string> args, const std::string& file) {
        args.insert(args.end(), {"--backend", backend});
        const SampleRender rendered = renderSample(golden.sample, dir / file, args);
        if (const auto reason = backendUnavailable(rendered.run, backend)) {
            unavailable = *reason;
            return rendered;
        }
        expectCleanRun(rendered);
        EXPECT_EQ(rendered.backend.rfind(backend, 0), 0u) << rendered.backend;
        return rendered;
    };
    const SampleRender rendered = render(golden.args, golden.golden + ".png");
    if (!unavailable.empty()) GTEST_SKIP() << unavailable;
    if (golden.minNonBlank > 0.0) expectNotBlank(readImage(rendered.image, 3), golden.minNonBlank);
    EXPECT_TRUE(matchesGolden(golden.golden, rendered)) << "the sample printed:\n"
                                                        << rendered.run.err;
    const std::string bytes = readBytes(rendered.image);
    for (size_t i = 0; i < golden.sameBytesAs.size(); ++i) {
        const SampleRender other =
            render(golden.sameBytesAs[i], "same" + std::to_string(i) + ".png");
        auto joined = [](const std::vector<std::string>& args) {
            std::string text;
            for (const std::string& arg : args) text += (text.empty() ? "" : " ") + arg;
            return text.empty() ? std::string("(no flags)") : text;
        };
        EXPECT_TRUE(readBytes(other.image) == bytes)
            << joined(golden.sameBytesAs[i]) << " draws differently from " << joined(golden.args);
    }
}

// Where each golden is drawn: every case on the first offscreen software backend this build has;
// on the others, the default pictures of the two glTF samples whose targets differ most (07's
// sRGB one, 10's with its half-float backdrop and its mips), which run all of a backend's own code
// (its context, its read-back): the flags and the sample choose what is drawn, not where, on one
// machine the backends give the same bytes (Golden.BackendsGiveTheSamePixels), and every sample
// runs clean on EGL (EverySample.RunsCleanHeadless). (Each sample's default on every backend
// cost 9 more runs, about 7 test-seconds, for no line of ours the others do not run.)
std::vector<std::tuple<GoldenCase, std::string>> goldenRuns() {
    const std::vector<std::string> backends = softwareBackends();
    std::vector<std::tuple<GoldenCase, std::string>> runs;
    for (const GoldenCase& golden : goldenCases()) {
        const bool everywhere =
            golden.args.empty() && (golden.golden == "07_gltf_metallic_roughness" ||
                                    golden.golden == "10_gltf_advanced_materials");
        for (size_t i = 0; i < backends.size(); ++i) {
            if (i == 0 || everywhere) runs.emplace_back(golden, backends[i]);
        }
    }
    return runs;
}

INSTANTIATE_TEST_SUITE_P(Backends, GoldenImage, ::testing::ValuesIn(goldenRuns()),
                         [](const auto& info) {
                             return std::get<0>(info.param).golden + "_" +
                                    paramName(std::get<1>(info.param));
                         });

// The table and the folder agree: every golden picture (with its .json) has a case, and every
// case has its picture. A golden without a case would never be checked or rewritten.
TEST(Golden, EveryGoldenFileHasACase) {
    const GoldenFolder folder = goldenFolder(PBR_PATH(PBR_GOLDEN_DIR), goldenCases());
    EXPECT_EQ(folder.pictures, folder.cases);
    EXPECT_EQ(folder.metadata, folder.cases);
}

// On one machine the backends give the same pixels, bit for bit (both are llvmpipe here).
TEST(Golden, BackendsGiveTheSamePixels) {
    const std::vector<std::string> backends = softwareBackends();
    if (backends.size() < 2) GTEST_SKIP() << "this build has one offscreen backend";
    const fs::path dir = testOutputDir("golden_backends");
    std::string first;
    for (const std::string& backend : backends) {
        const SampleRender render = renderSample("01_lighting", dir / (backend + ".png"),
                                                 {"--size", "640x360", "--backend", backend});
        if (const auto reason = backendUnavailable(render.run, backend)) GTEST_SKIP() << *reason;
        expectCleanRun(render);
        const std::string bytes = readBytes(render.image);
        ASSERT_FALSE(bytes.empty());
        if (first.empty())
            first = bytes;
        else
            EXPECT_TRUE(bytes == first) << backend << " differs from " << backends[0];
    }
}

// The gate must catch a small, real change: roughness + 0.05 on every sphere, or one light of the
// four gone; the unchanged render (the test above) passes it.
TEST(Golden, GateRejectsSmallChanges) {
    const fs::path dir = testOutputDir("golden_gate");
    const Image golden = readImage(fs::path(PBR_PATH(PBR_GOLDEN_DIR)) / "01_lighting.png", 3);
    const GoldenGate gate;

    auto verdictFor = [&](const std::string& file, const std::vector<std::string>& args) {
        const SampleRender render = renderSample("01_lighting", dir / file, args);
        expectCleanRun(render);
        const GoldenVerdict verdict = judge(readImage(render.image, 3), golden, gate);
        std::printf("%s: %s\n", file.c_str(), verdict.summary.c_str());
        return verdict;
    };
    const GoldenVerdict fresh = verdictFor("fresh.png", {});
    EXPECT_TRUE(fresh.pass) << fresh.summary;
    const GoldenVerdict rougher = verdictFor("rougher.png", {"--roughness-offset", "0.05"});
    EXPECT_FALSE(rougher.pass) << "roughness + 0.05 passed the gate: " << rougher.summary;
    const GoldenVerdict threeLights = verdictFor("three-lights.png", {"--lights", "3"});
    EXPECT_FALSE(threeLights.pass) << "a missing light passed the gate: " << threeLights.summary;
}

// Files written by others render: not blank, no GL error.
TEST(Golden, RealGltfFilesRender) {
    const fs::path dir = testOutputDir("golden_real_gltf");
    PBR_NEED_ASSIMP_MODELS(models);
    for (const char* file :
         {"2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "ClearCoat-glTF/ClearCoatTest.gltf",
          "BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf"}) {
        const SampleRender render =
            renderSample("03_gltf_unlit", dir / (fs::path(file).stem().string() + ".png"),
                         {"--model", (models / file).string(), "--size", "480x270"});
        expectCleanRun(render);
        expectNotBlank(readImage(render.image, 3), 0.02);
    }
}

// The sphere's own tangent frame and the text's screen-space one describe the same surface: the
// pictures agree but for the derivative frame's per-quad steps (a flipped bitangent would put
// about 9 % of the pixels off).
TEST(Golden, TangentFramesAgree) {
    const fs::path dir = testOutputDir("golden_tangent_frames");
    const std::vector<std::string> view = {"--size", "640x360", "--camera", "0,0,3"};
    auto with = [&](const std::string& frame) {
        std::vector<std::string> args = view;
        args.insert(args.end(), {"--tangent-frame", frame});
        const SampleRender render =
            renderSample("02_lighting_textured", dir / (frame + ".png"), args);
        expectCleanRun(render);
        return readImage(render.image, 3);
    };
    const ImageDiff diff = compareImages(with("mesh"), with("derivatives"), 2);
    EXPECT_LT(diff.fractionOverThreshold, 0.005)
        << "max " << diff.maxChannelDiff << ", PSNR " << diff.psnr;
    EXPECT_GT(diff.psnr, 50.0);
}

// (at 320x180: what makes two runs differ is not the picture's size)
// The test presets run llvmpipe with LLVM's optimiser off (GALLIVM_PERF=nopt, CMakePresets.json:
// a test draws a frame or a few, and the optimiser took more time than it saved); a user's run
// has it on. The second run of each pair is a user's, so the same bytes also prove that the
// goldens are what users get.
TEST(Golden, HeadlessOutputIsBitIdentical) {
    const fs::path dir = testOutputDir("golden_determinism");
    const std::vector<std::string> args = {"--size", "320x180"};
    for (const std::string sample : {"01_lighting", "02_lighting_textured", "03_gltf_unlit",
                                     "04_ibl_irradiance", "05_ibl_specular", "06_brdf_lut",
                                     "07_gltf_metallic_roughness", "10_gltf_advanced_materials"}) {
        const SampleRender first = renderSample(sample, dir / (sample + ".first.png"), args);
        const SampleRender second = renderSample(sample, dir / (sample + ".second.png"), args,
                                                 {.unsetEnv = {"GALLIVM_PERF"}});
        expectCleanRun(first);
        expectCleanRun(second);
        const std::string a = readBytes(first.image), b = readBytes(second.image);
        ASSERT_FALSE(a.empty());
        EXPECT_TRUE(a == b) << sample << ": two headless renders differ in their bytes (the "
                            << "second with the test environment's GALLIVM_PERF unset)";
    }
}

// Headless MSAA is real: with 4 samples the picture changes, and only at edges (where the
// single-sample render jumps between neighbouring pixels).
TEST(Golden, MsaaSmoothsEdgesOnly) {
    const fs::path dir = testOutputDir("golden_msaa");
    const SampleRender off =
        renderSample("01_lighting", dir / "off.png", {"--size", "640x360", "--msaa", "0"});
    const SampleRender on =
        renderSample("01_lighting", dir / "on.png", {"--size", "640x360", "--msaa", "4"});
    expectCleanRun(off);
    expectCleanRun(on);
    const Image a = readImage(off.image, 3), b = readImage(on.image, 3);
    size_t changed = 0, changedAwayFromEdges = 0;
    for (int y = 1; y + 1 < a.height; ++y) {
        for (int x = 1; x + 1 < a.width; ++x) {
            int diff = 0;
            for (int c = 0; c < 3; ++c)
                diff = std::max(diff, std::abs(int(a.at(x, y, c)) - int(b.at(x, y, c))));
            if (diff <= 2) continue;
            ++changed;
            int spread = 0;  // the largest step to a neighbour in the single-sample picture
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    for (int c = 0; c < 3; ++c)
                        spread = std::max(
                            spread, std::abs(int(a.at(x + dx, y + dy, c)) - int(a.at(x, y, c))));
            if (spread < 6) ++changedAwayFromEdges;
        }
    }
    EXPECT_GT(changed, 500u) << "4x MSAA changed almost nothing";
    EXPECT_LT(double(changed) / (double(a.width) * a.height), 0.05)
        << "MSAA changed more than edges";
    EXPECT_LT(double(changedAwayFromEdges), 0.02 * double(changed)) << "MSAA changed flat areas";
}

}  // namespace
}  // namespace pbr::test
