#include <gtest/gtest.h>

#include "error.h"
#include "options.h"

namespace pbr {
namespace {

const std::vector<FlagSpec> kSampleFlags = {{"--lights", "N", "lights"},
                                            {"--textured", "", "switch"}};

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

TEST(Options, BadInputNamesTheFlag) {
    EXPECT_EQ(errorOf({"--bogus"}), "unknown flag '--bogus'");
    EXPECT_EQ(errorOf({"stray"}), "unexpected argument 'stray'");
    EXPECT_EQ(errorOf({"--size"}), "--size: missing value");
    EXPECT_EQ(errorOf({"--size", "640"}), "--size: '640' is not WxH");
    EXPECT_EQ(errorOf({"--size", "0x10"}), "--size: 0 is out of range [1, 16384]");
    EXPECT_EQ(errorOf({"--size", "axb"}), "--size: 'a' is not a whole number");
    EXPECT_EQ(errorOf({"--msaa", "3"}), "--msaa: 3 is not 0, 1 or a power of two");
    EXPECT_EQ(errorOf({"--frames", "0"}), "--frames: 0 is out of range [1, 1000000]");
    EXPECT_EQ(errorOf({"--time", "nan"}), "--time: 'nan' is not a number");
    EXPECT_EQ(errorOf({"--camera", "1,2"}), "--camera: '1,2' is not x,y,z or x,y,z,yaw,pitch");
    EXPECT_EQ(errorOf({"--camera", "0,0,3,0,95"}), "--camera: pitch must lie in [-89, 89]");
    EXPECT_EQ(errorOf({"--headless=yes"}), "--headless: takes no value");
    EXPECT_EQ(errorOf({"--textured=1"}), "--textured: takes no value");
    EXPECT_EQ(errorOf({"--lights"}), "--lights: missing value");
}

TEST(Options, UsageListsCommonAndSampleFlags) {
    const std::string usage = usageText("01_lighting", kSampleFlags);
    for (const char* flag : {"--help", "--headless", "--output", "--size", "--frames", "--time",
                             "--msaa", "--camera", "--benchmark", "--lights", "--textured"}) {
        EXPECT_NE(usage.find(flag), std::string::npos) << flag;
    }
    EXPECT_EQ(usage.rfind("usage: 01_lighting", 0), 0u);
}

}  // namespace
}  // namespace pbr
