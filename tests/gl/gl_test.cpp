// The helper library inside a real (offscreen) GL context: the error detector, object ownership,
// shader reload, the render target. Each test makes its own headless App.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <numbers>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>

#include "app/app.h"
#include "base/error.h"
#include "base/output.h"
#include "base/paths.h"
#include "context/context.h"
#include "files/ktx.h"
#include "files/mip_chain.h"
#include "gl/framebuffer.h"
#include "gl/light_buffer.h"
#include "gl/mesh.h"
#include "gl/texture.h"
#include "gltf/gltf_renderer.h"
#include "gltf/model.h"
#include "ibl/ibl.h"
#include "ibl/ibl_cache.h"
#include "math/brdf.h"
#include "math/cube_geometry.h"
#include "math/gltf_extensions.h"
#include "math/sphere_grid.h"
#include "math/tonemap.h"
#include "support/build_paths.h"
#include "support/mesh_hit.h"
#include "support/process.h"

namespace pbr {
namespace {

namespace fs = std::filesystem;

// The command line of a headless App as a sample would make it, drawing into `dir`.
std::vector<std::string> appArguments(const fs::path& dir, const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"gl_test", "--headless", "--size",
                                     "64x36",   "--output",   (dir / "out.png").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
}

App makeApp(const fs::path& dir, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = appArguments(dir, extra);
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    return App(int(argv.size()), argv.data(), {.name = "gl_test"});
}

// The same on the heap, for a test that may find the App cannot be made.
std::unique_ptr<App> newApp(const fs::path& dir, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = appArguments(dir, extra);
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    return std::make_unique<App>(int(argv.size()), argv.data(), AppConfig{.name = "gl_test"});
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

// A framebuffer of the test's own, bound with its viewport: a colour renderbuffer of `format`
// and, when asked, a depth one.
struct TestTarget {
    GlFramebuffer framebuffer;
    GlRenderbuffer color, depth;
    TestTarget(int width, int height, GLenum format, bool withDepth, const char* what) {
        glBindRenderbuffer(GL_RENDERBUFFER, color.id());
        glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                  color.id());
        if (withDepth) {
            glBindRenderbuffer(GL_RENDERBUFFER, depth.id());
            glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                      depth.id());
        }
        requireCompleteFramebuffer(what);
        glViewport(0, 0, width, height);
    }
};

// No GL error can vanish: with KHR_debug's messages muted, or debug output switched off, three
// GL_INVALID_ENUMs still fail the run (glGetError is always asked), on every offscreen backend.
// And where the platform can make a debug context (EGL), the App asks for one.
TEST(Gl, ErrorsFailTheRunEvenWithDebugMessagesMuted) {
    const fs::path dir = test::testOutputDir("gl_error_muted");
    for (const std::string& backend : offscreenBackends()) {
        for (const bool switchedOff : {false, true}) {
            std::unique_ptr<App> made;
            try {
                made = newApp(dir, {"--backend", backend});
            } catch (const Error& e) {
                if (std::string(e.what()).rfind(backend + ":", 0) != 0) throw;
                std::printf("skipped %s: %s\n", backend.c_str(), e.what());  // not on this machine
                break;
            }
            App& app = *made;
            ASSERT_TRUE(app.nextFrame());
            if (backend.starts_with("egl")) {
                GLint flags = 0;
                glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
                EXPECT_TRUE(flags & GL_CONTEXT_FLAG_DEBUG_BIT)
                    << backend << ": not a debug context";
            }
            if (GLAD_GL_KHR_debug) {
                if (switchedOff)
                    glDisable(GL_DEBUG_OUTPUT);
                else
                    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr,
                                          GL_FALSE);
            }
            for (int i = 0; i < 3; ++i) glEnable(0x1234);  // not a capability: GL_INVALID_ENUM
            try {
                while (app.nextFrame()) {
                }
                ADD_FAILURE() << backend << (switchedOff ? ", debug output off" : ", muted")
                              << ": the errors vanished and the run ended normally";
            } catch (const Error& e) {
                const std::string message = e.what();
                EXPECT_NE(message.find("OpenGL error(s) during the run; first: GL_INVALID_ENUM"),
                          std::string::npos)
                    << backend << ": " << message;
            }
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
    fs::copy(PBR_PATH(PBR_SOURCE_SHADER_DIR), dir / "shaders", fs::copy_options::recursive);
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

// The BRDF LUT (1024 Hammersley samples on the GPU) against the CPU's numerical quadrature of the
// same integrals (pbr::cpu::splitSumQuadrature, sheenQuadrature, sheenAlbedoQuadrature: no
// sampling), at 64 texels spread over the table; texel (x, y) must hold NdotV = (x + 0.5) / N and
// roughness = (y + 0.5) / N, the orientation the renderer reads. All four channels within 0.01
// (the estimates' noise at 1024 samples, and half floats).
TEST(Gl, BrdfLutMatchesACpuIntegration) {
    const fs::path dir = test::testOutputDir("gl_brdf_lut");
    App app = makeApp(dir);
    constexpr int kSize = 64;
    const Texture2D lut = computeBrdfLut(kSize, 1024, BrdfLutChannels::ScaleBiasSheen);
    const std::vector<float> texels = lut.readFloats(4);
    double worst = 0.0, worstSheen = 0.0, largestSheen = 0.0, worstAlbedo = 0.0, largestAlbedo = 0.0;
    for (int y = 3; y < kSize; y += 8) {
        for (int x = 3; x < kSize; x += 8) {
            const double NdotV = (x + 0.5) / kSize, roughness = (y + 0.5) / kSize;
            const glm::dvec2 cpu = cpu::splitSumQuadrature(NdotV, roughness);
            const double sheen = cpu::sheenQuadrature(NdotV, roughness);
            const double albedo = cpu::sheenAlbedoQuadrature(NdotV, roughness);
            const size_t i = (size_t(y) * kSize + size_t(x)) * 4;
            worst = std::max({worst, std::abs(texels[i] - cpu.x), std::abs(texels[i + 1] - cpu.y)});
            worstSheen = std::max(worstSheen, std::abs(texels[i + 2] - sheen));
            largestSheen = std::max(largestSheen, sheen);
            worstAlbedo = std::max(worstAlbedo, std::abs(texels[i + 3] - albedo));
            largestAlbedo = std::max(largestAlbedo, albedo);
            EXPECT_NEAR(texels[i], cpu.x, 0.01)
                << "scale at NdotV " << NdotV << ", roughness " << roughness;
            EXPECT_NEAR(texels[i + 1], cpu.y, 0.01)
                << "bias at NdotV " << NdotV << ", roughness " << roughness;
            EXPECT_NEAR(texels[i + 2], sheen, 0.01)
                << "sheen at NdotV " << NdotV << ", roughness " << roughness;
            EXPECT_NEAR(texels[i + 3], albedo, 0.01)
                << "sheen albedo (Charlie's visibility) at NdotV " << NdotV << ", roughness "
                << roughness;
        }
    }
    // The glTF samples' table (07, 08, 10): the same two channels with glTF's V_GGX.
    const Texture2D gltfLut = computeBrdfLut(kSize, 1024, BrdfLutChannels::GltfScaleBias);
    const std::vector<float> gltfTexels = gltfLut.readFloats(2);
    double worstGltf = 0.0, largestGap = 0.0;
    for (int y = 3; y < kSize; y += 8) {
        for (int x = 3; x < kSize; x += 8) {
            const double NdotV = (x + 0.5) / kSize, roughness = (y + 0.5) / kSize;
            const glm::dvec2 cpu = cpu::gltfSplitSumQuadrature(NdotV, roughness);
            const size_t i = (size_t(y) * kSize + size_t(x)) * 2;
            worstGltf = std::max(
                {worstGltf, std::abs(gltfTexels[i] - cpu.x), std::abs(gltfTexels[i + 1] - cpu.y)});
            // the two tables differ where it matters (else the check above proves nothing new)
            const glm::dvec2 texts = cpu::splitSumQuadrature(NdotV, roughness);
            largestGap = std::max(largestGap, (cpu.x + cpu.y) - (texts.x + texts.y));
            EXPECT_NEAR(gltfTexels[i], cpu.x, 0.01)
                << "glTF scale at NdotV " << NdotV << ", roughness " << roughness;
            EXPECT_NEAR(gltfTexels[i + 1], cpu.y, 0.01)
                << "glTF bias at NdotV " << NdotV << ", roughness " << roughness;
        }
    }
    EXPECT_GT(largestGap, 0.1);
    std::printf(
        "BRDF LUT: worst difference from the CPU quadrature %.5f (R, G), "
        "%.5f (B, largest value %.4f), %.5f (A, largest value %.4f); glTF's %.5f (its white "
        "lobe's albedo up to %.4f above the texts')\n",
        worst, worstSheen, largestSheen, worstAlbedo, largestAlbedo, worstGltf, largestGap);
    EXPECT_GT(largestSheen, 0.3);  // the comparisons above are not between two zeros
    EXPECT_GT(largestAlbedo, 0.3);
    // smooth and head-on: almost all of F0 comes back (scale near 1, bias near 0)
    const size_t corner = (size_t(0) * kSize + size_t(kSize - 1)) * 4;
    EXPECT_GT(texels[corner], 0.9f);
    EXPECT_LT(texels[corner + 1], 0.05f);
    while (app.nextFrame()) {
    }
}

// The BRDF LUTs the build baked (resources/ibl, read by 05-08 instead of computing them) hold
// the bytes pbr::computeBrdfLut makes here, metadata and all: the build ran the same code.
TEST(Gl, BakedBrdfLutsAreWhatTheCodeMakes) {
    const fs::path dir = test::testOutputDir("gl_baked_lut");
    App app = makeApp(dir);
    for (const auto& [size, channels] : {std::pair{512, BrdfLutChannels::ScaleBias},
                                         std::pair{256, BrdfLutChannels::ScaleBiasSheen},
                                         std::pair{512, BrdfLutChannels::GltfScaleBias}}) {
        const MapFile file = brdfLutFile(size, 1024, channels);
        const KtxImage baked = readKtx(iblDir() / file.name);
        const KtxImage made =
            file.withMetadata(computeBrdfLut(size, 1024, channels).toKtx(brdfLutFormat(channels)));
        EXPECT_EQ(baked.metadata, made.metadata) << file.name;
        ASSERT_EQ(baked.images.size(), 1u) << file.name;
        EXPECT_TRUE(baked.images == made.images) << file.name << ": other texels";
    }
    while (app.nextFrame()) {
    }
}

// The prefiltered map's level 0 is the mirror (roughness 0): the environment itself, averaged
// over each texel's footprint. Its 128^2 texel centres coincide with those of the 512^2
// environment's mip level 2 (each the box average of 4 x 4 source texels), so the two must agree
// to half-float precision: 0.2 % relative, two steps of a half's 11-bit significand (measured: one
// step, 0.1 %), over the project's environment, sun (thousands of times the sky) included. A read
// one mip level off would miss by whole percents at every edge of the checkerboard.
TEST(Gl, PrefilteredLevelZeroIsTheSource) {
    const fs::path dir = test::testOutputDir("gl_prefilter");
    App app = makeApp(dir);
    const TextureCube environment =
        equirectangularToCubemap(Texture2D(readHdr(environmentDir() / "sunny_courtyard.hdr")), 512);
    const TextureCube prefiltered = prefilterSpecular(environment, 128, 5, 64);
    float brightest = 0.0f, worst = 0.0f;
    for (int face = 0; face < 6; ++face) {
        const std::vector<float> mirror = prefiltered.readFace(face, 0);
        const std::vector<float> source = environment.readFace(face, 2);
        ASSERT_EQ(mirror.size(), source.size());
        for (size_t i = 0; i < mirror.size(); ++i) {
            brightest = std::max(brightest, source[i]);
            worst = std::max(worst, std::abs(mirror[i] - source[i]) / std::max(source[i], 1e-3f));
            ASSERT_NEAR(mirror[i], source[i], 2e-3f * std::max(source[i], 1e-3f))
                << "face " << face << ", texel " << i / 3 << ", channel " << i % 3;
        }
    }
    std::printf("prefiltered level 0: worst relative difference %.6f, brightest texel %.0f\n",
                worst, brightest);
    EXPECT_GT(brightest, 100.0f);  // the sun is in the comparison
    while (app.nextFrame()) {
    }
}

// A small sun thousands of times brighter than the sky, through the three convolutions, against
// sums in double precision over every texel of the environment they read (exact solid angles):
// for the irradiance (1/pi) sum L max(0, N.L) dOmega, for the prefiltered levels 1-4
// sum L N.L D(H) dOmega / sum N.L D(H) dOmega with N = V, and the same with the sheen's
// D_Charlie for the sheen map's levels 0-4 (sheen roughness 0.1, 0.25 ... 1). All keep the sun's
// texels apart and sum them exactly (pbr::splitBrightTexels); sampling it instead, as the text
// does, misses by tens of percent next to the sun (and leaving it out, or weighting it wrongly,
// by more). Every texel of every level within 1 % (measured: 0.1 % for the first two; the sheen
// map 0.5 % at sheen roughness 0.1, whose lobe lies within 2 degrees of the horizon, and 0.1 %
// above; planted, the sheen's rings weighted without N.L, 98 %).
TEST(Gl, ConvolutionsOfASunMatchSumsOverEveryTexel) {
    const fs::path dir = test::testOutputDir("gl_sun");
    App app = makeApp(dir);
    HdrImage sky{128, 64, std::vector<float>(128 * 64 * 3, 1.0f)};
    for (int y = 20; y < 22; ++y) {  // a 2 x 2 pixel sun, 40 degrees up
        for (int x = 40; x < 42; ++x) {
            for (int c = 0; c < 3; ++c) sky.pixels[size_t((y * 128 + x) * 3 + c)] = 20000.0f;
        }
    }
    const TextureCube environment = equirectangularToCubemap(Texture2D(sky), 64);
    const TextureCube irradiance = convolveIrradiance(environment, 8);
    const TextureCube prefiltered = prefilterSpecular(environment, 32, 5, 256);
    const TextureCube sheen = prefilterSheen(environment, 16, 5);

    // what the convolutions read: the environment's level 0, every texel
    struct Texel {
        glm::dvec3 direction, radiance;
        double solidAngle;
    };
    std::vector<Texel> texels;
    constexpr int kN = 64;
    for (int face = 0; face < 6; ++face) {
        const std::vector<float> rgb = environment.readFace(face, 0);
        for (int j = 0; j < kN; ++j) {
            for (int i = 0; i < kN; ++i) {
                const size_t k = (size_t(j) * kN + size_t(i)) * 3;
                texels.push_back(
                    {cubeFaceDirection(face, cubeTexelCentre(i, kN), cubeTexelCentre(j, kN)),
                     glm::dvec3(rgb[k], rgb[k + 1], rgb[k + 2]), cubeTexelSolidAngle(i, j, kN)});
            }
        }
    }
    auto referenceIrradiance = [&](const glm::dvec3& N) {
        double sum = 0.0;
        for (const Texel& t : texels)
            sum += t.radiance.g * std::max(0.0, glm::dot(N, t.direction)) * t.solidAngle;
        return sum / std::numbers::pi;
    };
    auto referencePrefiltered = [&](const glm::dvec3& N, double roughness) {
        const double a2 = std::pow(roughness, 4.0);
        double sum = 0.0, weights = 0.0;
        for (const Texel& t : texels) {
            const double NdotL = glm::dot(N, t.direction);
            if (NdotL <= 0.0) continue;
            const double NdotH = glm::dot(N, glm::normalize(N + t.direction));
            const double denom = NdotH * NdotH * (a2 - 1.0) + 1.0;
            const double weight = NdotL * a2 / (std::numbers::pi * denom * denom) * t.solidAngle;
            sum += t.radiance.g * weight;
            weights += weight;
        }
        return sum / weights;
    };
    auto referenceSheen = [&](const glm::dvec3& N, double roughness) {
        const float alpha = float(roughness * roughness);
        double sum = 0.0, weights = 0.0;
        for (const Texel& t : texels) {
            const double NdotL = glm::dot(N, t.direction);
            if (NdotL <= 0.0) continue;
            const double NdotH = glm::dot(N, glm::normalize(N + t.direction));
            const double weight = NdotL * cpu::D_Charlie(float(NdotH), alpha) * t.solidAngle;
            sum += t.radiance.g * weight;
            weights += weight;
        }
        return sum / weights;
    };
    // every texel of a map level against the reference; the worst relative error
    auto worstError = [](const TextureCube& map, int level, const auto& reference) {
        const int n = std::max(1, map.size() >> level);
        double worst = 0.0, largest = 0.0;
        for (int face = 0; face < 6; ++face) {
            const std::vector<float> rgb = map.readFace(face, level);
            for (int j = 0; j < n; ++j) {
                for (int i = 0; i < n; ++i) {
                    const double expected = reference(
                        cubeFaceDirection(face, cubeTexelCentre(i, n), cubeTexelCentre(j, n)));
                    const double got = rgb[(size_t(j) * size_t(n) + size_t(i)) * 3 + 1];
                    worst = std::max(worst, std::abs(got - expected) / expected);
                    largest = std::max(largest, expected);
                }
            }
        }
        EXPECT_GT(largest, 3.0) << "level " << level << ": the sun is not in the comparison";
        return worst;
    };
    const double irradianceError = worstError(irradiance, 0, referenceIrradiance);
    EXPECT_LT(irradianceError, 0.01);
    std::printf("sun: irradiance worst %.4f; prefiltered worst", irradianceError);
    for (int level = 1; level < 5; ++level) {
        const double roughness = level / 4.0;
        const double error = worstError(prefiltered, level, [&](const glm::dvec3& N) {
            return referencePrefiltered(N, roughness);
        });
        std::printf(" L%d %.4f", level, error);
        EXPECT_LT(error, 0.01) << "level " << level;
    }
    std::printf("; sheen worst");
    for (int level = 0; level < 5; ++level) {
        const double roughness = std::max(level / 4.0, double(kMinSheenMapRoughness));
        const double error = worstError(sheen, level, [&](const glm::dvec3& N) {
            return referenceSheen(N, roughness);
        });
        std::printf(" L%d %.4f", level, error);
        EXPECT_LT(error, 0.01) << "sheen level " << level;
    }
    std::printf("\n");
    while (app.nextFrame()) {
    }
}

// The white furnace: an environment of radiance 1 all round, and two rows of 11 unit spheres
// (row 0 below, row 1 above; roughness col / 10 across) seen from (0, 0, 17) into a float
// target. A lossless white surface would come out 1 everywhere. The expected values come from
// the CPU's numerical quadrature of the single-scattering GGX lobe (pbr::cpu::splitSumQuadrature:
// scale A and bias B at the pixel's NdotV and roughness), never from a shader's formula. Pixels
// whose NdotV is below 0.15 are left out: there the 64 x 64 sphere's interpolated normals part
// from the CPU's exact sphere.
class WhiteFurnace {
public:
    static constexpr int kWidth = 880, kHeight = 320, kColumns = 11;
    static double roughnessOf(int col) { return double(col) / double(kColumns - 1); }

    WhiteFurnace()
        : white_(HdrImage{64, 32, std::vector<float>(64 * 32 * 3, 1.0f)}),
          environment_(equirectangularToCubemap(white_, 64)),
          irradiance_(convolveIrradiance(environment_, 8)),
          prefiltered_(prefilterSpecular(environment_, 32, 5, 256)),
          lut_(computeBrdfLut(256, 1024)),
          target_(kWidth, kHeight, GL_RGBA32F, true, "furnace target") {
        for (int col = 0; col < kColumns; ++col) {
            for (int i = 0; i <= kTable; ++i) {
                table_[size_t(col)].push_back(
                    cpu::splitSumQuadrature(std::max(double(i) / kTable, 1e-4), roughnessOf(col)));
            }
        }
        glEnable(GL_DEPTH_TEST);
    }

    // The camera's and the maps' uniforms, the maps bound from `firstUnit` on.
    void setUp(Shader& shader, int firstUnit) const {
        shader.set("projection",
                   glm::perspective(float(kFovY), float(kWidth) / float(kHeight), 0.1f, 100.0f));
        shader.set("view", glm::lookAt(glm::vec3(kCamera), glm::vec3(0.0f), glm::vec3(0, 1, 0)));
        shader.set("camPos", glm::vec3(kCamera));
        useIblMaps(shader, environment_, irradiance_, prefiltered_, lut_, firstUnit);
    }

    // Draws every sphere through `draw(row, col)` (which sets the material) and reads the target.
    std::vector<float> render(Shader& shader, const std::function<void(int, int)>& draw) const {
        glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer.id());
        glViewport(0, 0, kWidth, kHeight);
        glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        for (int row = 0; row < 2; ++row) {
            for (int col = 0; col < kColumns; ++col) {
                draw(row, col);
                shader.setModel(glm::translate(glm::mat4(1.0f), glm::vec3(centre(row, col))));
                sphere_.draw();
            }
        }
        std::vector<float> pixels(size_t(kWidth) * kHeight * 4);
        glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, pixels.data());
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return pixels;
    }

    // The quadrature's (A, B) of sphere column `col` at NdotV, read linearly from a table.
    glm::dvec2 scaleBias(int col, double NdotV) const {
        const double x = NdotV * kTable;
        const int i = std::min(int(x), kTable - 1);
        return glm::mix(table_[size_t(col)][size_t(i)], table_[size_t(col)][size_t(i) + 1], x - i);
    }

    // Every pixel whose ray (through its centre) meets a sphere at NdotV >= 0.15: the nearest
    // hit wins (a neighbour can hide a rim). Fails the test where nothing was drawn there.
    void forEachPixel(
        const std::vector<float>& pixels,
        const std::function<void(int row, int col, double NdotV, const float* rgba)>& visit) const {
        for (const Hit& hit : hits_) {
            const float* rgba = &pixels[hit.pixel * 4];
            ASSERT_EQ(rgba[3], 1.0f)
                << "no sphere drawn at pixel " << hit.pixel % kWidth << ", " << hit.pixel / kWidth;
            visit(hit.row, hit.col, hit.NdotV, rgba);
        }
    }

    // One sphere's values against their expected ones: how many lie outside +- `band`.
    struct Stats {
        double lowest = 1e9, highest = -1e9, sum = 0.0, band = 0.02;
        int count = 0, outside = 0;
        void add(double value, double expected) {
            if (std::abs(value - expected) > band) ++outside;
            lowest = std::min(lowest, value);
            highest = std::max(highest, value);
            sum += value;
            ++count;
        }
        double mean() const { return sum / count; }
    };

private:
    static constexpr double kFovY = 45.0 * std::numbers::pi / 180.0;
    static constexpr int kTable = 32;
    inline static const glm::dvec3 kCamera{0.0, 0.0, 17.0};
    static glm::dvec3 centre(int row, int col) {
        return glm::dvec3((col - kColumns / 2) * 2.2, row == 1 ? 1.25 : -1.25, 0.0);
    }

    // The pixels' rays against the spheres, worked out once.
    struct Hit {
        size_t pixel;
        int row, col;
        double NdotV;
    };
    static std::vector<Hit> traceHits() {
        std::vector<Hit> hits;
        const double tanHalf = std::tan(kFovY / 2.0), aspect = double(kWidth) / kHeight;
        for (int py = 0; py < kHeight; ++py) {
            for (int px = 0; px < kWidth; ++px) {
                const glm::dvec3 ray =
                    glm::normalize(glm::dvec3((2.0 * (px + 0.5) / kWidth - 1.0) * tanHalf * aspect,
                                              (2.0 * (py + 0.5) / kHeight - 1.0) * tanHalf, -1.0));
                double nearest = 1e9;
                int row = -1, col = -1;
                for (int r = 0; r < 2; ++r) {
                    for (int c = 0; c < kColumns; ++c) {
                        const glm::dvec3 oc = kCamera - centre(r, c);
                        const double b = glm::dot(oc, ray), d = b * b - glm::dot(oc, oc) + 1.0;
                        if (d > 0.0 && -b - std::sqrt(d) < nearest) {
                            nearest = -b - std::sqrt(d);
                            row = r;
                            col = c;
                        }
                    }
                }
                if (row < 0) continue;
                const glm::dvec3 N = glm::normalize(kCamera + ray * nearest - centre(row, col));
                const double NdotV = glm::dot(N, -ray);
                if (NdotV >= 0.15)
                    hits.push_back({size_t(py) * kWidth + size_t(px), row, col, NdotV});
            }
        }
        return hits;
    }

    std::vector<Hit> hits_ = traceHits();
    Texture2D white_;
    TextureCube environment_, irradiance_, prefiltered_;
    Texture2D lut_;
    TestTarget target_;
    GpuMesh sphere_{uvSphere(64, 64)};
    std::array<std::vector<glm::dvec2>, kColumns> table_;
};

// Sample 05's own shader and IBL maps, white spheres (albedo 1, ao 1, no point lights, row =
// metallic), drawn with both forms of the ambient term (shaders/include/ibl_ambient.glsl):
//   white metal, either form: A + B, the lobe's directional albedo (it loses light that bounces
//     between microfacets more than once: nothing for a mirror, more with roughness);
//   white dielectric, the exact form: 1 (the light the lobe does not reflect, 1 - (0.04 A + B),
//     is what the diffuse layer takes), never above 1;
//   white dielectric, the text's form: it multiplies the scale by a Fresnel term of the view
//     angle although the scale has Fresnel inside, and gains energy towards the rim of smooth
//     spheres: the README's figure, 1.24 at roughness 0, is held here.
// Each band: the expected value +- 0.02 (the LUT is 16-bit at 256^2 texels and 1024 samples,
// the irradiance within 1 %). The tone map is undone exactly.
TEST(Gl, WhiteFurnace) {
    const fs::path dir = test::testOutputDir("gl_furnace");
    App app = makeApp(dir);
    const WhiteFurnace furnace;
    Shader& shader = app.shader("common/pbr.vert", "05_ibl_specular/pbr.frag");
    furnace.setUp(shader, 0);
    shader.set("albedo", glm::vec3(1.0f));
    shader.set("ao", 1.0f);
    shader.set("lightCount", 0);
    auto render = [&](bool exact) {
        shader.set("exactSplitSum", exact ? 1 : 0);
        return furnace.render(shader, [&](int metallic, int col) {
            shader.set("metallic", float(metallic));
            shader.set("roughness", float(WhiteFurnace::roughnessOf(col)));
        });
    };
    const std::vector<float> textForm = render(false), exactForm = render(true);

    constexpr int kColumns = WhiteFurnace::kColumns;
    std::array<WhiteFurnace::Stats, 2 * kColumns> text{}, exact{};
    auto radiance = [](float encoded) {  // undo gamma 1/2.2, then Reinhard
        const double x = std::pow(double(encoded), 2.2);
        return x / (1.0 - x);
    };
    auto expected = [&](int metallic, int col, double NdotV) {
        const glm::dvec2 ab = furnace.scaleBias(col, NdotV);
        return metallic == 1 ? ab.x + ab.y : 1.0;
    };
    furnace.forEachPixel(textForm, [&](int metallic, int col, double NdotV, const float* rgba) {
        text[size_t(metallic * kColumns + col)].add(radiance(rgba[0]),
                                                    expected(metallic, col, NdotV));
    });
    furnace.forEachPixel(exactForm, [&](int metallic, int col, double NdotV, const float* rgba) {
        exact[size_t(metallic * kColumns + col)].add(radiance(rgba[0]),
                                                     expected(metallic, col, NdotV));
    });
    for (int metallic = 0; metallic < 2; ++metallic) {
        for (int col = 0; col < kColumns; ++col) {
            const size_t i = size_t(metallic * kColumns + col);
            const double roughness = WhiteFurnace::roughnessOf(col);
            ASSERT_GT(text[i].count, 500)
                << "sphere " << metallic << ", " << col << " barely visible";
            std::printf(
                "furnace metallic %d roughness %.1f: text form %.3f..%.3f, exact %.3f..%.3f "
                "(mean %.3f)\n",
                metallic, roughness, text[i].lowest, text[i].highest, exact[i].lowest,
                exact[i].highest, exact[i].mean());
            // The exact form: every sphere within its band, and no pixel above 1.
            EXPECT_EQ(exact[i].outside, 0)
                << exact[i].outside << " of " << exact[i].count << " pixels of the sphere metallic "
                << metallic << ", roughness " << roughness << " outside the band (exact form)";
            EXPECT_LE(exact[i].highest, 1.0 + 0.02) << "the exact form gains energy";
            // The text's form: metals within the band (their F is 1, the forms agree).
            if (metallic == 1) {
                EXPECT_EQ(text[i].outside, 0)
                    << text[i].outside << " pixels of the metal sphere of roughness " << roughness
                    << " outside the band (text's form)";
            }
        }
    }
    // The text's form on a smooth dielectric: 1.24 towards the rim, as the README says.
    EXPECT_NEAR(text[0].highest, 1.24, 0.02);
    EXPECT_GT(text[1].highest, 1.15);
    // A white mirror in a white furnace vanishes: exactly 1 all over.
    EXPECT_NEAR(exact[kColumns].lowest, 1.0, 0.02);
    EXPECT_NEAR(exact[kColumns].highest, 1.0, 0.02);
    // Single scattering loses energy with roughness: the roughest metal keeps well under 90 %.
    EXPECT_LT(exact[2 * kColumns - 1].mean(), 0.9);
    while (app.nextFrame()) {
    }
}

// The glTF samples' shader (shaders/common/gltf.frag, 07 and 08) in the same furnace: white
// base colour, metallic 0 (row 0) and 1 (row 1), each with multiple scattering (the default) and
// without (--single-scattering). Exposure 0.5 and no tone mapping keep values up to 2 readable.
//   multiple scattering: 1 for the white metal at every roughness (the energy the single lobe
//     loses, 1 - (A + B), comes back in full when every bounce reflects all: the closed form of
//     the compensation's geometric series at F0 = 1), and 1 for the white dielectric;
//   single scattering: A + B for the metal (0.89, 0.60, 0.31 of the environment at roughness 0.5,
//     0.75, 1 at NdotV = 1), 1 for the dielectric;
//   a half metal (metallic 0.5, drawn as a third pass): the mean of the two, so 1 with multiple
//     scattering and (1 + A + B) / 2 without: the specification mixes two whole BRDFs.
// Bands: +- 0.02 as above; the multiple-scattering metal +- 0.03 (the LUT's A + B is used twice).
TEST(Gl, GltfWhiteFurnaceWithAndWithoutMultipleScattering) {
    const fs::path dir = test::testOutputDir("gl_gltf_furnace");
    App app = makeApp(dir);
    const WhiteFurnace furnace;
    Shader& shader = app.shader("common/gltf.vert", "common/gltf.frag");
    const GltfRenderer renderer([&](const std::vector<std::string>&) -> Shader& { return shader; });
    renderer.setUnits(shader, {});
    GltfRenderer::setLights(shader, {});
    furnace.setUp(shader, GltfRenderer::kFirstIblUnit);
    const Texture2D white(Image{1, 1, 4, {255, 255, 255, 255}}, ColorSpace::Linear);
    for (int unit = 0; unit < 5; ++unit) white.bind(unit);
    shader.set("useIbl", 1);
    shader.set("usePunctual", 0);
    shader.set("toneMapper", 0);  // none
    shader.set("exposure", 0.5f);
    shader.set("unlit", 0);
    shader.set("specularGlossiness", 0);
    shader.set("hasNormalTexture", 0);
    shader.set("occlusionStrength", 1.0f);
    shader.set("alphaMode", 0);
    shader.set("baseColorFactor", glm::vec4(1.0f));
    shader.set("emissiveFactor", glm::vec3(0.0f));
    for (const char* slot : {"baseColor", "metallicRoughness", "normal", "occlusion", "emissive"}) {
        shader.set(std::string(slot) + "UvSet", 0);
        shader.set(std::string(slot) + "UvTransform", glm::mat3(1.0f));
    }
    constexpr int kColumns = WhiteFurnace::kColumns;
    for (const bool multiple : {true, false}) {
        shader.set("multipleScattering", multiple ? 1 : 0);
        for (const bool half : {false, true}) {
            const std::vector<float> pixels = furnace.render(shader, [&](int row, int col) {
                shader.set("metallicFactor", half ? 0.5f : float(row));
                shader.set("roughnessFactor", float(WhiteFurnace::roughnessOf(col)));
            });
            std::array<WhiteFurnace::Stats, 2 * kColumns> stats{};
            furnace.forEachPixel(pixels, [&](int row, int col, double NdotV, const float* rgba) {
                const glm::dvec2 ab = furnace.scaleBias(col, NdotV);
                const double metal = multiple ? 1.0 : ab.x + ab.y;
                const double expected = half ? 0.5 * (1.0 + metal) : row == 1 ? metal : 1.0;
                WhiteFurnace::Stats& s = stats[size_t(row * kColumns + col)];
                s.band = multiple && (half || row == 1) ? 0.03 : 0.02;
                for (int c = 0; c < 3; ++c) s.add(2.0 * rgba[c], expected);
            });
            for (int row = 0; row < 2; ++row) {
                for (int col = 0; col < kColumns; ++col) {
                    const WhiteFurnace::Stats& s = stats[size_t(row * kColumns + col)];
                    ASSERT_GT(s.count, 1500)
                        << "sphere " << row << ", " << col << " barely visible";
                    std::printf(
                        "glTF furnace, %s scattering, metallic %.1f, roughness %.1f: "
                        "%.3f..%.3f (mean %.3f)\n",
                        multiple ? "multiple" : "single", half ? 0.5 : double(row),
                        WhiteFurnace::roughnessOf(col), s.lowest, s.highest, s.mean());
                    EXPECT_EQ(s.outside, 0)
                        << s.outside << " of " << s.count << " values outside the band ("
                        << (multiple ? "multiple" : "single") << " scattering, metallic "
                        << (half ? 0.5 : double(row)) << ", roughness "
                        << WhiteFurnace::roughnessOf(col) << ")";
                }
            }
        }
    }
    while (app.nextFrame()) {
    }
}

// A non-uniformly scaled object: normals go through the inverse transpose of the model matrix
// (mat3(model), the text's shortcut, is right only for rotations and uniform scales). A sphere
// stretched (2, 0.6, 1) and turned, drawn with 01's own shaders into an 8-bit target without
// MSAA, against the CPU shading the same triangles (support/mesh_hit.h), whose normal matrix is
// its own; within 2/255 wherever the picture is steady.
TEST(Gl, NormalsUnderANonUniformScaleMatchTheCpu) {
    const fs::path dir = test::testOutputDir("gl_normal_matrix");
    App app = makeApp(dir, {"--msaa", "0"});
    constexpr int kWidth = 320, kHeight = 240;
    constexpr double kFovY = glm::radians(45.0);
    const glm::dvec3 camera(0.0, 0.0, 6.0);
    const glm::dmat4 model = glm::rotate(glm::scale(glm::dmat4(1.0), glm::dvec3(2.0, 0.6, 1.0)),
                                         0.7, glm::dvec3(0.3, 1.0, 0.2));
    const std::array<cpu::PointLight, 2> lights = {{
        {{4.0f, 3.0f, 4.0f}, {60.0f, 60.0f, 60.0f}},
        {{-4.0f, -1.0f, 3.0f}, {30.0f, 30.0f, 30.0f}},
    }};

    const TestTarget target(kWidth, kHeight, GL_RGBA8, true, "normal-matrix target");
    glEnable(GL_DEPTH_TEST);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    Shader& shader = app.shader("common/pbr.vert", "01_lighting/pbr.frag");
    shader.set("projection",
               glm::perspective(float(kFovY), float(kWidth) / float(kHeight), 0.1f, 100.0f));
    shader.set("view", glm::lookAt(glm::vec3(camera), glm::vec3(0.0f), glm::vec3(0, 1, 0)));
    shader.set("camPos", glm::vec3(camera));
    shader.set("albedo", glm::vec3(0.2f, 0.5f, 0.8f));
    shader.set("ao", 1.0f);
    shader.set("metallic", 0.3f);
    shader.set("roughness", 0.45f);
    const std::array<glm::vec3, 2> positions = {lights[0].position, lights[1].position};
    setPointLights(shader, positions, glm::vec3(0.0f));
    shader.set("lightColors[0]", lights[0].color);
    shader.set("lightColors[1]", lights[1].color);
    shader.setModel(glm::mat4(model));
    const MeshData sphere = uvSphere(64, 64);
    const GpuMesh gpuSphere(sphere);
    gpuSphere.draw();
    std::vector<std::uint8_t> pixels(size_t(kWidth) * kHeight * 4);
    glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    const glm::dvec3 front = glm::normalize(-camera);
    auto predict = [&](double x, double y) -> std::optional<glm::dvec3> {
        const glm::dvec3 ray = test::cameraRay(front, kFovY, kWidth, kHeight, x, y);
        const auto hit = test::hitUvSphere(sphere, 64, 64, model, camera, ray);
        if (!hit) return std::nullopt;
        cpu::SurfacePoint surface;
        surface.position = glm::vec3(hit->position);
        surface.normal = glm::vec3(hit->normal);
        surface.albedo = {0.2f, 0.5f, 0.8f};
        surface.metallic = 0.3f;
        surface.roughness = 0.45f;
        return glm::dvec3(
                   cpu::reinhardGamma(cpu::shadePointLights(surface, glm::vec3(camera), lights))) *
               255.0;
    };
    int checked = 0;
    double worst = 0.0;
    for (int py = 0; py < kHeight; ++py) {
        for (int px = 0; px < kWidth; ++px) {
            const auto expected = predict(px + 0.5, py + 0.5);
            if (!expected) continue;
            bool steady = true;
            for (auto [ox, oy] : {std::pair{0.25, 0.0}, {-0.25, 0.0}, {0.0, 0.25}, {0.0, -0.25}}) {
                const auto near = predict(px + 0.5 + ox, py + 0.5 + oy);
                if (!near || glm::length(*near - *expected) > 1.0) steady = false;
            }
            if (!steady) continue;
            const size_t at =
                (size_t(kHeight - 1 - py) * kWidth + size_t(px)) * 4;  // GL: bottom up
            double diff = 0.0;
            for (int c = 0; c < 3; ++c)
                diff = std::max(
                    diff, std::abs(double(pixels[at + size_t(c)]) - std::round((*expected)[c])));
            worst = std::max(worst, diff);
            EXPECT_LE(diff, 2.0) << "pixel " << px << ", " << py;
            ++checked;
        }
    }
    std::printf("non-uniform scale: %d pixels compared, worst channel diff %.0f/255\n", checked,
                worst);
    EXPECT_GT(checked, 4000);  // measured: 5,060 of the ellipsoid's pixels are steady
    while (app.nextFrame()) {
    }
}

// No seams along the cube's edges: the rough levels of the prefiltered map (4 x 4 and 2 x 2
// texels a face) are read across face edges, where only seamless cube-map filtering (on for the
// whole run, the App's job) blends the two faces; without it each face clamps to its own edge
// texels and the reading jumps at the edge. Along paths that cross edges, the largest step
// between neighbouring readings must stay within a few times the typical one.
TEST(Gl, NoSeamsAcrossCubeFaces) {
    const fs::path dir = test::testOutputDir("gl_seams");
    App app = makeApp(dir);
    HdrImage sky{64, 32, std::vector<float>(64 * 32 * 3)};
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 64; ++x) {
            const float u = (x + 0.5f) / 64.0f, v = (y + 0.5f) / 32.0f;
            const float value = 1.0f + 0.8f * std::sin(6.2832f * u) * std::cos(3.1416f * v) + v;
            for (int c = 0; c < 3; ++c) sky.pixels[(size_t(y) * 64 + size_t(x)) * 3 + c] = value;
        }
    }
    const TextureCube environment = equirectangularToCubemap(Texture2D(sky), 64);
    const TextureCube prefiltered = prefilterSpecular(environment, 16, 5, 256);

    // A fragment shader that reads the map along a path from `start` to `end`, one texel a step.
    const fs::path fragment = dir / "read_path.frag";
    writeFileAtomically(fragment, R"(#version 330 core
out vec4 FragColor;
in vec2 TexCoords;
uniform samplerCube map;
uniform float lod;
uniform vec3 start, end;
void main() { FragColor = vec4(textureLod(map, normalize(mix(start, end, TexCoords.x)), lod).rgb, 1.0); }
)");
    Shader shader(shaderDir() / "ibl/fullscreen.vert", fragment);
    constexpr int kSteps = 1024;
    const TestTarget target(kSteps, 1, GL_RGBA32F, false, "seam target");
    glDisable(GL_DEPTH_TEST);
    shader.set("map", 0);
    prefiltered.bind(0);
    const GpuMesh quad(pbr::quad());
    // Paths across the +X/+Z, +X/+Y, -Y/-Z and -X/+Y edges.
    const std::array<std::pair<glm::vec3, glm::vec3>, 4> paths = {{
        {{1.0f, 0.3f, 0.2f}, {0.2f, 0.3f, 1.0f}},
        {{1.0f, 0.2f, 0.3f}, {0.2f, 1.0f, 0.3f}},
        {{0.1f, -1.0f, -0.2f}, {0.1f, -0.2f, -1.0f}},
        {{-1.0f, 0.2f, -0.4f}, {-0.2f, 1.0f, -0.4f}},
    }};
    for (const float lod : {3.0f, 4.0f}) {
        for (const auto& [start, end] : paths) {
            shader.set("lod", lod);
            shader.set("start", start);
            shader.set("end", end);
            quad.draw();
            std::vector<float> readings(size_t(kSteps) * 4);
            glReadPixels(0, 0, kSteps, 1, GL_RGBA, GL_FLOAT, readings.data());
            std::vector<double> steps;
            for (int i = 0; i + 1 < kSteps; ++i) {
                steps.push_back(
                    std::abs(double(readings[size_t(i + 1) * 4]) - readings[size_t(i) * 4]));
            }
            std::vector<double> sorted = steps;
            std::sort(sorted.begin(), sorted.end());
            const double typical = sorted[sorted.size() * 3 / 4], largest = sorted.back();
            std::printf("lod %.0f, path from (%.1f, %.1f, %.1f): largest step %.5f, typical %.5f\n",
                        double(lod), double(start.x), double(start.y), double(start.z), largest,
                        typical);
            EXPECT_LT(largest, 8.0 * typical + 1e-4)
                << "a jump along the path from (" << start.x << ", " << start.y << ", " << start.z
                << ") at lod " << lod << ": a seam";
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glEnable(GL_DEPTH_TEST);
    while (app.nextFrame()) {
    }
}

// An orbit sample's App: view(), projection() and cameraPosition() are the fly camera's until
// useOrbitCamera, then the orbit camera's, framing the bounds or starting where --camera x,y,z
// says; --camera with yaw and pitch is a bad flag there, refused before any context exists.
TEST(Gl, AnOrbitSampleFramesItsModelOrStartsAtCameraXyz) {
    const fs::path dir = test::testOutputDir("gl_orbit");
    auto orbitApp = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = appArguments(dir, extra);
        std::vector<char*> argv;
        for (std::string& arg : args) argv.push_back(arg.data());
        return std::make_unique<App>(int(argv.size()), argv.data(),
                                     AppConfig{.name = "gl_test", .orbitCamera = true});
    };
    const glm::vec3 min(-2.0f, 0.0f, -1.0f), max(2.0f, 3.0f, 1.0f), centre(0.0f, 1.5f, 0.0f);
    {
        const auto app = orbitApp({});
        EXPECT_EQ(app->orbitCamera(), nullptr);
        EXPECT_EQ(app->view(), app->camera().viewMatrix());
        app->useOrbitCamera(min, max);
        ASSERT_NE(app->orbitCamera(), nullptr);
        const OrbitCamera expected = OrbitCamera::framing(min, max, app->aspect());
        EXPECT_EQ(app->cameraPosition(), expected.position());
        EXPECT_EQ(app->view(), expected.viewMatrix());
        EXPECT_EQ(app->projection(), expected.projectionMatrix(app->aspect()));
        while (app->nextFrame()) {
        }
    }
    {
        const auto app = orbitApp({"--camera", "1,2,30"});
        app->useOrbitCamera(min, max);
        const glm::vec3 eye = app->cameraPosition();
        EXPECT_NEAR(eye.x, 1.0f, 1e-4f);
        EXPECT_NEAR(eye.y, 2.0f, 1e-4f);
        EXPECT_NEAR(eye.z, 30.0f, 1e-4f);
        const glm::vec4 seen = app->view() * glm::vec4(centre, 1.0f);
        EXPECT_NEAR(seen.x, 0.0f, 1e-4f);
        EXPECT_NEAR(seen.y, 0.0f, 1e-4f);
        while (app->nextFrame()) {
        }
    }
    try {
        orbitApp({"--camera", "1,2,30,-90,0"});
        ADD_FAILURE() << "--camera with yaw and pitch was taken by an orbit sample";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("--camera: "), std::string::npos) << e.what();
    }
    // A fly-camera sample cannot switch: its flags were checked for the fly camera.
    App fly = makeApp(dir, {"--camera", "1,2,30,-90,0"});
    EXPECT_THROW(fly.useOrbitCamera(min, max), Error);
    EXPECT_EQ(fly.cameraPosition(), glm::vec3(1.0f, 2.0f, 30.0f));
    while (fly.nextFrame()) {
    }
}

