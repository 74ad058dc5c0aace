// The Windows build (./build.sh windows: Debian's MinGW-w64, cmake/mingw-w64.cmake) run where a
// Windows learner runs it, in a window, here under Wine on Xvfb (tests/windows/run_wine.sh),
// whose GL is the same llvmpipe as the goldens': every sample's default picture against its
// golden, and what the port must get right besides: the command line's answers, paths with a
// space and a non-ASCII letter, an output that replaces a file, the IBL cache in
// %LOCALAPPDATA%, the screenshot key. Skipped, saying why, where there is no Windows build or no
// Wine (./build.sh test makes both on Debian).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>

#include "base/paths.h"
#include "support/build_paths.h"
#include "support/golden.h"
#include "support/golden_cases.h"
#include "support/process.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

fs::path windowsExecutable(const std::string& sample) {
    return fs::path(PBR_PATH(PBR_WINDOWS_BIN_DIR)) / (sample + ".exe");
}

std::optional<std::string> windowsUnavailable(const std::string& sample) {
    if (!fs::exists(windowsExecutable(sample))) {
        return "no Windows build (" + windowsExecutable(sample).string() +
               "): ./build.sh windows makes it";
    }
    if (!onPath("wine") || !onPath("Xvfb")) return "no wine or Xvfb (Debian: wine, xvfb)";
    return std::nullopt;
}

#define PBR_NEED_WINDOWS(sample) \
    if (const auto whyNot = windowsUnavailable(sample)) GTEST_SKIP() << *whyNot

// `sample`.exe with `args`, in a window under Wine, from `dir` (the paths in `args` relative to
// it: Wine shows the Linux file system as drive Z:, and the working folder is there).
RunResult runWine(const std::vector<std::string>& command, const fs::path& dir,
                  RunOptions options = {}) {
    std::vector<std::string> argv{PBR_PATH(PBR_WINE_RUNNER), PBR_PATH(PBR_WINE_PREFIX)};
    argv.insert(argv.end(), command.begin(), command.end());
    options.workingDirectory = dir;
    return runSample(argv, options);
}
RunResult runWindows(const std::string& sample, std::vector<std::string> args, const fs::path& dir,
                     RunOptions options = {}) {
    args.insert(args.begin(), windowsExecutable(sample).string());
    return runWine(args, dir, std::move(options));
}

// A picture as the samples write it in a window: a few frames at time 0 (03 spins its objects
// with time, as a headless run does not).
const std::vector<std::string> kWindowFrames{"--frames", "2", "--time", "0"};

std::vector<std::string> withFrames(std::vector<std::string> args) {
    args.insert(args.end(), kWindowFrames.begin(), kWindowFrames.end());
    return args;
}

// `image` against `reference` (a golden, or the native build's picture) by the golden gate itself:
// Wine hands the GL to the same llvmpipe as the goldens' (measured: five samples the goldens'
// very pixels, five within 2 levels, nothing past the gate's 2).
void expectPicture(const fs::path& image, const fs::path& reference, const std::string& what) {
    ASSERT_TRUE(fs::exists(image)) << image;
    ASSERT_TRUE(fs::exists(reference)) << reference;
    const GoldenVerdict verdict = judge(readImage(image, 3), readImage(reference, 3), GoldenGate{});
    std::printf("%s under Wine: %s\n", what.c_str(), verdict.summary.c_str());
    EXPECT_TRUE(verdict.pass) << what << ": " << verdict.summary;
}
void expectGolden(const fs::path& image, const std::string& name) {
    expectPicture(image, fs::path(PBR_PATH(PBR_GOLDEN_DIR)) / (name + ".png"),
                  name + " against its golden");
}

class WindowsGolden : public ::testing::TestWithParam<GoldenCase> {};

// Each sample's default picture, drawn in a window and written with --output.
TEST_P(WindowsGolden, DrawsItsGoldenInAWindow) {
    const GoldenCase& golden = GetParam();
    PBR_NEED_WINDOWS(golden.sample);
    const fs::path dir = testOutputDir("windows_" + golden.golden);
    const RunResult run = runWindows(golden.sample, withFrames({"--output", "out.png"}), dir);
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    // in a window (GLFW), on llvmpipe: the picture is Windows', not a headless fallback's
    const std::vector<std::string> out = run.outLines();
    ASSERT_FALSE(out.empty()) << run.err;
    EXPECT_NE(out[0].find("out.png (1280x720, msaa 4, glfw, llvmpipe"), std::string::npos)
        << out[0];
    expectGolden(dir / "out.png", golden.golden);
}

std::vector<GoldenCase> defaultPictures() {
    std::vector<GoldenCase> cases;
    for (const GoldenCase& golden : goldenCases()) {
        if (golden.golden == golden.sample && golden.args.empty()) cases.push_back(golden);
    }
    return cases;
}

INSTANTIATE_TEST_SUITE_P(Samples, WindowsGolden, ::testing::ValuesIn(defaultPictures()),
                         [](const auto& info) { return info.param.golden; });

