#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string_view>

#include "app/options.h"
#include "base/error.h"

namespace pbr {
namespace {

const std::vector<FlagSpec> kSampleFlags = {
    FlagSpec::integer("--lights", "N", "lights", 0, 4, 4),
    FlagSpec::toggle("--textured", "switch"),
    FlagSpec::number("--roughness-offset", "D", "offset", -1.0, 1.0, 0.0),
    FlagSpec::choice("--filter", {"trilinear", "nearest"}, "filtering"),
    FlagSpec::text("--model", "FILE", "a model"),
    FlagSpec::outputFolder("--ktx-dir", "DIR", "a folder"),
};

Options parse(std::vector<std::string> args) {
    return parseOptions(args, kSampleFlags);
}

std::string errorOf(std::vector<std::string> args) {
    try {
        parse(std::move(args));
    } catch (const UsageError& e) {
        return e.what();
    }
    return "no error";
}

// "0.0012" 2, "-90" 1, "2.5e-07" 2.
size_t significantDigits(std::string_view text) {
    std::string digits;
    for (const char c : text.substr(0, text.find_first_of("eE")))
        if (c >= '0' && c <= '9') digits += c;
    const size_t first = digits.find_first_not_of('0');
    if (first == std::string::npos) return 0;
    return digits.find_last_not_of('0') - first + 1;
}

// A float flag value as the shortest text that reads back (through the flags' double) to the
// same float: the values of a float, not of the double it widens to. std::to_chars, the standard
// library's own shortest round trip, is the independent reference for the digits.
TEST(Options, FloatsAreWrittenShortest) {
    EXPECT_EQ(flagNumberText(2.2f), "2.2");
    EXPECT_EQ(flagNumberText(-90.0f), "-90");
    EXPECT_EQ(flagNumberText(0.1f), "0.1");
    EXPECT_EQ(flagNumberText(2.2), "2.2");
    EXPECT_EQ(flagNumberText(double(2.2f)), "2.200000047683716");  // the double it widens to
    std::uint32_t bits = 0x3f800000u;  // 1.0f, then every 9973rd float from there up
    for (int i = 0; i < 20000; ++i, bits += 9973u * 4099u) {
        float value = 0.0f;
        std::memcpy(&value, &bits, sizeof value);
        if (!std::isfinite(value)) continue;
        const std::string text = flagNumberText(value);
        EXPECT_EQ(float(std::strtod(text.c_str(), nullptr)), value) << text;
        char reference[32];
        const auto end = std::to_chars(reference, reference + sizeof reference, value).ptr;
        const std::string_view shortest(reference, size_t(end - reference));
        // (from 1e7 up the text keeps every digit of the whole part: 123456784, not 1.2345678e8)
        if (std::abs(value) < 1e7f) {
            EXPECT_LE(significantDigits(text), significantDigits(shortest))
                << text << " against " << shortest;
        }
    }
}

TEST(Options, Defaults) {
    const Options o = parse({});
    EXPECT_FALSE(o.headless);
    EXPECT_FALSE(o.benchmark);
    EXPECT_EQ(o.width, 1280);
    EXPECT_EQ(o.height, 720);
    EXPECT_EQ(o.msaa, 4);
    EXPECT_FALSE(o.frames);
    EXPECT_FALSE(o.time);
    EXPECT_FALSE(o.camera);
    EXPECT_TRUE(o.output.empty());
}

TEST(Options, EveryCommonFlag) {
    const Options o = parse({"--headless", "--output", "a.png", "--size", "640x360", "--frames",
                             "3", "--time=1.5", "--msaa", "8", "--camera", "0,0,3", "--benchmark"});
    EXPECT_TRUE(o.headless);
    EXPECT_TRUE(o.benchmark);
    EXPECT_EQ(o.output, "a.png");
    EXPECT_EQ(o.width, 640);
    EXPECT_EQ(o.height, 360);
    EXPECT_EQ(*o.frames, 3);
    EXPECT_DOUBLE_EQ(*o.time, 1.5);
    EXPECT_EQ(o.msaa, 8);
    ASSERT_TRUE(o.camera);
    EXPECT_FLOAT_EQ(o.camera->z, 3.0f);
    EXPECT_FALSE(o.camera->yaw);
}

TEST(Options, CameraWithYawAndPitch) {
    const Options o = parse({"--camera", "1,-2,3.5,-45,10"});
    ASSERT_TRUE(o.camera);
    EXPECT_FLOAT_EQ(o.camera->x, 1.0f);
    EXPECT_FLOAT_EQ(o.camera->y, -2.0f);
    EXPECT_FLOAT_EQ(*o.camera->yaw, -45.0f);
    EXPECT_FLOAT_EQ(*o.camera->pitch, 10.0f);
}

TEST(Options, MsaaOffSpellings) {
    EXPECT_EQ(parse({"--msaa", "0"}).msaa, 0);
    EXPECT_EQ(parse({"--msaa", "1"}).msaa, 0);
}

TEST(Options, SampleFlagsAndSwitches) {
    const Options o = parse({"--lights", "2", "--textured"});
    EXPECT_EQ(o.sampleFlags.at("--lights"), "2");
    EXPECT_TRUE(o.has("--textured"));
    EXPECT_EQ(parseIntFlag("--lights", "2", 0, 4), 2);
}

TEST(Options, DashHIsHelp) {
    EXPECT_TRUE(parse({"-h"}).help);
    EXPECT_TRUE(parse({"--help"}).help);
    EXPECT_EQ(errorOf({"-x"}), "unexpected argument '-x'");
}

TEST(Options, BadInputNamesTheFlag) {
    EXPECT_EQ(errorOf({"--bogus"}), "unknown flag '--bogus'");
    EXPECT_EQ(errorOf({"stray"}), "unexpected argument 'stray'");
    EXPECT_EQ(errorOf({"--size"}), "--size: missing value");
    const std::string notWxH = "is not WxH (width x height in pixels, e.g. 1280x720)";
    EXPECT_EQ(errorOf({"--size", "640"}), "--size: '640' " + notWxH);
    EXPECT_EQ(errorOf({"--size", "10x"}), "--size: '10x' " + notWxH);
    EXPECT_EQ(errorOf({"--size", "x10"}), "--size: 'x10' " + notWxH);
    EXPECT_EQ(errorOf({"--size", "1x2x3"}), "--size: '1x2x3' " + notWxH);
    EXPECT_EQ(errorOf({"--size", "0x10"}), "--size: 0 is out of range [1, 16384]");
    EXPECT_EQ(errorOf({"--size", "axb"}), "--size: 'a' is not a whole number");
    EXPECT_EQ(errorOf({"--size", "99999999999x10"}),
              "--size: 99999999999 is out of range [1, 16384]");
    EXPECT_EQ(errorOf({"--msaa", "3"}), "--msaa: 3 is not 0, 1 or a power of two");
    EXPECT_EQ(errorOf({"--msaa", "128"}), "--msaa: 128 is out of range [0, 64]");
    EXPECT_EQ(errorOf({"--frames", "0"}), "--frames: 0 is out of range [1, 1000000]");
    EXPECT_EQ(errorOf({"--time", "nan"}), "--time: 'nan' is not a finite number");
    EXPECT_EQ(errorOf({"--time", "soon"}), "--time: 'soon' is not a number");
    EXPECT_EQ(errorOf({"--camera", "1,2"}), "--camera: '1,2' is not x,y,z or x,y,z,yaw,pitch");
    EXPECT_EQ(errorOf({"--camera", "1e40,0,0"}), "--camera: 1e40 is out of range [-1e+06, 1e+06]");
    EXPECT_EQ(errorOf({"--camera", "1e400,0,0"}),
              "--camera: 1e400 is out of range [-1e+06, 1e+06]");
    EXPECT_EQ(errorOf({"--camera", "inf,0,0"}), "--camera: 'inf' is not a finite number");
    EXPECT_EQ(errorOf({"--camera", "1,,2"}), "--camera: empty number in '1,,2'");
    EXPECT_EQ(errorOf({"--camera", "0,0,3,0,95"}), "--camera: pitch must lie in [-89, 89]");
    EXPECT_EQ(errorOf({"--headless=yes"}), "--headless: takes no value");
    EXPECT_EQ(errorOf({"--textured=1"}), "--textured: takes no value");
    EXPECT_EQ(errorOf({"--lights"}), "--lights: missing value");
}

// A sample's own flags are checked in the same pass as the common ones, before any context.
TEST(Options, SampleFlagValuesAreCheckedByTheirKind) {
    EXPECT_EQ(errorOf({"--lights", "5"}), "--lights: 5 is out of range [0, 4]");
    EXPECT_EQ(errorOf({"--lights", "two"}), "--lights: 'two' is not a whole number");
    EXPECT_EQ(errorOf({"--roughness-offset", "nan"}),
              "--roughness-offset: 'nan' is not a finite number");
    EXPECT_EQ(errorOf({"--roughness-offset", "2"}),
              "--roughness-offset: 2 is out of range [-1, 1]");
    EXPECT_EQ(errorOf({"--filter", "foo"}), "--filter: 'foo' is not one of trilinear|nearest");
    EXPECT_EQ(errorOf({"--model", ""}), "--model: empty value");
    EXPECT_EQ(errorOf({"--ktx-dir="}), "--ktx-dir: empty value");
    const Options o = parse({"--roughness-offset", "-0.25", "--filter", "nearest"});
    EXPECT_EQ(o.sampleFlags.at("--roughness-offset"), "-0.25");
    EXPECT_EQ(o.sampleFlags.at("--filter"), "nearest");
}

// A number flag without a default (10's --clearcoat: each material's own unless given) is
// checked as any number when given, absent when not, and --help gives it no default.
TEST(Options, ANumberWithoutADefaultIsAbsentUnlessGiven) {
    const std::vector<FlagSpec> flags = {
        FlagSpec::number("--clearcoat", "F", "the clear coat's factor", 0.0, 1.0, 0.0)
            .withoutDefault()
            .asLive()};
    const std::vector<std::string> given = {"--clearcoat", "0.5"};
    EXPECT_EQ(parseOptions(given, flags).sampleFlags.at("--clearcoat"), "0.5");
    EXPECT_FALSE(parseOptions(std::vector<std::string>{}, flags).has("--clearcoat"));
    try {
        parseOptions(std::vector<std::string>{"--clearcoat", "2"}, flags);
        ADD_FAILURE() << "no error";
    } catch (const UsageError& e) {
        EXPECT_STREQ(e.what(), "--clearcoat: 2 is out of range [0, 1]");
    }
    const std::string usage = usageText("10", flags);
    const size_t line = usage.find("  --clearcoat F");
    ASSERT_NE(line, std::string::npos) << usage;
    const std::string own = usage.substr(line, usage.find('\n', line) - line);
    EXPECT_EQ(own.find("(default"), std::string::npos) << own;
}

TEST(Options, ChoiceFlagsNameTheirWords) {
    EXPECT_EQ(kSampleFlags[3].valueName, "trilinear|nearest");
}

TEST(Options, UsageListsCommonAndSampleFlagsAndTheEnvironment) {
    const std::string usage = usageText("01_lighting", kSampleFlags);
    for (const char* flag :
         {"--help", "--headless", "--output", "--size", "--frames", "--time", "--msaa", "--camera",
          "--benchmark", "--backend", "--lights", "--textured", "-h"}) {
        EXPECT_NE(usage.find(flag), std::string::npos) << flag;
    }
    for (const char* variable :
         {"PBR_SHADER_DIR", "PBR_RESOURCE_DIR", "PBR_CACHE_DIR", "XDG_CACHE_HOME", "DISPLAY"}) {
        EXPECT_NE(usage.find(variable), std::string::npos) << variable;
    }
    EXPECT_EQ(usage.rfind("usage: 01_lighting", 0), 0u);
}

// Two columns that never run into each other: every help text starts at one column, at least
// two spaces after its flag (or on the line below a long one), and no line is over 100 wide.
TEST(Options, UsageColumnsAreAligned) {
    const std::string usage = usageText("01_lighting", kSampleFlags);
    std::istringstream lines(usage);
    std::string line;
    size_t helpColumn = 0;
    int flagLines = 0;
    while (std::getline(lines, line)) {
        EXPECT_LE(line.size(), 100u) << line;
        if (line.rfind("  ", 0) != 0) continue;  // headings
        const size_t nameEnd = line.find("  ", 2);
        const size_t help = line.find_first_not_of(' ', 2);
        if (help > 2) {  // a continuation line: only help text
            if (helpColumn) {
                EXPECT_EQ(help, helpColumn) << line;
            }
            continue;
        }
        if (nameEnd == std::string::npos) continue;  // a long flag alone; its help follows
        const size_t start = line.find_first_not_of(' ', nameEnd);
        ASSERT_NE(start, std::string::npos) << line;
        if (!helpColumn) helpColumn = start;
        EXPECT_EQ(start, helpColumn) << line;
        EXPECT_GE(start - nameEnd, 2u) << line;
        ++flagLines;
    }
    EXPECT_GE(flagLines, 14);
}

}  // namespace
}  // namespace pbr
