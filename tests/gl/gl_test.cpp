// The helper library inside a real (offscreen) GL context: the error detector, object ownership,
// shader reload, the render target. Each test makes its own headless App.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "app.h"
#include "brdf.h"
#include "error.h"
#include "ibl.h"
#include "mesh.h"
#include "paths.h"
#include "support/process.h"
#include "texture.h"

namespace pbr {
namespace {

namespace fs = std::filesystem;

// A headless App as a sample would make it, drawing into `dir`.
App makeApp(const fs::path& dir, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {"gl_test", "--headless", "--size",
                                     "64x36",   "--output",   (dir / "out.png").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    return App(int(argv.size()), argv.data(), {.name = "gl_test"});
}

TEST(Gl, AGlErrorFailsTheRunAndIsNamed) {
    const fs::path dir = test::testOutputDir("gl_error");
    App app = makeApp(dir);
    ASSERT_TRUE(app.nextFrame());
    glEnable(0x1234);  // not a capability: GL_INVALID_ENUM
    try {
        app.nextFrame();
        FAIL() << "a GL error went unnoticed";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("1 OpenGL error(s) during the run"), std::string::npos) << message;
        // With KHR_debug (llvmpipe has it) the driver's message names the call.
        if (GLAD_GL_KHR_debug) {
            EXPECT_NE(message.find("glEnable"), std::string::npos) << message;
        }
    }
}

TEST(Gl, ACleanRunHasNoErrorAndReleasesEveryObject) {
    const fs::path dir = test::testOutputDir("gl_clean");
    App app = makeApp(dir);
    const GlObjectCensus empty = takeGlObjectCensus();
    EXPECT_EQ(empty.framebuffers, 2);   // the render target: multisampled + resolved
    EXPECT_EQ(empty.renderbuffers, 4);  // colour and depth of each
    {
        const GpuMesh sphere(uvSphere());
        const Texture2D texture(Image{2, 2, 3, std::vector<std::uint8_t>(12, 128)},
                                ColorSpace::Srgb);
        const GlObjectCensus during = takeGlObjectCensus();
        EXPECT_EQ(during.vertexArrays, empty.vertexArrays + 1);
        EXPECT_EQ(during.buffers, empty.buffers + 2);
        EXPECT_EQ(during.textures, empty.textures + 1);
        while (app.nextFrame()) {
            glClearColor(0.25f, 0.5f, 1.0f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT);
        }
    }
    EXPECT_EQ(takeGlObjectCensus().total(), empty.total());
    // The clear colour reached the file: 0.25 * 255 = 63.75 -> 64, 0.5 -> 128, 1 -> 255.
    const Image image = readImage(dir / "out.png", 3);
    EXPECT_EQ(image.at(10, 10, 0), 64);
    EXPECT_EQ(image.at(10, 10, 1), 128);
    EXPECT_EQ(image.at(10, 10, 2), 255);
}

TEST(Gl, ALeakedObjectIsReportedAtExit) {
    const fs::path dir = test::testOutputDir("gl_leak");
    ::testing::internal::CaptureStderr();
    {
        App app = makeApp(dir);
        GLuint texture = 0;
        glGenTextures(1, &texture);  // by hand, never deleted
        glBindTexture(GL_TEXTURE_2D, texture);
        while (app.nextFrame()) {
        }
    }
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("gl_test: error: GL objects leaked: 1 texture\n"), std::string::npos) << err;
}

TEST(Gl, ReloadKeepsTheUniformValuesAlreadySet) {
    const fs::path dir = test::testOutputDir("gl_reload");
    App app = makeApp(dir);
    Shader& shader = app.shader("common/pbr.vert", "01_lighting/pbr.frag");
    shader.set("roughness", 0.375f);
    const GLuint before = shader.id();
    ASSERT_TRUE(shader.reload());
    EXPECT_NE(shader.id(), before);  // a new program...
    float value = 0.0f;
    glGetUniformfv(shader.id(), glGetUniformLocation(shader.id(), "roughness"), &value);
    EXPECT_FLOAT_EQ(value, 0.375f);  // ...with the old value
    while (app.nextFrame()) {
    }
}

TEST(Gl, ReloadOfABrokenEditKeepsTheOldProgram) {
    const fs::path dir = test::testOutputDir("gl_reload_broken");
    fs::copy(PBR_SOURCE_SHADER_DIR, dir / "shaders", fs::copy_options::recursive);
    setenv("PBR_SHADER_DIR", (dir / "shaders").c_str(), 1);
    {
        App app = makeApp(dir);
        Shader& shader = app.shader("common/pbr.vert", "01_lighting/pbr.frag");
        const GLuint before = shader.id();
        std::ofstream(dir / "shaders/01_lighting/pbr.frag", std::ios::app)
            << "\nthis is not glsl\n";
        EXPECT_FALSE(shader.reload());
        EXPECT_EQ(shader.id(), before);
        while (app.nextFrame()) {
        }
    }
    unsetenv("PBR_SHADER_DIR");
}

// The irradiance convolution against values known in closed form (stored as irradiance / pi):
// a constant environment L gives L everywhere; an environment bright (1) above the horizon and
// black below gives 1 facing up, 0 facing down and exactly 1/2 facing any horizontal direction
// (by symmetry half of the cosine-weighted hemisphere lies above the horizon).
TEST(Gl, IrradianceOfKnownEnvironments) {
    const fs::path dir = test::testOutputDir("gl_irradiance");
    App app = makeApp(dir);
    auto convolve = [](const HdrImage& image) {
        const Texture2D equirect(image);
        const TextureCube environment = equirectangularToCubemap(equirect, 64);
        return convolveIrradiance(environment, 8);
    };
    HdrImage constant{64, 32, std::vector<float>(64 * 32 * 3, 2.0f)};
    const TextureCube flat = convolve(constant);
    for (int face = 0; face < 6; ++face) {
        for (float texel : flat.readFace(face, 0))
            EXPECT_NEAR(texel, 2.0f, 0.02f) << "face " << face;
    }

    HdrImage sky{64, 32, std::vector<float>(64 * 32 * 3, 0.0f)};
    std::fill(sky.pixels.begin(), sky.pixels.begin() + 64 * 16 * 3, 1.0f);  // top half: up
    const TextureCube halves = convolve(sky);
    auto centre = [&](int face) {
        const std::vector<float> texels = halves.readFace(face, 0);
        // the average of the face's four central texels (8 x 8 face), red channel
        return (texels[(3 * 8 + 3) * 3] + texels[(3 * 8 + 4) * 3] + texels[(4 * 8 + 3) * 3] +
                texels[(4 * 8 + 4) * 3]) /
               4.0f;
    };
    EXPECT_NEAR(centre(2), 1.0f, 0.02f);  // +Y: the whole hemisphere is sky
    EXPECT_NEAR(centre(3), 0.0f, 0.02f);  // -Y: the whole hemisphere is ground
    for (int face : {0, 1, 4, 5}) EXPECT_NEAR(centre(face), 0.5f, 0.03f) << "face " << face;
    while (app.nextFrame()) {
    }
}

// The BRDF LUT (1024 Hammersley samples on the GPU) against a double-precision CPU integration of
// the same integral with 16,384 samples, at 64 texels spread over the table; texel (x, y) must hold
// NdotV = (x + 0.5) / N and roughness = (y + 0.5) / N, the orientation the renderer reads.
TEST(Gl, BrdfLutMatchesACpuIntegration) {
    const fs::path dir = test::testOutputDir("gl_brdf_lut");
    App app = makeApp(dir);
    constexpr int kSize = 64;
    const Texture2D lut = computeBrdfLut(kSize, 1024);
    const std::vector<float> texels = lut.readFloats(2);
    double worst = 0.0;
    for (int y = 3; y < kSize; y += 8) {
        for (int x = 3; x < kSize; x += 8) {
            const glm::dvec2 cpu = cpu::integrateBrdf((x + 0.5) / kSize, (y + 0.5) / kSize, 16384);
            const size_t i = (size_t(y) * kSize + size_t(x)) * 2;
            worst = std::max({worst, std::abs(texels[i] - cpu.x), std::abs(texels[i + 1] - cpu.y)});
            EXPECT_NEAR(texels[i], cpu.x, 0.01)
                << "scale at NdotV " << (x + 0.5) / kSize << ", roughness " << (y + 0.5) / kSize;
            EXPECT_NEAR(texels[i + 1], cpu.y, 0.01)
                << "bias at NdotV " << (x + 0.5) / kSize << ", roughness " << (y + 0.5) / kSize;
        }
    }
    std::printf("BRDF LUT: worst difference from the 16k-sample CPU integral %.5f\n", worst);
    // smooth and head-on: almost all of F0 comes back (scale near 1, bias near 0)
    const size_t corner = (size_t(0) * kSize + size_t(kSize - 1)) * 2;
    EXPECT_GT(texels[corner], 0.9f);
    EXPECT_LT(texels[corner + 1], 0.05f);
    while (app.nextFrame()) {
    }
}

TEST(Gl, MoreSamplesThanTheDriverAllowsIsAClearError) {
    const fs::path dir = test::testOutputDir("gl_msaa");
    try {
        makeApp(dir, {"--msaa", "16"});
        FAIL() << "16x MSAA accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("--msaa 16: this GL allows at most"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace pbr