// The GLSL tone mappers (shaders/include/tonemap.glsl's toneMap) against their CPU mirror
// (pbr::cpu::toneMap): each input colour one column of a float target, each mapper one row (and a
// row for an unknown mapper, which is none), at two exposures. The inputs cover black, greys up
// to 1000, the Khronos Neutral toe (< 0.08) and knee (0.76), saturated and negative colours.
// Within 1e-4, a fortieth of an 8-bit level (measured: 2e-7 on llvmpipe): 1/255 would let a
// changed constant in the toe (6.25 -> 6, at most 0.4/255) through.
// Sample 09's light block: every offset pbr::LightBlock / pbr::PackedLight puts a field at is
// the offset GL gives that member of the std140 block in light_types.glsl (first, second and
// last light), and the block's size is the struct's.
TEST(Gl, LightBlockOffsetsAreWhatGlReports) {
    const fs::path dir = test::testOutputDir("gl_light_block");
    App app = makeApp(dir);
    const fs::path fragment = dir / "lights.frag";
    writeFileAtomically(fragment, R"(#version 330 core
out vec4 FragColor;
#include "brdf.glsl"
#include "light_types.glsl"
void main() { FragColor = vec4(shadeLights(vec3(0.0), vec3(0, 1, 0), vec3(0, 0, 1), vec3(1.0), 0.0, 0.5, 1.0), 1.0); }
)");
    Shader shader(shaderDir() / "ibl/fullscreen.vert", fragment);
    LightBuffer::attach(shader.id());
    const GLuint block = glGetUniformBlockIndex(shader.id(), "LightBlock");
    ASSERT_NE(block, GL_INVALID_INDEX);
    GLint size = 0;
    glGetActiveUniformBlockiv(shader.id(), block, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
    EXPECT_EQ(size_t(size), sizeof(LightBlock));

    std::vector<std::pair<std::string, size_t>> members = {
        {"lightCount", offsetof(LightBlock, lightCount)}};
    for (const int i : {0, 1, LightBlock::kMaxLights - 1}) {
        const std::string at = "lights[" + std::to_string(i) + "].";
        const size_t base = offsetof(LightBlock, lights) + size_t(i) * sizeof(PackedLight);
        members.push_back(
            {at + "positionConstant", base + offsetof(PackedLight, positionConstant)});
        members.push_back({at + "forwardLinear", base + offsetof(PackedLight, forwardLinear)});
        members.push_back({at + "colorQuadratic", base + offsetof(PackedLight, colorQuadratic)});
        members.push_back({at + "typeCutoffOuterIntensity",
                           base + offsetof(PackedLight, typeCutoffOuterIntensity)});
    }
    for (const auto& [name, expected] : members) {
        const char* names[] = {name.c_str()};
        GLuint index = GL_INVALID_INDEX;
        glGetUniformIndices(shader.id(), 1, names, &index);
        ASSERT_NE(index, GL_INVALID_INDEX) << name;
        GLint offset = -1;
        glGetActiveUniformsiv(shader.id(), 1, &index, GL_UNIFORM_OFFSET, &offset);
        EXPECT_EQ(size_t(offset), expected) << name;
    }
    // one light too many is a clear error, not a write past the block
    LightBuffer buffer;
    const std::vector<PackedLight> tooMany(size_t(LightBlock::kMaxLights) + 1);
    EXPECT_THROW(buffer.upload(tooMany), Error);
}

// A float texture holding a shader test's inputs, one RGB value a texel, row by row.
Texture2D inputsTexture(int width, int height, const std::vector<glm::vec3>& values) {
    Texture2D texture(width, height, GL_RGB32F);
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGB, GL_FLOAT, values.data());
    return texture;
}

