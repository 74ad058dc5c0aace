#pragma once
// Golden images: render a sample headless, compare with tests/golden/<name>.png under a gate,
// and on failure leave the actual, expected and amplified difference pictures for a person.
//
// Goldens change only on purpose: run the golden tests with PBR_UPDATE_GOLDENS=1, look at the new
// pictures, and say why in the commit.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "files/image.h"
#include "support/process.h"

namespace pbr::test {

// The sRGB transfer function and its inverse (IEC 61966-2-1), for the reference tests' own
// arithmetic; `linearToSrgb` clamps to [0, 1] first.
double srgbToLinear(double c);
double linearToSrgb(double c);

// How many pixels differ from the top-left corner (the clear colour) by more than `threshold`
// levels in some channel: whether a render drew anything.
size_t pixelsUnlikeCorner(const Image& image, int threshold = 8);
// Whether pixel (x, y) is one of those.
bool unlikeCorner(const Image& image, int x, int y, int threshold = 8);

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
    std::string backend;   // from the sample's "wrote ..." line: "osmesa", "egl/surfaceless", ...
    std::string renderer;  // the GL_RENDERER string, from the same line
};
// When a run failed because `backend` cannot start on this machine (its errors start with the
// backend's name: "egl-software: no software display ..."), the reason, for a visible skip.
std::optional<std::string> backendUnavailable(const RunResult& run, const std::string& backend);

// Runs `sample --headless --output <output> <args...>`.
SampleRender renderSample(const std::string& sample, const std::filesystem::path& output,
                          const std::vector<std::string>& args = {},
                          const RunOptions& options = {});

// Renders each of `views` (--view words) in one run of `sample --headless <args...>`: a panel
// script (PBR_PANEL_SCRIPT) sets --view live before each picture and writes it (F12), as the
// panel would; the LiveFlags tests prove that a view set live draws the very bytes of a run
// started with it. One run instead of one a view: the sample starts once. The pictures land in
// `dir` as <view>.png; `images` is empty when the run failed (see `run`).
struct ViewRenders {
    RunResult run;
    std::map<std::string, std::filesystem::path> images;
};
ViewRenders renderViews(const std::string& sample, const std::vector<std::string>& views,
                        const std::vector<std::string>& args, const std::filesystem::path& dir);

// Compares the render with tests/golden/<name>.png and adds it to the golden report. With
// PBR_UPDATE_GOLDENS=1 it replaces the golden (and its .json metadata) instead and passes.
::testing::AssertionResult matchesGolden(const std::string& name, const SampleRender& render,
                                         const GoldenGate& gate = {});

// The golden report: one static HTML page with, for each golden comparison, the expected,
// actual and amplified difference pictures side by side, the metrics against the gate, the
// verdict and the renderer. Every golden test adds its entry; the page is rebuilt each time.
std::filesystem::path goldenReportDir();
std::filesystem::path goldenReportPage();

}  // namespace pbr::test
