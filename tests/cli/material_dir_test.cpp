// 02 --material-dir: every common image layout loads; bad folders and files are one-line errors.
#include <gtest/gtest.h>

#include <stb_image_write.h>

#include <cmath>
#include <fstream>

#include <glm/glm.hpp>

#include "support/golden.h"
#include "support/png16.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

constexpr int kSize = 32;

// Smooth test maps (8-bit values), so that JPEG stays close to them.
struct TestMaps {
    std::vector<std::uint8_t> albedo, normal, metallic, roughness, ao;  // 3, 3, 1, 1, 1 channels
};

TestMaps makeMaps() {
    TestMaps m;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const float u = (x + 0.5f) / kSize, v = (y + 0.5f) / kSize;
            m.albedo.insert(m.albedo.end(),
                            {std::uint8_t(120 + 100 * u), std::uint8_t(60 + 80 * v), 40});
            const glm::vec3 n = glm::normalize(
                glm::vec3(0.3f * std::sin(6.2832f * u), 0.3f * std::cos(6.2832f * v), 1.0f));
            for (int c = 0; c < 3; ++c)
                m.normal.push_back(std::uint8_t(std::lround((n[c] * 0.5f + 0.5f) * 255.0f)));
            m.metallic.push_back(std::uint8_t(255 * v));
            m.roughness.push_back(std::uint8_t(60 + 160 * u));
            m.ao.push_back(std::uint8_t(200 + 55 * u));
        }
    }
    return m;
}

// Writes 8-bit PNGs in the plain layout: RGB albedo and normal, grey metallic / roughness / ao.
fs::path writePlainSet(const fs::path& dir, const TestMaps& m, bool withAo = true) {
    fs::create_directories(dir);
    writePng(dir / "albedo.png", Image{kSize, kSize, 3, m.albedo});
    writePng(dir / "normal.png", Image{kSize, kSize, 3, m.normal});
    writePng(dir / "metallic.png", Image{kSize, kSize, 1, m.metallic});
    writePng(dir / "roughness.png", Image{kSize, kSize, 1, m.roughness});
    if (withAo) writePng(dir / "ao.png", Image{kSize, kSize, 1, m.ao});
    return dir;
}

SampleRender renderSet(const fs::path& materialDir, const fs::path& output) {
    return renderSample("02_lighting_textured", output,
                        {"--material-dir", materialDir.string(), "--size", "160x90", "--camera",
                         "0,0,3", "--msaa", "0"});
}

// The same values stored as RGBA, grey + alpha and 16-bit PNGs render exactly like the plain set.
TEST(MaterialDir, EveryPngLayoutGivesTheSamePicture) {
    const fs::path dir = testOutputDir("material_layouts");
    const TestMaps m = makeMaps();
    const fs::path plain = writePlainSet(dir / "plain", m);

    const fs::path mixed = dir / "mixed";
    fs::create_directories(mixed);
    std::vector<std::uint8_t> rgba, greyAlpha, aoRgb;
    for (size_t i = 0; i < size_t(kSize * kSize); ++i) {
        rgba.insert(rgba.end(), {m.albedo[i * 3], m.albedo[i * 3 + 1], m.albedo[i * 3 + 2], 255});
        greyAlpha.insert(greyAlpha.end(), {m.metallic[i], 255});
        aoRgb.insert(aoRgb.end(), {m.ao[i], m.ao[i], m.ao[i]});
    }
    writePng(mixed / "albedo.png", Image{kSize, kSize, 4, rgba});  // RGBA 8-bit
    std::vector<std::uint16_t> normal16, roughness16;
    for (std::uint8_t v : m.normal) normal16.push_back(std::uint16_t(v * 257));
    for (std::uint8_t v : m.roughness) roughness16.push_back(std::uint16_t(v * 257));
    writePng16(mixed / "normal.png", kSize, kSize, 3, normal16);          // RGB 16-bit
    writePng(mixed / "metallic.png", Image{kSize, kSize, 2, greyAlpha});  // grey + alpha
    writePng16(mixed / "roughness.png", kSize, kSize, 1, roughness16);    // grey 16-bit
    writePng(mixed / "ao.png", Image{kSize, kSize, 3, aoRgb});            // RGB grey

    const SampleRender a = renderSet(plain, dir / "plain.png");
    const SampleRender b = renderSet(mixed, dir / "mixed.png");
    ASSERT_EQ(a.run.exitCode, 0) << a.run.err;
    ASSERT_EQ(b.run.exitCode, 0) << b.run.err;
    EXPECT_TRUE(readBytes(a.image) == readBytes(b.image))
        << "the layouts decode to different values";
}