TEST(Gl, ToneMappersMatchTheCpu) {
    const fs::path dir = test::testOutputDir("gl_tonemap");
    App app = makeApp(dir);
    std::vector<glm::vec3> inputs = {
        {0.0f, 0.0f, 0.0f},      {0.02f, 0.05f, 0.079f}, {0.04f, 0.2f, 0.5f}, {0.5f, 0.3f, 0.1f},
        {0.79f, 0.4f, 0.2f},     {0.81f, 0.805f, 0.8f},  {1.0f, 0.0f, 0.0f},  {0.0f, 1.0f, 0.0f},
        {0.0f, 0.0f, 1.0f},      {8.0f, 4.0f, 1.0f},     {0.3f, 50.0f, 6.0f}, {2.0f, 0.5f, 0.1f},
        {0.8f, 0.2f, 0.05f},     {0.05f, 0.3f, 1.5f},    {-1.0f, 0.5f, 2.0f}, {-0.1f, -0.2f, -0.3f},
        {1000.0f, 1.0f, 0.001f}, {0.18f, 0.18f, 0.18f}};
    for (float grey = 0.001f; grey < 1000.0f; grey *= 1.6f) inputs.push_back(glm::vec3(grey));
    const int count = int(inputs.size());
    ASSERT_GE(count, 40);
    constexpr int kUnknownMapper = 7;
    const std::array<int, 5> mappers = {0, 1, 2, 3, kUnknownMapper};

    const Texture2D inputTexture = inputsTexture(count, 1, inputs);
    const fs::path fragment = dir / "tonemap.frag";
    writeFileAtomically(fragment, R"(#version 330 core
#include "tonemap.glsl"
out vec4 FragColor;
uniform sampler2D inputs;
uniform int mappers[5];
uniform float exposure;
void main()
{
    vec3 color = texelFetch(inputs, ivec2(gl_FragCoord.x, 0), 0).rgb;
    FragColor = vec4(toneMap(color, mappers[int(gl_FragCoord.y)], exposure), 1.0);
}
)");
    Shader shader(shaderDir() / "ibl/fullscreen.vert", fragment);
    const TestTarget target(count, int(mappers.size()), GL_RGBA32F, false, "tone map target");
    glDisable(GL_DEPTH_TEST);
    shader.set("inputs", 0);
    inputTexture.bind(0);
    for (size_t row = 0; row < mappers.size(); ++row)
        shader.set("mappers[" + std::to_string(row) + "]", mappers[row]);
    const GpuMesh quad(pbr::quad());
    for (const float exposure : {1.0f, 2.5f}) {
        shader.set("exposure", exposure);
        quad.draw();
        std::vector<float> pixels(size_t(count) * mappers.size() * 4);
        glReadPixels(0, 0, count, int(mappers.size()), GL_RGBA, GL_FLOAT, pixels.data());
        double worst = 0.0;
        for (size_t row = 0; row < mappers.size(); ++row) {
            const auto mapper = mappers[row] == kUnknownMapper ? cpu::ToneMapper::None
                                                               : cpu::ToneMapper(mappers[row]);
            for (int column = 0; column < count; ++column) {
                const glm::vec3 cpu = cpu::toneMap(inputs[size_t(column)], mapper, exposure);
                for (int c = 0; c < 3; ++c) {
                    const float gpu =
                        pixels[(row * size_t(count) + size_t(column)) * 4 + size_t(c)];
                    worst = std::max(worst, double(std::abs(gpu - cpu[c])));
                    EXPECT_NEAR(gpu, cpu[c], 1e-4)
                        << "mapper " << mappers[row] << ", exposure " << exposure << ", input ("
                        << inputs[size_t(column)].r << ", " << inputs[size_t(column)].g << ", "
                        << inputs[size_t(column)].b << "), channel " << c;
                }
            }
        }
        std::printf("exposure %.1f: largest difference GLSL - CPU %.2e\n", double(exposure), worst);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glEnable(GL_DEPTH_TEST);
    while (app.nextFrame()) {
    }
}

// The GLSL layers of the advanced glTF materials (shaders/include/gltf_extensions.glsl) against
// their CPU mirror (common/math/gltf_extensions.cpp), which the unit tests integrate in white
// furnaces: 64 pairs of view and light directions (NdotV and NdotL from 0.05 to 1, the light
// turned 40 degrees about the normal), one a column of a float target, each function a row, at
// four roughnesses (which also set the ior, 1 + 2 roughness). Within 1e-4 relative (the GPU's
// pow and exp against the CPU's; measured below).
TEST(Gl, GltfExtensionLayersMatchTheCpu) {
    const fs::path dir = test::testOutputDir("gl_gltf_extensions");
    App app = makeApp(dir);
    std::vector<glm::vec3> directions;  // V of each case, then L of each
    constexpr int kCount = 64;
    for (int i = 0; i < kCount; ++i) {
        const float NdotV = 0.05f + 0.95f * float(i % 8) / 7.0f;
        directions.push_back({std::sqrt(1.0f - NdotV * NdotV), 0.0f, NdotV});
    }
    for (int i = 0; i < kCount; ++i) {
        const float NdotL = 0.05f + 0.95f * float(i / 8) / 7.0f, sinL = std::sqrt(1.0f - NdotL * NdotL);
        directions.push_back({-sinL * std::cos(0.7f), sinL * std::sin(0.7f), NdotL});
    }
    const Texture2D inputTexture = inputsTexture(kCount, 2, directions);
    const fs::path fragment = dir / "layers.frag";
    writeFileAtomically(fragment, R"(#version 330 core
#include "brdf.glsl"
#include "ibl_ambient.glsl"
#include "gltf_extensions.glsl"
out vec4 FragColor;
uniform sampler2D directions;
uniform float roughness;
const vec3 sheenColor = vec3(1.0, 0.5, 0.25);
void main()
{
    int i = int(gl_FragCoord.x);
    vec3 V = texelFetch(directions, ivec2(i, 0), 0).rgb;
    vec3 L = texelFetch(directions, ivec2(i, 1), 0).rgb;
    vec3 N = vec3(0.0, 0.0, 1.0);
    float alpha = max(roughness * roughness, MIN_SHEEN_ALPHA);
    float NdotH = dot(N, normalize(V + L));
    float ior = 1.0 + 2.0 * roughness;
    DielectricFresnel f = dielectricFresnel(ior, sheenColor * 20.0, roughness);
    int row = int(gl_FragCoord.y);
    if (row == 0)
        FragColor = vec4(clearcoatDirect(N, V, L, roughness), D_Charlie(NdotH, alpha),
                         V_Sheen(L.z, V.z, alpha), lambdaSheen(V.z, alpha));
    else if (row == 1)
        FragColor = vec4(sheenDirect(N, V, L, sheenColor, roughness), iorToF0(ior));
    else if (row == 2)
        FragColor = vec4(f.F0, f.F90);
    else if (row == 3)
        FragColor = vec4(clearcoatFresnel(iorToF0(ior), V.z), sheenAlbedoScaling(sheenColor, V.z, L.z),
                         coatOver(vec3(L.z), vec3(V.z), roughness).x, emission(sheenColor, 4.0, roughness).y);
    else if (row == 6)
        FragColor = vec4(transmissionDirect(N, V, vec3(L.xy, -L.z), f.F0, f.F90, roughness, ior).xz,
                         iorScaledRoughness(roughness, ior),
                         volumeAttenuation(vec3(2.0), 2.0 * L.z, vec3(0.2, 0.5, 0.9), 0.7 * roughness).z);
    else if (row == 7)
        FragColor = vec4(volumeRay(normalize(vec3(0.3, 0.1, 1.0)), V, 0.8 * L.z, ior, vec3(1.0, 2.0, 0.5)),
                         iorScaledRoughness(roughness * roughness, 1.2 + 0.1 * V.z));
    else
    {
        LayeredSurface s;
        s.N = normalize(vec3(0.1, -0.2, 1.0));
        s.diffuseColor = vec3(0.8, 0.3, 0.2);
        s.F0 = f.F0;
        s.F90 = f.F90;
        s.metalColor = vec3(0.9, 0.6, 0.3);
        s.metallic = 0.5 * roughness;
        s.roughness = roughness;
        s.sheenColor = vec3(0.5, 0.4, 0.9);
        s.sheenRoughness = 1.0 - 0.5 * roughness;
        s.clearcoat = 0.8;
        s.clearcoatRoughness = 0.5 * roughness;
        s.clearcoatN = N;
        s.clearcoatF0 = iorToF0(ior);
        s.transmission = 0.7 * roughness;
        s.ior = ior;
        s.thickness = 0.5;
        s.attenuationColor = vec3(0.9, 0.5, 0.2);
        s.attenuationDistance = 0.4;
        SplitSumReads base = SplitSumReads(dot(s.N, V), vec3(0.5, 0.6, 0.7), vec3(2.0, 1.5, 1.0) * L.z,
                                           vec2(0.6, 0.1) * V.z);
        SplitSumReads coat = SplitSumReads(V.z, vec3(0.0), vec3(1.0, 2.0, 3.0) * L.z, vec2(0.7, 0.05));
        if (row == 4)
            FragColor = vec4(layeredDirectLight(s, V, L, vec3(1.0, 0.8, 0.6), vec3(L.xy, -L.z),
                                                vec3(0.5, 0.7, 0.9), 0.5 * V.z, 0.5 * L.z), 0.0);
        else
            FragColor = vec4(layeredAmbientLight(s, base, coat, vec3(0.3, 0.2, 0.1), 0.5 * V.z,
                                                 vec3(0.4, 0.3, 0.2) * V.z), 0.0);
    }
}
)");
    Shader shader(shaderDir() / "ibl/fullscreen.vert", fragment);
    constexpr int kRows = 8;
    const TestTarget target(kCount, kRows, GL_RGBA32F, false, "layers target");
    glDisable(GL_DEPTH_TEST);
    shader.set("directions", 0);
    shader.set("multipleScattering", true);
    inputTexture.bind(0);
    const GpuMesh quad(pbr::quad());
    const glm::vec3 N(0.0f, 0.0f, 1.0f), sheenColor(1.0f, 0.5f, 0.25f);
    std::array<std::array<double, 4>, kRows> worst{};
    auto tolerance = [](int row, int c) {
        return (row == 0 && c < 2) || (row == 1 && c < 3) || row == 4 || (row == 6 && c < 2)
                   ? 5e-3
                   : 1e-4;
    };
    for (const float roughness : {0.05f, 0.3f, 0.7f, 1.0f}) {
        shader.set("roughness", roughness);
        quad.draw();
        std::vector<float> pixels(size_t(kCount) * kRows * 4);
        glReadPixels(0, 0, kCount, kRows, GL_RGBA, GL_FLOAT, pixels.data());
        for (int i = 0; i < kCount; ++i) {
            const glm::vec3 V = directions[size_t(i)], L = directions[size_t(kCount + i)];
            const float alpha = std::max(roughness * roughness, cpu::kMinSheenAlpha);
            const float NdotH = glm::dot(N, glm::normalize(V + L)), ior = 1.0f + 2.0f * roughness;
            const cpu::DielectricFresnel f =
                cpu::dielectricFresnel(ior, sheenColor * 20.0f, roughness);
            const glm::vec3 sheen = cpu::sheenDirect(N, V, L, sheenColor, roughness);
            cpu::LayeredSurface s;
            s.N = glm::normalize(glm::vec3(0.1f, -0.2f, 1.0f));
            s.diffuseColor = glm::vec3(0.8f, 0.3f, 0.2f);
            s.F0 = f.F0;
            s.F90 = f.F90;
            s.metalColor = glm::vec3(0.9f, 0.6f, 0.3f);
            s.metallic = 0.5f * roughness;
            s.roughness = roughness;
            s.sheenColor = glm::vec3(0.5f, 0.4f, 0.9f);
            s.sheenRoughness = 1.0f - 0.5f * roughness;
            s.clearcoat = 0.8f;
            s.clearcoatRoughness = 0.5f * roughness;
            s.clearcoatN = N;
            s.clearcoatF0 = cpu::iorToF0(ior);
            s.transmission = 0.7f * roughness;
            s.ior = ior;
            s.thickness = 0.5f;
            s.attenuationColor = glm::vec3(0.9f, 0.5f, 0.2f);
            s.attenuationDistance = 0.4f;
            const glm::vec3 behind(L.x, L.y, -L.z);
            const glm::vec3 attenuated = cpu::volumeAttenuation(
                glm::vec3(2.0f), 2.0f * L.z, glm::vec3(0.2f, 0.5f, 0.9f), 0.7f * roughness);
            const cpu::SplitSumReads base{glm::dot(s.N, V), glm::vec3(0.5f, 0.6f, 0.7f),
                                          glm::vec3(2.0f, 1.5f, 1.0f) * L.z,
                                          glm::vec2(0.6f, 0.1f) * V.z};
            const cpu::SplitSumReads coat{V.z, glm::vec3(0.0f), glm::vec3(1.0f, 2.0f, 3.0f) * L.z,
                                          glm::vec2(0.7f, 0.05f)};
            const std::array<glm::vec4, kRows> expected = {
                glm::vec4(cpu::clearcoatDirect(N, V, L, roughness), cpu::D_Charlie(NdotH, alpha),
                          cpu::V_Sheen(L.z, V.z, alpha), cpu::lambdaSheen(V.z, alpha)),
                glm::vec4(sheen, cpu::iorToF0(ior)),
                glm::vec4(f.F0, f.F90),
                glm::vec4(cpu::clearcoatFresnel(cpu::iorToF0(ior), V.z),
                          cpu::sheenAlbedoScaling(sheenColor, V.z, L.z),
                          cpu::coatOver(glm::vec3(L.z), glm::vec3(V.z), roughness).x,
                          cpu::emission(sheenColor, 4.0f, roughness).y),
                glm::vec4(cpu::layeredDirectLight(s, V, L, glm::vec3(1.0f, 0.8f, 0.6f), behind,
                                                  glm::vec3(0.5f, 0.7f, 0.9f), 0.5f * V.z,
                                                  0.5f * L.z),
                          0.0f),
                glm::vec4(cpu::layeredAmbientLight(s, base, coat, glm::vec3(0.3f, 0.2f, 0.1f),
                                                   0.5f * V.z, glm::vec3(0.4f, 0.3f, 0.2f) * V.z,
                                                   true),
                          0.0f),
                glm::vec4(glm::vec2(cpu::transmissionDirect(N, V, behind, f.F0, f.F90, roughness, ior).x,
                                    cpu::transmissionDirect(N, V, behind, f.F0, f.F90, roughness, ior).z),
                          cpu::iorScaledRoughness(roughness, ior), attenuated.z),
                glm::vec4(cpu::volumeRay(glm::normalize(glm::vec3(0.3f, 0.1f, 1.0f)), V, 0.8f * L.z,
                                         ior, glm::vec3(1.0f, 2.0f, 0.5f)),
                          cpu::iorScaledRoughness(roughness * roughness, 1.2f + 0.1f * V.z))};
            for (int row = 0; row < kRows; ++row) {
                for (int c = 0; c < 4; ++c) {
                    const float gpu = pixels[(size_t(row) * kCount + size_t(i)) * 4 + size_t(c)];
                    const float cpu = expected[size_t(row)][c];
                    const double relative =
                        std::abs(double(gpu) - cpu) / std::max(std::abs(double(cpu)), 1e-3);
                    worst[size_t(row)][size_t(c)] = std::max(worst[size_t(row)][size_t(c)], relative);
                    EXPECT_LE(relative, tolerance(row, c))
                        << "roughness " << roughness << ", case " << i << " (NdotV " << V.z
                        << ", NdotL " << L.z << "), row " << row << ", channel " << c
                        << ": GLSL " << gpu << ", CPU " << cpu;
                }
            }
        }
    }
    for (int row = 0; row < kRows; ++row) {
        std::printf("row %d: largest relative differences GLSL - CPU %.1e %.1e %.1e %.1e\n", row,
                    worst[size_t(row)][0], worst[size_t(row)][1], worst[size_t(row)][2],
                    worst[size_t(row)][3]);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glEnable(GL_DEPTH_TEST);
    while (app.nextFrame()) {
    }
}

// The sheen map goes through the cache as the other maps do: computed once and stored under its
// name, then loaded by the next start, the same texels, nothing computed.
TEST(Gl, SheenMapIsStoredAndLoadedBack) {
    const fs::path dir = test::testOutputDir("gl_sheen_cache");
    App app = makeApp(dir);
    const fs::path cacheDir = dir / "cache", hdr = environmentDir() / "sunny_courtyard.hdr";
    fs::remove_all(cacheDir);
    std::vector<float> first;
    {
        IblCache cache(cacheDir);
        IblEnvironment environment(cache, hdr);
        first = environment.sheenMap(16, 3).readFace(2, 1);
        EXPECT_GT(cache.computeSeconds(), 0.0);
        EXPECT_TRUE(fs::exists(cacheDir / environment.sheenFile(16, 3).name));
    }
    {
        IblCache cache(cacheDir);
        IblEnvironment environment(cache, hdr);
        EXPECT_TRUE(environment.sheenMap(16, 3).readFace(2, 1) == first);
        EXPECT_EQ(cache.computeSeconds(), 0.0);
    }
    ASSERT_FALSE(first.empty());
    EXPECT_GT(*std::max_element(first.begin(), first.end()), 0.05f) << "a black sheen map";
    while (app.nextFrame()) {
    }
}

// The IBL passes and the skybox change framebuffers, viewport, depth and culling state, the
// program and texture bindings; each must hand the caller's state back as it found it.
TEST(Gl, IblPassesLeaveTheCallersStateAlone) {
    const fs::path dir = test::testOutputDir("gl_state");
    App app = makeApp(dir);
    const TestTarget mine(32, 32, GL_RGBA8, false, "the caller's target");
    glViewport(3, 5, 17, 19);
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glEnable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    Shader& shader = app.shader("common/pbr.vert", "01_lighting/pbr.frag");
    shader.use();
    const Texture2D marker(Image{1, 1, 3, {1, 2, 3}}, ColorSpace::Linear);
    marker.bind(0);
    glActiveTexture(GL_TEXTURE3);

    auto expectUnchanged = [&](const char* pass) {
        GLint value = 0, viewport[4] = {};
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &value);
        EXPECT_EQ(GLuint(value), mine.framebuffer.id()) << pass;
        glGetIntegerv(GL_VIEWPORT, viewport);
        EXPECT_EQ(viewport[0], 3) << pass;
        EXPECT_EQ(viewport[3], 19) << pass;
        EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST)) << pass;
        glGetIntegerv(GL_DEPTH_FUNC, &value);
        EXPECT_EQ(value, GL_GREATER) << pass;
        EXPECT_TRUE(glIsEnabled(GL_CULL_FACE)) << pass;
        EXPECT_TRUE(glIsEnabled(GL_BLEND)) << pass;
        glGetIntegerv(GL_CURRENT_PROGRAM, &value);
        EXPECT_EQ(GLuint(value), shader.id()) << pass;
        glGetIntegerv(GL_ACTIVE_TEXTURE, &value);
        EXPECT_EQ(value, GL_TEXTURE3) << pass;
        glActiveTexture(GL_TEXTURE0);
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &value);
        EXPECT_EQ(GLuint(value), marker.id()) << pass;
        glActiveTexture(GL_TEXTURE3);
    };
    const Texture2D white(HdrImage{16, 8, std::vector<float>(16 * 8 * 3, 1.0f)});
    const TextureCube environment = equirectangularToCubemap(white, 16);
    expectUnchanged("equirectangularToCubemap");
    const TextureCube irradiance = convolveIrradiance(environment, 4);
    expectUnchanged("convolveIrradiance");
    const TextureCube prefiltered = prefilterSpecular(environment, 8, 2, 16);
    expectUnchanged("prefilterSpecular");
    const Texture2D lut = computeBrdfLut(8, 16);
    expectUnchanged("computeBrdfLut");
    // The skybox draws (its program, its texture on unit 0); it keeps the depth function.
    Skybox skybox;
    skybox.draw(environment, glm::mat4(1.0f), glm::mat4(1.0f));
    GLint depthFunc = 0;
    glGetIntegerv(GL_DEPTH_FUNC, &depthFunc);
    EXPECT_EQ(depthFunc, GL_GREATER) << "the skybox forced its own depth function";
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    while (app.nextFrame()) {
    }
}

