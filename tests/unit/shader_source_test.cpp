// GLSL #include expansion and the mapping of compiler messages back to files: no GL needed.
#include <gtest/gtest.h>

#include <fstream>

#include "error.h"
#include "shader.h"

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
    // Lines it does not understand pass through unchanged.
    EXPECT_EQ(mapShaderLog("something else\n", files).at(0), "something else");
}

}  // namespace
}  // namespace pbr
