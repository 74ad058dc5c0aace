// Every sample, on every offscreen backend: a headless run exits 0 with zero GL errors (KHR_debug
// reports them where the driver has it, glGetError elsewhere) and leaks no GL object (the App
// asks GL about every name at exit). On the software backends the golden tests check the same in
// each sample's default picture (Backends/GoldenImage.MatchesGolden, expectCleanRun): the runs
// here are on the backends that have no golden: --backend egl, a GPU where there is one.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "context/context.h"
#include "support/golden.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> sampleNames() {
    std::vector<std::string> names;
    std::istringstream list(PBR_SAMPLE_LIST);
    std::string name;
    while (std::getline(list, name, ',')) names.push_back(name);
    return names;
}

using SampleOnBackend = std::tuple<std::string, std::string>;

class EverySample : public ::testing::TestWithParam<SampleOnBackend> {};

TEST_P(EverySample, RunsCleanHeadless) {
    const auto& [sample, backend] = GetParam();
    const fs::path dir = testOutputDir("samples_" + sample + "_" + backend);
    const SampleRender render =
        renderSample(sample, dir / (sample + ".png"), {"--size", "320x180", "--backend", backend});
    if (const auto reason = backendUnavailable(render.run, backend)) GTEST_SKIP() << *reason;
    EXPECT_EQ(render.run.exitCode, 0) << render.run.err;
    EXPECT_EQ(render.run.err.find("GL error"), std::string::npos) << render.run.err;
    EXPECT_EQ(render.run.err.find("leaked"), std::string::npos) << render.run.err;
    EXPECT_TRUE(fs::exists(render.image));
}

// Every sample on every backend the golden tests do not draw on.
std::vector<SampleOnBackend> samplesOnBackends() {
    const std::vector<std::string> software = softwareBackends();
    std::vector<SampleOnBackend> runs;
    for (const std::string& sample : sampleNames()) {
        for (const std::string& backend : offscreenBackends()) {
            if (std::find(software.begin(), software.end(), backend) == software.end()) {
                runs.emplace_back(sample, backend);
            }
        }
    }
    return runs;
}

// (none in a build whose backends are all software)
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(EverySample);
INSTANTIATE_TEST_SUITE_P(All, EverySample, ::testing::ValuesIn(samplesOnBackends()),
                         [](const auto& info) {
                             return std::get<0>(info.param) + "_" +
                                    paramName(std::get<1>(info.param));
                         });

}  // namespace
}  // namespace pbr::test