// Setting a uniform makes its program current, but only when it is not current already: a frame
// of 01 sets some 200 uniforms, and each glUseProgram is a state change. Counted by wrapping
// glad's entry point.
PFNGLUSEPROGRAMPROC originalUseProgram = nullptr;
int useProgramCalls = 0;
void GLAD_API_PTR countingUseProgram(GLuint program) {
    ++useProgramCalls;
    originalUseProgram(program);
}

TEST(Gl, SettingUniformsBindsTheProgramOnce) {
    const fs::path dir = test::testOutputDir("gl_use_program");
    App app = makeApp(dir);
    Shader& first = app.shader("common/pbr.vert", "01_lighting/pbr.frag");
    Shader& second = app.shader("common/pbr.vert", "04_ibl_irradiance/pbr.frag");
    originalUseProgram = glad_glUseProgram;
    glad_glUseProgram = countingUseProgram;
    useProgramCalls = 0;
    for (int i = 0; i < 10; ++i) first.set("roughness", 0.1f * float(i));
    first.setModel(glm::mat4(1.0f));
    const int forFirst = useProgramCalls;
    for (int i = 0; i < 10; ++i) second.set("metallic", 0.1f * float(i));
    const int forBoth = useProgramCalls;
    glad_glUseProgram = originalUseProgram;
    EXPECT_LE(forFirst, 1);
    EXPECT_EQ(forBoth - forFirst, 1);
    GLint current = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    EXPECT_EQ(GLuint(current), second.id());
    while (app.nextFrame()) {
    }
}

