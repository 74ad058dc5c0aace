// GLSL #include expansion and the mapping of compiler messages back to files: no GL needed.
#include <gtest/gtest.h>

#include "support/build_paths.h"

#include <fstream>

#include "base/error.h"
#include "base/paths.h"
#include "gl/shader.h"

namespace pbr {
namespace {

namespace fs = std::filesystem;

class ShaderSourceTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("pbr-shader-test-" + std::to_string(::getpid()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "include");
        fs::create_directories(dir_ / "sample");
    }
    void write(const fs::path& relative, const std::string& text) {
        std::ofstream(dir_ / relative) << text;
    }
    std::string messageOf(const fs::path& relative) {
        try {
            preprocessShader(dir_ / relative, dir_ / "include");
        } catch (const Error& e) {
            return e.what();
        }
        return "no error";
    }
    fs::path dir_;
};

TEST_F(ShaderSourceTest, ExpandsIncludesOnceAndNumbersTheLines) {
    write("include/common.glsl", "const float PI = 3.14;\n");
    write("include/brdf.glsl", "#include \"common.glsl\"\nfloat D() { return PI; }\n");
    write("sample/local.glsl", "float local() { return 1.0; }\n");
    write("sample/main.frag",
          "#version 330 core\n#include \"brdf.glsl\"\n#include \"common.glsl\"\n"
          "#include \"local.glsl\"\nvoid main() {}\n");
    const ShaderSource source = preprocessShader(dir_ / "sample/main.frag", dir_ / "include");
    ASSERT_EQ(source.files.size(), 4u);  // main, brdf, common (once), local (beside main)
    EXPECT_EQ(source.files[0].filename(), "main.frag");
    EXPECT_EQ(source.files[1].filename(), "brdf.glsl");
    EXPECT_EQ(source.files[2].filename(), "common.glsl");
    EXPECT_EQ(source.files[3].filename(), "local.glsl");
    const std::string expected =
        "#version 330 core\n"
        "#line 10001\n"  // brdf.glsl line 1
        "#line 20001\n"  // common.glsl line 1
        "const float PI = 3.14;\n"
        "#line 10002\n"  // back in brdf.glsl at line 2
        "float D() { return PI; }\n"
        "#line 3\n"  // back in main.frag at line 3
        "#line 4\n"  // common.glsl again: nothing, main.frag line 4
        "#line 30001\n"
        "float local() { return 1.0; }\n"
        "#line 5\n"
        "void main() {}\n";
    EXPECT_EQ(source.text, expected);
}

TEST_F(ShaderSourceTest, MissingIncludeNamesFileAndLine) {
    write("sample/main.frag", "#version 330 core\n\n#include \"nowhere.glsl\"\n");
    const std::string message = messageOf("sample/main.frag");
    EXPECT_NE(message.find("main.frag:3: #include \"nowhere.glsl\": not found"), std::string::npos)
        << message;
}

TEST_F(ShaderSourceTest, IncludeCycleIsRefused) {
    write("include/a.glsl", "#include \"b.glsl\"\n");
    write("include/b.glsl", "#include \"a.glsl\"\n");
    write("sample/main.frag", "#version 330 core\n#include \"a.glsl\"\n");
    const std::string message = messageOf("sample/main.frag");
    EXPECT_NE(message.find("b.glsl:1: #include cycle through"), std::string::npos) << message;
}

TEST_F(ShaderSourceTest, UnquotedIncludeIsRefused) {
    write("sample/main.frag", "#version 330 core\n#include <brdf.glsl>\n");
    EXPECT_NE(
        messageOf("sample/main.frag").find("main.frag:2: #include needs a \"quoted\" file name"),
        std::string::npos);
}

TEST_F(ShaderSourceTest, MissingFileIsNamed) {
    EXPECT_NE(messageOf("sample/none.frag").find("none.frag: cannot open"), std::string::npos);
}

// Line 10000 of a file would carry the number of line 0 of the next one (a promise the
// shader_source fuzz target checks; its input: tests/fuzz/regressions/shader_source).
TEST_F(ShaderSourceTest, FileOfMoreThan9999LinesIsRefused) {
    const std::string lines = "#version 330 core\n" + std::string(9998, '\n');  // 9999 lines
    write("sample/main.frag", lines);
    EXPECT_NO_THROW(preprocessShader(dir_ / "sample/main.frag", dir_ / "include"));
    write("sample/main.frag", lines + "x\n");
    const std::string message = messageOf("sample/main.frag");
    EXPECT_NE(message.find("main.frag:10000: more than 9999 lines"), std::string::npos) << message;
}

TEST(ShaderLog, MesaAndNvidiaMessagesMapToFileAndLine) {
    const std::vector<fs::path> files = {"/s/main.frag", "/s/include/brdf.glsl"};
    const auto mesa = mapShaderLog(
        "0:12(5): error: `roughnes' undeclared\n"
        "0:10007(3): error: syntax error\n",
        files);
    ASSERT_EQ(mesa.size(), 2u);
    EXPECT_EQ(mesa[0], "/s/main.frag:12: error: `roughnes' undeclared");
    EXPECT_EQ(mesa[1], "/s/include/brdf.glsl:7: error: syntax error");
    const auto nvidia = mapShaderLog("0(10042) : error C1008: undefined variable \"b\"\n", files);
    ASSERT_EQ(nvidia.size(), 1u);
    EXPECT_EQ(nvidia[0], "/s/include/brdf.glsl:42: error C1008: undefined variable \"b\"");
    // ANGLE, the browsers' compiler (what a WebGL page reports)
    const auto angle = mapShaderLog(
        "ERROR: 0:10009: 'roughnes' : undeclared identifier\n"
        "WARNING: 0:3: 'x' : unused\n",
        files);
    ASSERT_EQ(angle.size(), 2u);
    EXPECT_EQ(angle[0], "/s/include/brdf.glsl:9: error: 'roughnes' : undeclared identifier");
    EXPECT_EQ(angle[1], "/s/main.frag:3: warning: 'x' : unused");
    // Lines it does not understand pass through unchanged.
    EXPECT_EQ(mapShaderLog("something else\n", files).at(0), "something else");
    EXPECT_EQ(mapShaderLog("ERROR: nothing to map\n", files).at(0), "ERROR: nothing to map");
}

// The browser build's rewrite: only the first line changes into the ES version and precision
// statements, and the file's next line is still numbered 2, so messages keep their lines.
TEST(ShaderEs, VersionLineBecomesEsWithPrecisionAndTheLinesKeepTheirNumbers) {
    const std::string desktop = "#version 330 core\nout vec4 FragColor;\n#line 10001\nx\n";
    const std::string es = toGlslEs(desktop, "a.frag");
    EXPECT_EQ(es,
              "#version 300 es\nprecision highp float;\nprecision highp int;\n"
              "precision highp sampler2D;\nprecision highp samplerCube;\n#line 2\n"
              "out vec4 FragColor;\n#line 10001\nx\n");
    EXPECT_EQ(toGlslEs("#version 330 core\r\nx\n", "a.frag").substr(0, 16), "#version 300 es\n");
    try {
        toGlslEs("#version 410 core\nx\n", "shaders/a.frag");
        FAIL() << "another version was taken";
    } catch (const Error& e) {
        EXPECT_NE(
            std::string(e.what()).find("a.frag:1: the first line must be '#version 330 core'"),
            std::string::npos)
            << e.what();
    }
}

// Every shader of the suite starts the way the rewrite expects.
TEST(ShaderEs, EveryShaderOfTheSuiteCanBeRewritten) {
    int count = 0;
    for (const auto& entry : fs::recursive_directory_iterator(PBR_PATH(PBR_SOURCE_SHADER_DIR))) {
        const std::string extension = entry.path().extension().string();
        if (extension != ".vert" && extension != ".frag") continue;
        EXPECT_NO_THROW(toGlslEs(readTextFile(entry.path()), entry.path())) << entry.path();
        ++count;
    }
    EXPECT_GT(count, 20);
}

}  // namespace
}  // namespace pbr
