// The term views' names and numbers: pbr::View (common/app/views.h) and the VIEW_ constants of
// shaders/include/views.glsl are one table in two languages.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "app/views.h"
#include "base/paths.h"

namespace pbr {
namespace {

std::map<std::string, int> glslViewConstants() {
    std::ifstream file(shaderDir() / "include" / "views.glsl");
    std::stringstream text;
    text << file.rdbuf();
    const std::string source = text.str();
    std::map<std::string, int> constants;
    const std::regex constant(R"(const int (VIEW_[A-Z0-9_]+) = (\d+);)");
    for (auto it = std::sregex_iterator(source.begin(), source.end(), constant);
         it != std::sregex_iterator(); ++it) {
        constants[(*it)[1]] = std::stoi((*it)[2]);
    }
    return constants;
}

TEST(Views, GlslConstantsAreTheViewNumbers) {
    const std::map<std::string, int> glsl = glslViewConstants();
    ASSERT_FALSE(glsl.empty()) << "no VIEW_ constant in views.glsl";
    std::set<std::string> seen;
    for (View view : kDirectLightViews) {
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
    for (View view : kDirectLightViews) {
        const std::string name(viewName(view));
        EXPECT_TRUE(names.insert(name).second) << name << " twice";
        EXPECT_EQ(viewNamed(name), view) << name;
    }
    EXPECT_EQ(viewFlag(kDirectLightViews).choices.front(), "final");
    EXPECT_THROW(viewNamed("gloss"), Error);
}

}  // namespace
}  // namespace pbr