// A GpuModel owes nothing to the Model it was made from: made from a temporary, every material
// is still readable (under AddressSanitizer a pointer into the gone Model is a failure).
TEST(Gl, AGpuModelOutlivesTheModelItWasMadeFrom) {
    const fs::path dir = test::testOutputDir("gl_gpu_model");
    App app = makeApp(dir);
    const GpuModel gpu(loadModel(modelDir() / "unlit_showcase.gltf"));
    ASSERT_EQ(gpu.primitives().size(), 4u);
    // The showcase's second object, the sphere, carries the base colour factor (1, 0.42, 0.08).
    bool sawSphere = false;
    for (const GpuModel::Primitive& primitive : gpu.primitives()) {
        if (primitive.material.name == "base colour factor") {
            sawSphere = true;
            EXPECT_FLOAT_EQ(primitive.material.baseColorFactor.g, 0.42f);
        }
    }
    EXPECT_TRUE(sawSphere);
    while (app.nextFrame()) {
    }
}

// An sRGB texture keeps every channel of its image: grey spreads to R, G and B (GL 3.3 has no
// grey sRGB format), the alpha of grey + alpha stays alpha, RGB and RGBA go in as they are. The
// stored bytes are read back as they are (glGetTexImage converts nothing) and compared with
// what each pixel of the source says they must be.
TEST(Gl, SrgbTexturesKeepEveryChannelOfTheirImage) {
    const fs::path dir = test::testOutputDir("gl_srgb_texture");
    App app = makeApp(dir);
    for (int channels = 1; channels <= 4; ++channels) {
        SCOPED_TRACE(std::to_string(channels) + " channels");
        Image image{3, 2, channels, {}};
        for (int i = 0; i < 3 * 2 * channels; ++i) {
            image.pixels.push_back(std::uint8_t(17 + 37 * i));
        }
        const Texture2D texture(image, ColorSpace::Srgb, TextureFilter::Nearest);
        glBindTexture(GL_TEXTURE_2D, texture.id());
        GLint internalFormat = 0;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &internalFormat);
        const bool alpha = channels == 2 || channels == 4, grey = channels <= 2;
        EXPECT_EQ(GLenum(internalFormat), alpha ? GLenum(GL_SRGB8_ALPHA8) : GLenum(GL_SRGB8));
        std::vector<std::uint8_t> stored(3 * 2 * 4);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, stored.data());
        for (int x = 0; x < 3; ++x) {
            for (int y = 0; y < 2; ++y) {
                const std::array<int, 4> expected = {
                    image.at(x, y, 0), image.at(x, y, grey ? 0 : 1), image.at(x, y, grey ? 0 : 2),
                    alpha ? image.at(x, y, channels - 1) : 255};
                for (int c = 0; c < 4; ++c) {
                    EXPECT_EQ(int(stored[size_t((y * 3 + x) * 4 + c)]), expected[size_t(c)])
                        << "texel " << x << "," << y << " channel " << c;
                }
            }
        }
    }
    while (app.nextFrame()) {
    }
}