// JPEG maps load too (lossy, so close rather than equal).
TEST(MaterialDir, JpegMapsLoad) {
    const fs::path dir = testOutputDir("material_jpeg");
    const TestMaps m = makeMaps();
    const fs::path plain = writePlainSet(dir / "plain", m);
    const fs::path jpeg = dir / "jpeg";
    fs::create_directories(jpeg);
    stbi_write_jpg((jpeg / "albedo.jpg").c_str(), kSize, kSize, 3, m.albedo.data(), 95);
    stbi_write_jpg((jpeg / "normal.jpeg").c_str(), kSize, kSize, 3, m.normal.data(), 95);
    stbi_write_jpg((jpeg / "metallic.jpg").c_str(), kSize, kSize, 1, m.metallic.data(), 95);
    stbi_write_jpg((jpeg / "roughness.jpg").c_str(), kSize, kSize, 1, m.roughness.data(), 95);
    stbi_write_jpg((jpeg / "ao.jpg").c_str(), kSize, kSize, 1, m.ao.data(), 95);
    const SampleRender a = renderSet(plain, dir / "plain.png");
    const SampleRender b = renderSet(jpeg, dir / "jpeg.png");
    ASSERT_EQ(b.run.exitCode, 0) << b.run.err;
    const ImageDiff diff = compareImages(readImage(b.image, 3), readImage(a.image, 3), 2);
    EXPECT_GT(diff.psnr, 35.0);
    EXPECT_GT(diff.maxChannelDiff, 0) << "the JPEG set was not the one drawn";
}

// No ao map means ao = 1, as the text suggests: the same as an all-white ao.png.
TEST(MaterialDir, MissingAoMeansWhite) {
    const fs::path dir = testOutputDir("material_no_ao");
    TestMaps m = makeMaps();
    const fs::path withoutAo = writePlainSet(dir / "without", m, false);
    std::fill(m.ao.begin(), m.ao.end(), 255);
    const fs::path whiteAo = writePlainSet(dir / "white", m);
    const SampleRender a = renderSet(withoutAo, dir / "without.png");
    const SampleRender b = renderSet(whiteAo, dir / "white.png");
    ASSERT_EQ(a.run.exitCode, 0) << a.run.err;
    EXPECT_TRUE(readBytes(a.image) == readBytes(b.image));
}

// Maps of different sizes are allowed: each is sampled by uv on its own.
TEST(MaterialDir, MapsOfDifferentSizesAreAllowed) {
    const fs::path dir = testOutputDir("material_sizes");
    const fs::path set = writePlainSet(dir / "set", makeMaps());
    writePng(set / "roughness.png", Image{8, 4, 1, std::vector<std::uint8_t>(32, 128)});
    writePng(set / "normal.png", Image{64, 16, 3, std::vector<std::uint8_t>(64 * 16 * 3, 128)});
    const SampleRender render = renderSet(set, dir / "sizes.png");
    EXPECT_EQ(render.run.exitCode, 0) << render.run.err;
    EXPECT_TRUE(render.run.err.empty()) << render.run.err;
}

