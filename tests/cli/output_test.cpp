// Outputs are whole or absent, through whole samples: a full device, a nearly full disk, a folder
// in the way or missing, and 06, whose picture and maps appear together or not at all. Each
// failure is one line naming the file and the reason, exit 1, and nothing left behind.
#include <gtest/gtest.h>

#include <fstream>

#include "base/paths.h"
#include "files/ktx.h"
#include "support/build_paths.h"
#include "support/golden.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

// A failed run: exit 1, stderr exactly one line, which holds every piece of `expected`; no
// "wrote" line on stdout.
void expectOneLineFailure(const RunResult& run, const std::vector<std::string>& expected) {
    EXPECT_EQ(run.exitCode, 1) << run.err;
    const auto lines = run.errLines();
    ASSERT_EQ(lines.size(), 1u) << run.err;
    for (const std::string& piece : expected) {
        EXPECT_NE(lines[0].find(piece), std::string::npos) << lines[0] << " lacks " << piece;
    }
    EXPECT_EQ(run.out.find("wrote"), std::string::npos) << run.out;
}

TEST(Output, FullDeviceIsAnError) {
    const RunResult run =
        runSample({"01_lighting", "--headless", "--size", "64x36", "--output", "/dev/full"});
    expectOneLineFailure(run, {"error: /dev/full: cannot write: No space left on device"});
}

// A disk with 8 KB left (the child may not grow a file past it): the picture does not fit, so
// the run fails naming it, and the folder holds exactly what it held before: an older picture
// keeps its bytes, and no temporary is left.
TEST(Output, NearlyFullDiskLeavesNothing) {
    const fs::path dir = testOutputDir("output_nearly_full");
    std::ofstream(dir / "grid.png") << "an older picture";
    const RunResult run = runSample(
        {"01_lighting", "--headless", "--size", "320x180", "--output", (dir / "grid.png").string()},
        {.fileSizeLimit = 8192});
    expectOneLineFailure(run, {"grid.png: cannot write: File too large"});
    EXPECT_EQ(folderEntries(dir), std::vector<std::string>{"grid.png"});
    EXPECT_EQ(readBytes(dir / "grid.png"), "an older picture");
}

// The path as the user typed it, before any context exists (no "rendering offscreen" line).
TEST(Output, OutputNamingAFolderSaysSo) {
    const fs::path dir = testOutputDir("output_is_folder");
    fs::create_directory(dir / "pictures");
    const RunResult run =
        runSample({"01_lighting", "--size", "64x36", "--output", "pictures/"},
                  {.unsetEnv = {"DISPLAY", "WAYLAND_DISPLAY"}, .workingDirectory = dir});
    expectOneLineFailure(run, {"error: pictures/: is a directory"});
}

// A missing folder is an error for every output flag alike, and nothing is created.
TEST(Output, MissingFolderIsAnErrorForEveryOutputFlag) {
    const fs::path dir = testOutputDir("output_missing_folder");
    const RunOptions here{.unsetEnv = {"DISPLAY", "WAYLAND_DISPLAY"}, .workingDirectory = dir};
    expectOneLineFailure(runSample({"01_lighting", "--output", "new/grid.png"}, here),
                         {"error: new/grid.png: no such folder 'new'"});
    expectOneLineFailure(runSample({"06_brdf_lut", "--ktx-dir", "new"}, here),
                         {"error: --ktx-dir new: no such folder"});
    expectOneLineFailure(runSample({"06_brdf_lut", "--headless", "--output", "new/lut.png"}, here),
                         {"error: new/lut.png: no such folder 'new'"});
    EXPECT_TRUE(folderEntries(dir).empty());
}

// 06 writes its picture and its KTX files as one batch. Each failure below used to leave some of
// them behind (the LUT was written first, before the picture or even the shaders were tried).
TEST(Output, BrdfLutToolWritesAllOrNothing) {
    const fs::path dir = testOutputDir("output_06_batch");
    const std::vector<std::string> small = {"06_brdf_lut", "--headless", "--size", "64x36"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> argv = small;
        argv.insert(argv.end(), extra.begin(), extra.end());
        return argv;
    };

    // --output naming a folder: refused before anything is computed; nothing in its parent.
    fs::create_directory(dir / "taken");
    expectOneLineFailure(runSample(with({"--output", (dir / "taken").string()})),
                         {"taken: is a directory"});
    EXPECT_EQ(folderEntries(dir), std::vector<std::string>{"taken"});

    // The picture cannot be written (/dev/full): the maps, written first to temporaries, are
    // withdrawn.
    fs::create_directory(dir / "maps");
    expectOneLineFailure(
        runSample(with({"--output", "/dev/full", "--ktx-dir", (dir / "maps").string()})),
        {"/dev/full: cannot write: No space left on device"});
    EXPECT_TRUE(folderEntries(dir / "maps").empty());

    // The disk fills up while the maps are written: none of them, and no picture. (--no-cache:
    // the cache could not store the LUT either, and would say so in a line of its own.)
    expectOneLineFailure(
        runSample(with({"--output", (dir / "maps" / "lut.png").string(), "--no-cache"}),
                  {.fileSizeLimit = 100000}),
        {"brdf_lut_sheen_256.ktx: cannot write: File too large"});
    EXPECT_TRUE(folderEntries(dir / "maps").empty());

    // A broken shader of 06's own: no file at all.
    const fs::path shaders = dir / "shaders";
    fs::copy(PBR_PATH(PBR_SOURCE_SHADER_DIR), shaders, fs::copy_options::recursive);
    std::ofstream(shaders / "06_brdf_lut" / "show_lut.frag", std::ios::app) << "broken\n";
    const RunResult broken = runSample(with({"--output", (dir / "maps" / "lut.png").string()}),
                                       {.setEnv = {{"PBR_SHADER_DIR", shaders.string()}}});
    expectOneLineFailure(broken, {"show_lut.frag"});
    EXPECT_TRUE(folderEntries(dir / "maps").empty());

    // And when everything works, all of it, each file named on stdout.
    const RunResult good = runSample(with({"--output", (dir / "maps" / "lut.png").string()}));
    ASSERT_EQ(good.exitCode, 0) << good.err;
    EXPECT_EQ(folderEntries(dir / "maps"),
              (std::vector<std::string>{"brdf_lut_sheen_256.ktx", "lut.png"}));
    EXPECT_NE(good.out.find("wrote " + (dir / "maps" / "brdf_lut_sheen_256.ktx").string()),
              std::string::npos)
        << good.out;
}

// The IBL cache on a nearly full disk: what does not fit is not cached (one warning line each),
// the picture is still drawn, and every file left in the cache is a whole KTX file.
TEST(Output, CacheOnANearlyFullDiskHoldsOnlyWholeFiles) {
    const fs::path dir = testOutputDir("output_cache_full");
    const fs::path cache = dir / "cache";
    const RunResult run =
        runSample({"04_ibl_irradiance", "--headless", "--size", "32x18", "--output",
                   (dir / "04.png").string()},
                  {.setEnv = {{"PBR_CACHE_DIR", cache.string()}}, .fileSizeLimit = 65536});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("sunny_courtyard.environment.ktx: cannot write: File too large; not "
                           "cached"),
              std::string::npos)
        << run.err;
    EXPECT_TRUE(fs::exists(dir / "04.png"));
    const std::vector<std::string> cached = folderEntries(cache);
    EXPECT_EQ(cached, std::vector<std::string>{"sunny_courtyard.irradiance.ktx"});
    for (const std::string& name : cached) EXPECT_NO_THROW(readKtx(cache / name)) << name;
}

}  // namespace
}  // namespace pbr::test