// A trilinear texture carries the CPU's mip chain (files/mip_chain.h) at every level, down to
// 1x1 and no further: sides of 6 and 5 make levels of 3x2 and 1x1 (rows of 9 bytes, which GL
// reads right only with an unpack alignment of 1), linear RGB and sRGB RGBA alike.
TEST(Gl, TrilinearTexturesCarryTheMipChainAtEveryLevel) {
    const fs::path dir = test::testOutputDir("gl_mip_chain");
    App app = makeApp(dir);
    for (int channels : {3, 4}) {
        const ColorSpace space = channels == 3 ? ColorSpace::Linear : ColorSpace::Srgb;
        SCOPED_TRACE(channels == 3 ? "linear RGB" : "sRGB RGBA");
        Image image{6, 5, channels, {}};
        for (int i = 0; i < 6 * 5 * channels; ++i)
            image.pixels.push_back(std::uint8_t(29 * i % 256));
        const std::vector<Image> chain = mipChain(image, space == ColorSpace::Srgb);
        ASSERT_EQ(chain.size(), 2u);
        const Texture2D texture(image, space);
        glBindTexture(GL_TEXTURE_2D, texture.id());
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        for (int level = 1; level <= 3; ++level) {
            GLint width = 0, height = 0;
            glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_WIDTH, &width);
            glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_HEIGHT, &height);
            if (level == 3) {
                EXPECT_EQ(width, 0) << "a level past 1x1";
                break;
            }
            const Image& expected = chain[size_t(level - 1)];
            ASSERT_EQ(width, expected.width);
            ASSERT_EQ(height, expected.height);
            std::vector<std::uint8_t> stored(expected.pixels.size());
            glGetTexImage(GL_TEXTURE_2D, level, channels == 3 ? GL_RGB : GL_RGBA, GL_UNSIGNED_BYTE,
                          stored.data());
            EXPECT_EQ(stored, expected.pixels) << "level " << level;
        }
    }
    while (app.nextFrame()) {
    }
}

// --help promises "a power of two up to what the GL allows (4 on llvmpipe)": the GL's limit
// works, twice it is one clear error naming the limit.
TEST(Gl, MoreSamplesThanTheDriverAllowsIsAClearError) {
    const fs::path dir = test::testOutputDir("gl_msaa");
    GLint maxSamples = 0;
    std::string renderer;
    {
        App app = makeApp(dir, {"--msaa", "0"});
        glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
        renderer = app.renderer();
    }
    if (renderer.find("llvmpipe") != std::string::npos) {
        EXPECT_EQ(maxSamples, 4);
    }
    ASSERT_GE(maxSamples, 1);
    EXPECT_NO_THROW(makeApp(dir, {"--msaa", std::to_string(maxSamples)}));
    const std::string tooMany = std::to_string(maxSamples * 2);
    try {
        makeApp(dir, {"--msaa", tooMany});
        FAIL() << tooMany << "x MSAA accepted";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "--msaa " + tooMany + ": this GL allows at most " +
                                             std::to_string(maxSamples) + " samples");
    }
}

}  // namespace
}  // namespace pbr