// Windows has no DISPLAY variable, and a window opens without one. (The build once asked for one,
// as X11 needs, and so never opened a window on Windows. Wine hands its programs the Linux
// DISPLAY: cmd takes it away from the sample's environment first.)
TEST(Windows, OpensAWindowWithoutADisplayVariable) {
    PBR_NEED_WINDOWS("01_lighting");
    const fs::path dir = testOutputDir("windows_no_display_variable");
    std::string exe = "Z:" + windowsExecutable("01_lighting").string();
    std::replace(exe.begin(), exe.end(), '/', '\\');
    std::ofstream(dir / "run.bat")
        << "@set DISPLAY=\r\n@\"" << exe << "\" --frames 2 --time 0 --output out.png\r\n"
        << "@exit /b %errorlevel%\r\n";
    const RunResult run = runWine({"cmd", "/c", "run.bat"}, dir);
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    expectGolden(dir / "out.png", "01_lighting");
}

TEST(Windows, HelpIsTheUsageExit0) {
    PBR_NEED_WINDOWS("09_light_types");
    const RunResult run = runWindows("09_light_types", {"--help"}, testOutputDir("windows_help"));
    EXPECT_EQ(run.exitCode, 0) << run.err;
    const std::vector<std::string> lines = run.outLines();
    ASSERT_FALSE(lines.empty());
    EXPECT_EQ(lines[0].rfind("usage: 09_light_types", 0), 0u) << lines[0];
    EXPECT_NE(run.out.find("--point-lights"), std::string::npos) << run.out;  // 09's own
    // the cache's place as Windows has it
    EXPECT_NE(run.out.find("%LOCALAPPDATA%\\pbr-samples"), std::string::npos) << run.out;
    EXPECT_EQ(run.out.find("WAYLAND_DISPLAY"), std::string::npos) << run.out;
    EXPECT_TRUE(run.err.empty()) << run.err;
}

TEST(Windows, BadFlagIsTheUsageThenOneLastLineExit2) {
    PBR_NEED_WINDOWS("01_lighting");
    const RunResult run = runWindows("01_lighting", {"--bogus"}, testOutputDir("windows_bad_flag"));
    EXPECT_EQ(run.exitCode, 2);
    const std::vector<std::string> lines = run.errLines();
    ASSERT_GE(lines.size(), 2u) << run.err;
    EXPECT_EQ(lines[0].rfind("usage: 01_lighting", 0), 0u) << lines[0];
    EXPECT_EQ(lines.back(), "error: unknown flag '--bogus'");
    EXPECT_TRUE(run.out.empty()) << run.out;
}

TEST(Windows, MissingFileIsOneLineExit1) {
    PBR_NEED_WINDOWS("04_ibl_irradiance");
    const RunResult run = runWindows("04_ibl_irradiance", {"--hdr", "no such file.hdr"},
                                     testOutputDir("windows_missing_file"));
    EXPECT_EQ(run.exitCode, 1);
    const std::vector<std::string> lines = run.errLines();
    ASSERT_EQ(lines.size(), 1u) << run.err;
    EXPECT_EQ(lines[0], "error: no such file.hdr: cannot open: No such file or directory");
}

// A learner's files in a folder whose name has spaces and non-ASCII letters: the model and its
// textures, the environment, and the picture written there, the picture the native build draws
// of them (a model given is framed from its bounds, not by the default model's camera). Without
// the UTF-8 manifest, argv reaches the program in Windows' ANSI code page and the ü is lost; a
// path made from the text by std::filesystem::path itself (not pathFromUtf8) reads it wrong.
TEST(Windows, ModelAndHdrFromAFolderWithSpacesAndANonAsciiLetter) {
    PBR_NEED_WINDOWS("07_gltf_metallic_roughness");
    const fs::path dir = testOutputDir("windows_non_ascii");
    const fs::path folder = dir / fs::path(u8"a learner's f\u00f6lder, \u00fc");
    fs::create_directories(folder);
    const fs::path resources = fs::path(PBR_PATH(PBR_ENVIRONMENT_DIR)).parent_path();
    for (const auto& entry : fs::directory_iterator(resources / "models")) {
        const std::string name = entry.path().filename().string();
        if (name.starts_with("pbr_showcase") && entry.path().extension() != ".pbrmodel")
            fs::copy_file(entry.path(), folder / name);
    }
    fs::copy_file(resources / "environments" / "sunny_courtyard.hdr",
                  folder / "sunny_courtyard.hdr");
    const std::string in = utf8Path(folder.filename());
    const RunResult run =
        runWindows("07_gltf_metallic_roughness",
                   withFrames({"--model", in + "/pbr_showcase.gltf", "--hdr",
                               in + "/sunny_courtyard.hdr", "--output", in + "/out.png"}),
                   dir);
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    const SampleRender native = renderSample("07_gltf_metallic_roughness", dir / "native.png",
                                             {"--model", utf8Path(folder / "pbr_showcase.gltf"),
                                              "--hdr", utf8Path(folder / "sunny_courtyard.hdr")});
    ASSERT_EQ(native.run.exitCode, 0) << native.run.err;
    expectPicture(folder / "out.png", native.image,
                  "07 with a model and an environment given, against the native build");
}

