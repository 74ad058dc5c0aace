// The term views' names and numbers: pbr::View (common/app/views.h) and the VIEW_ constants of
// shaders/include/views.glsl are one table in two languages.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "app/options.h"
#include "app/views.h"
#include "base/error.h"
#include "base/paths.h"

namespace pbr {
namespace {

// Every "const int VIEW_<NAME> = <number>;" line of views.glsl (no <regex>: its GCC 12 headers
// warn under the sanitizers).
std::map<std::string, int> glslViewConstants() {
    std::ifstream file(shaderDir() / "include" / "views.glsl");
    std::map<std::string, int> constants;
    std::string line;
    const std::string prefix = "const int VIEW_";
    while (std::getline(file, line)) {
        if (line.rfind(prefix, 0) != 0) continue;
        const size_t equals = line.find(" = ");
        const size_t end = line.find(';');
        if (equals == std::string::npos || end == std::string::npos) continue;
        constants[line.substr(10, equals - 10)] =
            std::stoi(line.substr(equals + 3, end - equals - 3));
    }
    return constants;
}

TEST(Views, GlslConstantsAreTheViewNumbers) {
    const std::map<std::string, int> glsl = glslViewConstants();
    ASSERT_FALSE(glsl.empty()) << "no VIEW_ constant in views.glsl";
    std::set<std::string> seen;
    for (View view : allViews()) {
        const std::string constant = viewConstant(view);
        ASSERT_TRUE(glsl.count(constant)) << constant << " is not in views.glsl";
        EXPECT_EQ(glsl.at(constant), int(view)) << constant;
        seen.insert(constant);
    }
    for (const auto& [constant, number] : glsl) {
        EXPECT_TRUE(seen.count(constant)) << constant << " = " << number << " has no pbr::View";
    }
}

TEST(Views, NamesGoBothWays) {
    std::set<std::string> names;
    for (View view : allViews()) {
        const std::string name(viewName(view));
        EXPECT_TRUE(names.insert(name).second) << name << " twice";
        EXPECT_EQ(viewNamed(name), view) << name;
    }
    EXPECT_EQ(viewFlag(kDirectLightViews).choices.front(), "final");
    EXPECT_THROW(viewNamed("gloss"), Error);
}

// One vocabulary: LearnOpenGL's albedo and ao are the glTF texts' base colour and occlusion, and
// each sample takes both words, keeping its own text's (the other listed by --help), so a view
// keeps its name from sample to sample.
TEST(Views, EachSampleTakesTheOtherTextsWords) {
    const auto parsed = [](std::span<const View> views, const std::string& word) {
        const std::vector<FlagSpec> flags = {viewFlag(views)};
        const std::vector<std::string> args = {"--view", word};
        return parseOptions(args, flags).sampleFlags.at("--view");
    };
    for (const std::span<const View> views :
         {std::span<const View>(kDirectLightViews), std::span<const View>(kLightTypeViews),
          std::span<const View>(kIrradianceViews), std::span<const View>(kSplitSumViews)}) {
        EXPECT_EQ(parsed(views, "albedo"), "albedo");
        EXPECT_EQ(parsed(views, "base-color"), "albedo");
        EXPECT_EQ(parsed(views, "occlusion"), "ao");
        EXPECT_EQ(parsed(views, "ao"), "ao");
        EXPECT_THROW(parsed(views, "emissive"), UsageError);  // no emission in those lessons
    }
    EXPECT_EQ(parsed(kGltfViews, "albedo"), "base-color");
    EXPECT_EQ(parsed(kGltfViews, "ao"), "occlusion");
    EXPECT_EQ(parsed(kGltfViews, "occlusion"), "occlusion");
    // --help, its lines joined (it wraps at 100 columns)
    const auto usage = [](std::span<const View> views) {
        const std::vector<FlagSpec> flags = {viewFlag(views)};
        std::string joined;
        for (const char c : usageText("sample", flags)) {
            if (c != ' ' && c != '\n')
                joined += c;
            else if (!joined.empty() && joined.back() != ' ')
                joined += ' ';
        }
        return joined;
    };
    EXPECT_NE(usage(kDirectLightViews).find("; base-color is albedo, occlusion is ao"),
              std::string::npos)
        << usage(kDirectLightViews);
    EXPECT_NE(usage(kGltfViews).find("; albedo is base-color, ao is occlusion"), std::string::npos);
}

// Every view of every sample says what it shows: a caption that starts with its name and ends
// with its encoding, a scale bar where the values are mapped; the picture itself has none.
TEST(Views, EveryViewHasACaption) {
    EXPECT_EQ(viewCaption(View::Final), "");
    for (const std::span<const View> views :
         {std::span<const View>(kDirectLightViews), std::span<const View>(kLightTypeViews),
          std::span<const View>(kIrradianceViews), std::span<const View>(kSplitSumViews),
          std::span<const View>(kGltfViews)}) {
        for (const View view : views) {
            if (view == View::Final) continue;
            const std::string caption = viewCaption(view);
            EXPECT_EQ(caption.rfind(std::string(viewName(view)) + ": ", 0), 0u) << caption;
            const ViewScale scale = viewScale(view);
            if (scale == ViewScale::Compressed) {
                EXPECT_TRUE(caption.ends_with("; x / (1 + x)")) << caption;
            }
            if (scale == ViewScale::AsItIs) {
                EXPECT_TRUE(caption.ends_with("; as it is")) << caption;
            }
        }
    }
    EXPECT_EQ(
        viewCaption(View::D),
        "d: the GGX distribution D, summed over the lights that reach the point; x / (1 + x)");
    EXPECT_EQ(viewScale(View::Normal), ViewScale::None);
}

}  // namespace
}  // namespace pbr