// Each bad input: exit 1, one line on stderr naming the file and the reason.
void expectOneLineError(const fs::path& materialDir, const std::string& names,
                        const std::string& reason) {
    const SampleRender render = renderSet(materialDir, materialDir.parent_path() / "out.png");
    EXPECT_EQ(render.run.exitCode, 1) << render.run.err;
    const auto lines = render.run.errLines();
    ASSERT_EQ(lines.size(), 1u) << render.run.err;
    EXPECT_NE(lines[0].find(names), std::string::npos) << lines[0];
    EXPECT_NE(lines[0].find(reason), std::string::npos) << lines[0];
    EXPECT_FALSE(fs::exists(materialDir.parent_path() / "out.png"));
}

TEST(MaterialDir, MissingFolder) {
    const fs::path dir = testOutputDir("material_missing_dir");
    expectOneLineError(dir / "nowhere", "nowhere", "no such folder");
}

TEST(MaterialDir, EachRequiredMapMissing) {
    for (const char* map : {"albedo", "normal", "metallic", "roughness"}) {
        const fs::path dir = testOutputDir(std::string("material_missing_") + map);
        const fs::path set = writePlainSet(dir / "set", makeMaps());
        fs::remove(set / (std::string(map) + ".png"));
        expectOneLineError(set, "set: missing the " + std::string(map) + " map",
                           "after any prefix");
    }
}

// The names real sets use: a prefix, another word for the map, any case, a resolution tag. Each
// folder holds the plain set's pixels under such names and must draw the very same bytes.
TEST(MaterialDir, DownloadedSetNamesGiveTheSamePicture) {
    const fs::path dir = testOutputDir("material_names");
    const TestMaps m = makeMaps();
    const SampleRender plain = renderSet(writePlainSet(dir / "plain", m), dir / "plain.png");
    ASSERT_EQ(plain.run.exitCode, 0) << plain.run.err;
    const std::vector<std::vector<std::string>> layouts = {
        // albedo, normal, metallic, roughness, ao
        {"rustediron2_basecolor.png", "rustediron2_normal.png", "rustediron2_metallic.png",
         "rustediron2_roughness.png", "rustediron2_ao.png"},  // freepbr
        {"Bricks076C_1K_Color.PNG", "Bricks076C_1K_NormalGL.PNG", "Bricks076C_1K_Metalness.PNG",
         "Bricks076C_1K_Roughness.PNG", "Bricks076C_1K_AmbientOcclusion.PNG"},  // ambientCG
        {"brick_wall_diff_4k.png", "brick_wall_nor_gl_4k.png", "brick_wall_metal_4k.png",
         "brick_wall_rough_4k.png", "brick_wall_ao_4k.png"},  // Poly Haven
        {"Diffuse.png", "Normal.png", "Metallic.png", "Roughness.png", "Occlusion.png"},
        {"base_color.png", "normal-ogl.png", "metalness.png", "roughness.png",
         "ambient_occlusion.png"},
    };
    int index = 0;
    for (const auto& names : layouts) {
        const fs::path set = dir / ("set" + std::to_string(index++));
        fs::create_directories(set);
        writePng(set / names[0], Image{kSize, kSize, 3, m.albedo});
        writePng(set / names[1], Image{kSize, kSize, 3, m.normal});
        writePng(set / names[2], Image{kSize, kSize, 1, m.metallic});
        writePng(set / names[3], Image{kSize, kSize, 1, m.roughness});
        writePng(set / names[4], Image{kSize, kSize, 1, m.ao});
        writePng(set / "preview_height.png", Image{2, 2, 1, {0, 0, 0, 0}});  // not a map: ignored
        const SampleRender render = renderSet(set, set.string() + ".png");
        ASSERT_EQ(render.run.exitCode, 0) << names[0] << ": " << render.run.err;
        EXPECT_TRUE(readBytes(render.image) == readBytes(plain.image)) << names[0];
    }
}

