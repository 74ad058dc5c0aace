// Every bad input gets one line naming the thing and the reason, and a non-zero exit.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "base/paths.h"
#include "support/build_paths.h"
#include "support/golden.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

// The line number of the first line of `file` that contains `text` (1-based), found by reading
// the file: the expected number comes from the file, not from the program under test.
int lineOf(const fs::path& file, const std::string& text) {
    std::ifstream in(file);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (line.find(text) != std::string::npos) return number;
    }
    return -1;
}

void replaceInFile(const fs::path& file, const std::string& from, const std::string& to) {
    std::string text = readTextFile(file);
    const size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from << " not in " << file;
    text.replace(at, from.size(), to);
    std::ofstream(file, std::ios::trunc) << text;
}

// A copy of shaders/ to break.
fs::path copyShaders(const fs::path& dir) {
    const fs::path copy = dir / "shaders";
    fs::copy(PBR_PATH(PBR_SOURCE_SHADER_DIR), copy, fs::copy_options::recursive);
    return copy;
}

// A bad flag: the usage, then one line naming the flag as the last line (what `2>&1 | tail -1`
// shows), exit 2.
TEST(Cli, UnknownFlagIsTheUsageThenOneLastLineExit2) {
    const RunResult run = runSample({"01_lighting", "--headless", "--bogus"});
    EXPECT_EQ(run.exitCode, 2);
    const auto lines = run.errLines();
    ASSERT_GE(lines.size(), 2u);
    EXPECT_EQ(lines[0].rfind("usage: 01_lighting", 0), 0u) << lines[0];
    EXPECT_EQ(lines.back(), "error: unknown flag '--bogus'");
    EXPECT_TRUE(run.out.empty()) << run.out;
}

// Every flag, the sample's own included, is checked before any window or context exists: with
// no display and no --headless, a bad value gives no "rendering offscreen instead" line first.
TEST(Cli, BadFlagValuesNameTheFlagBeforeAnyContext) {
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"01_lighting", "--size", "0x360"}, "--size: 0 is out of range [1, 16384]"},
        {{"01_lighting", "--size", "10x"},
         "--size: '10x' is not WxH (width x height in pixels, e.g. 1280x720)"},
        {{"01_lighting", "--msaa", "3"}, "--msaa: 3 is not 0, 1 or a power of two"},
        {{"01_lighting", "--frames", "0"}, "--frames: 0 is out of range [1, 1000000]"},
        {{"01_lighting", "--camera", "1,2"}, "--camera: '1,2' is not x,y,z or x,y,z,yaw,pitch"},
        {{"01_lighting", "--camera", "1e40,0,0"}, "--camera: 1e40 is out of range [-1e+06, 1e+06]"},
        {{"01_lighting", "--time", "soon"}, "--time: 'soon' is not a number"},
        {{"01_lighting", "--lights", "5"}, "--lights: 5 is out of range [0, 4]"},
        {{"01_lighting", "--roughness-offset", "nan"},
         "--roughness-offset: 'nan' is not a finite number"},
        {{"01_lighting", "--output"}, "--output: missing value"},
        {{"02_lighting_textured", "--tangent-frame", "foo"},
         "--tangent-frame: 'foo' is not one of mesh|derivatives"},
        {{"02_lighting_textured", "--filter", "foo"},
         "--filter: 'foo' is not one of trilinear|nearest"},
        {{"05_ibl_specular", "--textured=yes"}, "--textured: takes no value"},
        {{"06_brdf_lut", "--hdr"}, "--hdr: missing value"},
        {{"09_light_types", "--only", "sun"},
         "--only: 'sun' is not one of all|point|directional|spot|ambient-box|ambient-sphere"},
        {{"07_gltf_metallic_roughness", "--tonemap", "filmic"},
         "--tonemap: 'filmic' is not one of khronos-neutral|none|reinhard|aces"},
        {{"09_light_types", "--point-lights", "251"},
         "--point-lights: 251 is out of range [0, 250]"},
        {{"09_light_types", "--attenuation", "1,2"},
         "--attenuation: '1,2' is not C,L,Q (3 numbers, comma-separated)"},
        {{"09_light_types", "--attenuation", "1,-1,0"},
         "--attenuation: -1 is out of range [0, 1e+06]"},
        // the sample's own check (FlagSpec::refusing), also before any context
        {{"09_light_types", "--attenuation", "0,0e3,0.0"},
         "--attenuation: '0,0e3,0.0': all three terms are 0"},
        {{"01_lighting", "--fov", "0.5"}, "--fov: 0.5 is out of range [1, 45]"},
    };
    for (const auto& [argv, message] : cases) {
        const RunResult run = runSample(argv, {.unsetEnv = {"DISPLAY", "WAYLAND_DISPLAY"}});
        EXPECT_EQ(run.exitCode, 2) << message;
        const auto lines = run.errLines();
        ASSERT_FALSE(lines.empty()) << message;
        EXPECT_EQ(lines.back(), "error: " + message);
        EXPECT_EQ(run.err.find("rendering offscreen instead"), std::string::npos) << run.err;
        EXPECT_EQ(lines[0].rfind("usage: " + argv[0], 0), 0u) << lines[0];
    }
}

