// Sample 03 against the unlit arithmetic done on the CPU from the same file: at pixels of the
// project's showcase, colour = baseColorFactor x vertex colour x baseColorTexture, within 1/255.
//
// Exactness: no MSAA; a pixel is compared only where its ray hits a triangle away from the
// triangle's edges (barycentrics >= 0.02), so perspective-correct interpolation of the vertex
// colours is the same on both sides; and, on textured objects, only where the hit's uv lies 4 or
// more texels inside one of the texture's 16 x 16 blocks, so every tap of trilinear filtering
// (to mip level 2) reads that block's colour.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>

#include "base/paths.h"
#include "gltf/model.h"
#include "math/camera.h"
#include "support/golden.h"
#include "support/mesh_hit.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;


TEST(Reference, GltfUnlit03IsFactorTimesVertexColourTimesTexel) {
    constexpr int kWidth = 1280, kHeight = 720;
    const fs::path dir = testOutputDir("reference_03");
    const SampleRender render =
        renderSample("03_gltf_unlit", dir / "03_nomsaa.png", {"--msaa", "0"});
    ASSERT_EQ(render.run.exitCode, 0) << render.run.err;
    const Image image = readImage(render.image, 3);

    const Model model = loadModel(modelDir() / "unlit_showcase.gltf");
    const Image texture = loadTextureImage(model,
                                           model.materials[0].baseColorTexture.present()
                                               ? model.materials[0].baseColorTexture
                                               : model.materials[2].baseColorTexture,
                                           3);
    ASSERT_EQ(texture.width, 128);

    // The view at time 0: the model framed into a unit sphere, the camera on +Z looking down -Z.
    const float aspect = float(kWidth) / float(kHeight);
    const Framing framing = frameBounds(model.boundsMin, model.boundsMax, 45.0f, aspect);
    const glm::dmat4 toWorld = glm::inverse(
        glm::dmat4(glm::perspective(glm::radians(45.0f), aspect, 0.1f, 100.0f) *
                   glm::lookAt(framing.cameraPosition, framing.cameraPosition + glm::vec3(0, 0, -1),
                               glm::vec3(0, 1, 0))));

    const ModelRayCaster caster(model, glm::dmat4(framing.normalize));
    int compared = 0, textured = 0;
    double worst = 0.0;
    for (int py = 0; py < kHeight; py += 4) {
        for (int px = 0; px < kWidth; px += 4) {
            const auto [origin, dir] = pixelRay(toWorld, kWidth, kHeight, px, py);
            const auto hit = caster.hit(origin, dir);
            if (!hit || hit->minBarycentric < 0.02) continue;
            const Material& material =
                model.materials[size_t(model.primitives[size_t(hit->primitive)].material)];
            glm::dvec4 color = hit->color * glm::dvec4(material.baseColorFactor);
            if (material.baseColorTexture.present()) {
                const glm::dvec2 texel = hit->uv0 * 128.0;
                const glm::dvec2 inBlock = texel - 16.0 * glm::floor(texel / 16.0);
                if (std::min(inBlock.x, inBlock.y) < 4.0 || std::max(inBlock.x, inBlock.y) > 12.0)
                    continue;
                const int tx = std::clamp(int(texel.x), 0, 127),
                          ty = std::clamp(int(texel.y), 0, 127);
                for (int c = 0; c < 3; ++c) color[c] *= srgbToLinear(texture.at(tx, ty, c) / 255.0);
                ++textured;
            }
            for (int c = 0; c < 3; ++c) {
                const double expected = std::round(linearToSrgb(color[c]) * 255.0);
                const double diff = std::abs(double(image.at(px, py, c)) - expected);
                worst = std::max(worst, diff);
                EXPECT_LE(diff, 1.0)
                    << material.name << " at pixel (" << px << ", " << py << ") channel " << c
                    << ": rendered " << int(image.at(px, py, c)) << ", CPU " << expected;
            }
            ++compared;
        }
    }
    std::printf("compared %d pixels (%d textured); worst channel diff %.0f/255\n", compared,
                textured, worst);
    EXPECT_GT(compared, 2000);
    EXPECT_GT(textured, 400);
}

// glTF's BLEND mode mixes colours in linear light (the specification's alpha coverage: the
// result is the source times alpha plus the destination times 1 - alpha, both as light). A red
// quad of alpha 0.5 over an opaque green one must come out encode(0.5 red + 0.5 green) =
// (188, 188, 0), not the (128, 128, 0) of blending the sRGB-encoded bytes.
TEST(Reference, GltfUnlit03BlendsInLinearLight) {
    const fs::path dir = testOutputDir("reference_03_blend");
    // Two quads facing +Z: the back one opaque green, 2 x 2; the front one, 0.1 nearer, red at
    // alpha 0.5, 1 x 1. Counter-clockwise from the camera.
    std::string bin;
    auto put = [&bin](const auto& value) {
        bin.append(reinterpret_cast<const char*>(&value), sizeof value);
    };
    for (const auto& [size, z] : {std::pair{1.0f, 0.0f}, std::pair{0.5f, 0.1f}}) {
        for (const auto& [x, y] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
            put(float(x) * size);
            put(float(y) * size);
            put(z);
        }
    }
    for (const std::uint16_t index : {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7}) put(index);
    std::ofstream(dir / "quads.bin", std::ios::binary) << bin;
    std::ofstream(dir / "quads.gltf") << R"({
  "asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_materials_unlit"],
  "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [
    {"attributes": {"POSITION": 0}, "indices": 1, "material": 0},
    {"attributes": {"POSITION": 0}, "indices": 2, "material": 1}]}],
  "materials": [
    {"pbrMetallicRoughness": {"baseColorFactor": [0, 1, 0, 1]},
     "extensions": {"KHR_materials_unlit": {}}},
    {"pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 0.5]}, "alphaMode": "BLEND",
     "extensions": {"KHR_materials_unlit": {}}}],
  "buffers": [{"uri": "quads.bin", "byteLength": 120}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 96},
                  {"buffer": 0, "byteOffset": 96, "byteLength": 24}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3",
     "min": [-1, -1, 0], "max": [1, 1, 0.1]},
    {"bufferView": 1, "byteOffset": 0, "componentType": 5123, "count": 6, "type": "SCALAR"},
    {"bufferView": 1, "byteOffset": 12, "componentType": 5123, "count": 6, "type": "SCALAR"}]
})";
    const SampleRender render = renderSample(
        "03_gltf_unlit", dir / "blend.png",
        {"--model", (dir / "quads.gltf").string(), "--msaa", "0", "--size", "200x200"});
    ASSERT_EQ(render.run.exitCode, 0) << render.run.err;
    const Image image = readImage(render.image, 3);
    auto expectPixel = [&](int x, int y, glm::dvec3 linear) {
        for (int c = 0; c < 3; ++c) {
            const int expected = int(std::lround(linearToSrgb(linear[c]) * 255.0));
            EXPECT_NEAR(image.at(x, y, c), expected, 1)
                << "pixel " << x << ", " << y << " channel " << c;
        }
    };
    expectPixel(100, 100, {0.5, 0.5, 0.0});  // the centre: both quads
    expectPixel(100, 60, {0.0, 1.0, 0.0});   // the back quad alone
    EXPECT_NEAR(image.at(100, 100, 0), 188, 1);
}

}  // namespace
}  // namespace pbr::test