// A DirectX normal map (green pointing down) is flipped on load: stored so, it draws exactly what
// the OpenGL map draws; beside an OpenGL map, the OpenGL one is used.
TEST(MaterialDir, DirectXNormalMapsAreFlipped) {
    const fs::path dir = testOutputDir("material_directx");
    const TestMaps m = makeMaps();
    const SampleRender plain = renderSet(writePlainSet(dir / "plain", m), dir / "plain.png");
    std::vector<std::uint8_t> directX = m.normal;
    for (size_t i = 1; i < directX.size(); i += 3) directX[i] = std::uint8_t(255 - directX[i]);

    const fs::path set = writePlainSet(dir / "dx", m);
    fs::remove(set / "normal.png");
    writePng(set / "wall_normal_dx.png", Image{kSize, kSize, 3, directX});
    const SampleRender flipped = renderSet(set, dir / "dx.png");
    ASSERT_EQ(flipped.run.exitCode, 0) << flipped.run.err;
    EXPECT_TRUE(readBytes(flipped.image) == readBytes(plain.image));

    writePng(set / "wall_normal_gl.png", Image{kSize, kSize, 3, m.normal});
    const SampleRender both = renderSet(set, dir / "both.png");
    ASSERT_EQ(both.run.exitCode, 0) << both.run.err;
    EXPECT_TRUE(readBytes(both.image) == readBytes(plain.image));

    // Without the flip the picture would differ: the test sees the convention.
    fs::remove(set / "wall_normal_gl.png");
    fs::remove(set / "wall_normal_dx.png");
    writePng(set / "wall_normal.png", Image{kSize, kSize, 3, directX});
    const SampleRender unflipped = renderSet(set, dir / "unflipped.png");
    EXPECT_FALSE(readBytes(unflipped.image) == readBytes(plain.image));
}

// Two files for one map: one line naming both.
TEST(MaterialDir, TwoFilesForOneMapAreNamed) {
    const fs::path dir = testOutputDir("material_ambiguous");
    const TestMaps m = makeMaps();
    const fs::path set = writePlainSet(dir / "set", m);
    writePng(set / "BaseColor.png", Image{kSize, kSize, 3, m.albedo});
    expectOneLineError(set, "2 files for the albedo map (BaseColor.png and albedo.png)",
                       "keep one");
    const fs::path jpeg = writePlainSet(dir / "jpeg", m);
    stbi_write_jpg((jpeg / "roughness.jpg").c_str(), kSize, kSize, 1, m.roughness.data(), 95);
    expectOneLineError(jpeg, "2 files for the roughness map (roughness.jpg and roughness.png)",
                       "keep one");
}

TEST(MaterialDir, BrokenFiles) {
    const fs::path dir = testOutputDir("material_broken");
    const TestMaps m = makeMaps();

    const fs::path truncated = writePlainSet(dir / "truncated", m);
    const std::string whole = readBytes(truncated / "normal.png");
    std::ofstream(truncated / "normal.png", std::ios::binary | std::ios::trunc)
        << whole.substr(0, whole.size() / 2);
    expectOneLineError(truncated, "normal.png", "truncated or damaged PNG data");

    const fs::path empty = writePlainSet(dir / "empty", m);
    std::ofstream(empty / "albedo.png", std::ios::trunc).close();
    expectOneLineError(empty, "albedo.png", "empty file");

    const fs::path text = writePlainSet(dir / "text", m);
    std::ofstream(text / "metallic.png", std::ios::trunc) << "metallic = 1.0\n";
    expectOneLineError(text, "metallic.png", "not a PNG or JPEG image");
}

TEST(MaterialDir, BadFlagValuesAreUsageErrors) {
    for (const auto& [flag, value] : std::vector<std::pair<std::string, std::string>>{
             {"--filter", "bilinear"}, {"--tangent-frame", "bitangent"}}) {
        const RunResult run = runSample({"02_lighting_textured", "--headless", flag, value});
        EXPECT_EQ(run.exitCode, 2);
        const auto lines = run.errLines();
        ASSERT_FALSE(lines.empty());
        EXPECT_EQ(lines.back().rfind("error: " + flag + ": '" + value + "'", 0), 0u)
            << lines.back();
    }
}

}  // namespace
}  // namespace pbr::test