// --output onto a file that is there: replaced whole (Windows' rename does not replace unless
// asked to), with nothing left beside it.
TEST(Windows, OutputReplacesAnExistingFile) {
    PBR_NEED_WINDOWS("01_lighting");
    const fs::path dir = testOutputDir("windows_replace");
    std::ofstream(dir / "out.png") << "an older file, not a picture";
    const RunResult run = runWindows("01_lighting", withFrames({"--output", "out.png"}), dir);
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_EQ(folderEntries(dir), std::vector<std::string>{"out.png"});
    expectGolden(dir / "out.png", "01_lighting");
}

// Without PBR_CACHE_DIR, the IBL maps are kept in %LOCALAPPDATA%\pbr-samples (the prefix's
// C:\users\<user>\AppData\Local), and read from there by the next run.
TEST(Windows, IblCacheIsInLocalAppData) {
    PBR_NEED_WINDOWS("04_ibl_irradiance");
    const fs::path users = fs::path(PBR_PATH(PBR_WINE_PREFIX)) / "drive_c" / "users";
    ASSERT_TRUE(fs::exists(users)) << "no Wine prefix: " << users;
    std::vector<fs::path> caches;
    for (const auto& user : fs::directory_iterator(users)) {
        const fs::path cache = user.path() / "AppData" / "Local" / "pbr-samples";
        if (fs::exists(user.path() / "AppData" / "Local")) caches.push_back(cache);
    }
    ASSERT_EQ(caches.size(), 1u) << "one user's AppData\\Local in " << users;
    fs::remove_all(caches[0]);
    const fs::path dir = testOutputDir("windows_cache");
    const RunOptions options{.unsetEnv = {"PBR_CACHE_DIR", "XDG_CACHE_HOME"}};
    const std::vector<std::string> args = withFrames({"--size", "320x180", "--output", "a.png"});
    const RunResult first = runWindows("04_ibl_irradiance", args, dir, options);
    ASSERT_EQ(first.exitCode, 0) << first.out << first.err;
    ASSERT_TRUE(fs::exists(caches[0])) << first.out << first.err;
    const std::vector<std::string> kept = folderEntries(caches[0]);
    EXPECT_FALSE(kept.empty());
    const RunResult second = runWindows(
        "04_ibl_irradiance", withFrames({"--size", "320x180", "--output", "b.png"}), dir, options);
    ASSERT_EQ(second.exitCode, 0) << second.out << second.err;
    EXPECT_EQ(folderEntries(caches[0]), kept);
    EXPECT_EQ(readBytes(dir / "a.png"), readBytes(dir / "b.png"));
}

// GLFW frees the XInput DLL it loaded at glfwTerminate, and Wine 8's XInput, so unloaded, can be
// unmapped before its device thread has left its code: 1 run in about 100 then ended in a page
// fault inside xinput1_4.dll after writing its picture (the CI found it; 1 in 89 here). The
// samples pin the DLL (common/context/context_glfw.cpp): Wine's loader trace shows it loaded,
// and never unloaded before the process ends.
TEST(Windows, XInputStaysLoadedUntilTheProcessEnds) {
    PBR_NEED_WINDOWS("01_lighting");
    const fs::path dir = testOutputDir("windows_xinput");
    const RunResult run =
        runWindows("01_lighting", {"--frames", "1", "--size", "64x64", "--output", "out.png"}, dir,
                   {.setEnv = {{"PBR_WINEDEBUG", "-all,+loaddll"}}});
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    bool loaded = false;
    for (const std::string& line : run.errLines()) {
        if (line.find("xinput") == std::string::npos) continue;
        loaded = loaded || line.find("Loaded ") != std::string::npos;
        EXPECT_EQ(line.find("Unloaded module"), std::string::npos) << line;
    }
    EXPECT_TRUE(loaded) << "no XInput DLL in Wine's loader trace:\n" << run.err;
}

// The screenshot key in a window: F12 (here from a panel script, PBR_PANEL_SCRIPT, as the tests
// press it natively) writes screenshot-<sample>-<frame>.png in the working folder.
TEST(Windows, ScreenshotKeyWritesThePicture) {
    PBR_NEED_WINDOWS("01_lighting");
    const fs::path dir = testOutputDir("windows_screenshot");
    std::ofstream(dir / "script.txt") << "-\nF12\n";
    const RunResult run = runWindows("01_lighting", {"--frames", "3", "--time", "0"}, dir,
                                     {.setEnv = {{"PBR_PANEL_SCRIPT", "script.txt"}}});
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    const fs::path shot = dir / "screenshot-01_lighting-1.png";
    ASSERT_TRUE(fs::exists(shot)) << run.out;
    const Image image = readImage(shot, 3);
    EXPECT_EQ(image.width, 1280);
    EXPECT_EQ(image.height, 720);
    EXPECT_GT(double(pixelsUnlikeCorner(image)) / (1280.0 * 720.0), 0.15);
}

}  // namespace
}  // namespace pbr::test
