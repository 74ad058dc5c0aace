#pragma once
// Golden images: render a sample headless, compare with tests/golden/<name>.png under a gate,
// and on failure leave the actual, expected and amplified difference pictures for a person.
//
// Goldens change only on purpose: run the golden tests with PBR_UPDATE_GOLDENS=1, look at the new
// pictures, and say why in the commit.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image.h"
#include "support/process.h"

namespace pbr::test {

// The tolerance gate. A pixel "differs" when any colour channel is off by more than
// channelThreshold levels; the image passes when few pixels differ and the PSNR stays high.
// Tight enough that roughness + 0.05 or a missing light fails; loose enough for the last-bit
// rounding of another Mesa/LLVM build at anti-aliased edges.
struct GoldenGate {
    int channelThreshold = 2;
    double maxFractionOver = 0.001;  // 0.1 % of the pixels
    double minPsnr = 45.0;           // dB
};

struct GoldenVerdict {
    bool pass = false;
    ImageDiff diff;
    std::string summary;  // the metrics against the thresholds, one line
};
GoldenVerdict judge(const Image& actual, const Image& expected, const GoldenGate& gate);

struct SampleRender {
    RunResult run;
    std::filesystem::path image;
    std::string renderer;  // from the sample's "wrote ..." line
};
// Runs `sample --headless --output <output> <args...>`.
SampleRender renderSample(const std::string& sample, const std::filesystem::path& output,
                          const std::vector<std::string>& args = {});

// Compares `actual` with tests/golden/<name>.png. With PBR_UPDATE_GOLDENS=1 it replaces the
// golden (and its .json metadata) instead and passes.
::testing::AssertionResult matchesGolden(const std::string& name,
                                         const std::filesystem::path& actual,
                                         const std::string& renderer, const GoldenGate& gate = {});

}  // namespace pbr::test