TEST(Cli, HelpPrintsUsageAndExits0) {
    const RunResult run = runSample({"01_lighting", "--help"});
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_NE(run.out.find("--headless"), std::string::npos);
    EXPECT_NE(run.out.find("--lights N"), std::string::npos);
    EXPECT_TRUE(run.err.empty()) << run.err;
    const RunResult shortForm = runSample({"01_lighting", "-h"});
    EXPECT_EQ(shortForm.exitCode, 0);
    EXPECT_EQ(shortForm.out, run.out);
    EXPECT_TRUE(shortForm.err.empty()) << shortForm.err;
}

// Runs sample 01 on the shaders in `shaders`, writing into `dir`; expects exit 1, no picture and
// exactly one line on stderr, which it returns.
std::string oneLineFailure(const fs::path& dir, const fs::path& shaders) {
    const RunResult run =
        runSample({"01_lighting", "--headless", "--output", (dir / "x.png").string()},
                  {.setEnv = {{"PBR_SHADER_DIR", shaders.string()}}});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_FALSE(fs::exists(dir / "x.png"));
    const auto lines = run.errLines();
    EXPECT_EQ(lines.size(), 1u) << run.err;
    return lines.empty() ? "" : lines[0];
}

TEST(Cli, MissingShaderFileIsNamed) {
    const fs::path dir = testOutputDir("cli_missing_shader");
    const fs::path shaders = copyShaders(dir);
    fs::remove(shaders / "01_lighting" / "pbr.frag");
    const std::string line = oneLineFailure(dir, shaders);
    EXPECT_NE(line.find("01_lighting/pbr.frag: cannot open"), std::string::npos) << line;
}

// Breaks `file` (relative to shaders/) by replacing `from` with `to`, runs sample 01 on that copy
// and expects one line naming the file and the line that holds `to`.
void expectCompileErrorAt(const std::string& testName, const std::string& file,
                          const std::string& from, const std::string& to) {
    const fs::path dir = testOutputDir(testName);
    const fs::path shaders = copyShaders(dir);
    replaceInFile(shaders / file, from, to);
    const int line = lineOf(shaders / file, to);
    ASSERT_GT(line, 0);
    const std::string message = oneLineFailure(dir, shaders);
    const std::string where = file + ":" + std::to_string(line) + ": ";
    EXPECT_NE(message.find(where), std::string::npos) << message << " (expected " << where << ")";
    EXPECT_NE(message.find("error"), std::string::npos) << message;
}

TEST(Cli, CompileErrorPointsAtTheLineInTheFile) {
    expectCompileErrorAt("cli_compile_error", "01_lighting/pbr.frag",
                         "vec3 V = normalize(camPos - WorldPos);",
                         "vec3 V = normalize(camPos - WorldPos) * roughnes;");
}

TEST(Cli, CompileErrorInAnIncludeNamesTheIncludedFile) {
    expectCompileErrorAt("cli_include_error", "include/brdf.glsl", "float a2 = a * a;",
                         "float a2 = a * alpha;");
}

TEST(Cli, UnwritableOutputIsNamed) {
    const RunResult run = runSample(
        {"01_lighting", "--headless", "--size", "64x36", "--output", "/proc/no-such-dir/out.png"});
    EXPECT_EQ(run.exitCode, 1);
    const auto lines = run.errLines();
    ASSERT_EQ(lines.size(), 1u) << run.err;
    EXPECT_EQ(lines[0], "error: /proc/no-such-dir/out.png: no such folder '/proc/no-such-dir'");
    const RunResult readOnly =
        runSample({"01_lighting", "--headless", "--size", "64x36", "--output", "/proc/out.png"});
    EXPECT_EQ(readOnly.exitCode, 1);
    ASSERT_EQ(readOnly.errLines().size(), 1u) << readOnly.err;
    EXPECT_EQ(readOnly.errLines()[0].rfind("error: /proc/out.png: cannot write: ", 0), 0u)
        << readOnly.err;
}

// The main command with no display: no --headless, yet it renders offscreen, writes
// 01_lighting.png in the working directory and says where.
TEST(Cli, NoDisplayFallsBackToOffscreen) {
    const fs::path dir = testOutputDir("cli_no_display");
    const RunResult run =
        runSample({"01_lighting", "--size", "320x180"},
                  {.unsetEnv = {"DISPLAY", "WAYLAND_DISPLAY"}, .workingDirectory = dir});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("no display"), std::string::npos) << run.err;
    const fs::path written = dir / "01_lighting.png";
    EXPECT_TRUE(fs::exists(written));
    EXPECT_NE(run.out.find(written.string()), std::string::npos) << run.out;
}

// 07's --light K past the file's punctual lights (a number the command line cannot check, since
// the model decides it): no light, as --no-punctual draws, and a note saying so, not silence.
TEST(Cli, A07LightPastTheFilesLightsIsSaid) {
    const fs::path dir = testOutputDir("cli_light_past");
    const std::vector<std::string> common = {"07_gltf_metallic_roughness", "--headless", "--size",
                                             "96x54"};
    std::vector<std::string> past = common, none = common;
    past.insert(past.end(), {"--light", "8", "--output", (dir / "past.png").string()});
    none.insert(none.end(), {"--no-punctual", "--output", (dir / "none.png").string()});
    const RunResult run = runSample(past);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_TRUE(std::regex_search(
        run.err, std::regex("note: --light 8: there (is|are) only [0-9]+ punctual lights?.*; no "
                            "light is drawn\n")))
        << run.err;
    ASSERT_EQ(runSample(none).exitCode, 0);
    EXPECT_TRUE(readBytes(dir / "past.png") == readBytes(dir / "none.png"))
        << "--light 8 should draw what --no-punctual draws";
}

}  // namespace
}  // namespace pbr::test
