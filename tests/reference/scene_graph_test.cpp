// Sample 07's scene graph and per-texture state against answers the test knows: each scene is
// written twice, once using the feature (a node hierarchy, a mirroring node, a double-sided back
// face, a texture transform on each slot, one image shared by two samplers) and once with the same
// result baked into plain data by the test itself (vertices transformed here with glm, the light
// placed in world space, the mirrored or turned-around geometry with its normals and tangents,
// the textures resampled, the image copied). 07 draws both from the same camera and the two
// pictures must agree. Blending has a closed form instead: unlit layers composited here from
// their alphas, at every pixel whose layers are known. Debian's 2CylinderEngine is compared with
// its own hierarchy flattened by the test.
//
// Every render: --no-ibl --tonemap none --msaa 1, small, so the file runs in seconds (about 5 s
// on llvmpipe). Without image-based light the occlusion texture shows nothing, so its transform is
// not among the slots compared. Each test was seen to fail with its bug planted: child x parent
// for meshes or for lights, no winding turn under a mirror, blended layers nearest first or
// writing depth, the back face's tangent frame left unturned, one slot read through another's
// transform, a second texture of an image losing its sampler, the handedness not turned under a
// mirror.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "support/gltf_scene.h"
#include "support/golden.h"
#include "support/mesh_hit.h"
#include "support/test_data.h"

#include "files/gltf_file.h"
#include "files/image.h"
#include "gltf/model.h"
#include "math/camera.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

constexpr double kPi = std::numbers::pi;

std::string vec3Arg(const glm::vec3& v) {
    return std::to_string(v.x) + "," + std::to_string(v.y) + "," + std::to_string(v.z);
}

// 07 on `model` seen from `eye`, no image-based light, no tone mapping, no MSAA; the picture
// goes to dir/<model's stem>.png.
Image render07(const fs::path& dir, const fs::path& model, const glm::vec3& eye,
               const glm::ivec2& size) {
    const SampleRender render = renderSample(
        "07_gltf_metallic_roughness", dir / (model.stem().string() + ".png"),
        {"--model", model.string(), "--no-ibl", "--tonemap", "none", "--msaa", "1", "--size",
         std::to_string(size.x) + "x" + std::to_string(size.y), "--camera", vec3Arg(eye)});
    EXPECT_EQ(render.run.exitCode, 0) << render.run.err;
    EXPECT_EQ(render.run.err.find("GL error"), std::string::npos) << render.run.err;
    if (render.run.exitCode != 0) return {};
    return readImage(render.image, 3);
}

// The two renders of a pair agree: at most `gate.maxFractionOver` of the pixels differ by more
// than `gate.channelThreshold` levels and the PSNR is at least `gate.minPsnr`. Both must show
// something (at least `minCovered` of the pixels unlike the corner). On failure the amplified
// difference is left beside the renders.
void expectPairAgrees(const std::string& what, const fs::path& dir, const Image& feature,
                      const Image& baked, const GoldenGate& gate, double minCovered = 0.1) {
    ASSERT_FALSE(feature.pixels.empty());
    ASSERT_FALSE(baked.pixels.empty());
    ASSERT_EQ(feature.pixels.size(), baked.pixels.size());
    const ImageDiff diff = compareImages(feature, baked, gate.channelThreshold);
    const double covered =
        double(pixelsUnlikeCorner(baked)) / double(baked.width) / double(baked.height);
    std::printf(
        "%s: max channel difference %d/255, %zu pixels (%.3f %%) over %d, PSNR %.1f dB; "
        "%.0f %% of the picture drawn\n",
        what.c_str(), diff.maxChannelDiff, diff.pixelsOverThreshold,
        100.0 * diff.fractionOverThreshold, gate.channelThreshold, diff.psnr, 100.0 * covered);
    EXPECT_GE(covered, minCovered) << what << ": the baked render is nearly empty";
    const bool pass =
        diff.fractionOverThreshold <= gate.maxFractionOver && diff.psnr >= gate.minPsnr;
    EXPECT_TRUE(pass) << what << ": " << diff.pixelsOverThreshold << " pixels differ by more than "
                      << gate.channelThreshold << " (allowed fraction " << gate.maxFractionOver
                      << "), PSNR " << diff.psnr << " dB (at least " << gate.minPsnr << "); see "
                      << (dir / "difference.png");
    if (!pass) writePng(dir / "difference.png", differenceImage(feature, baked, 8));
}

// The gate for a pair. Measured on llvmpipe (Mesa 22.3.6, 2026-12-02) the pairs differ by at
// most 1/255 at any pixel (PSNR 94-95 dB, or identical); each planted bug moves 7-69 % of the
// pixels by 64-252/255 (PSNR 9-25 dB). 2/255 on at most 0.2 % of the pixels and 45 dB leave room
// for another build's rounding at edges and nothing for a misplaced part or a turned normal.
constexpr GoldenGate kPairGate{.channelThreshold = 2, .maxFractionOver = 0.002, .minPsnr = 45.0};

// ---- geometry, as plain arrays the test can transform ----

// A w x h rectangle in the XY plane at the origin facing +Z (counter-clockwise seen from +Z),
// uv (0, 0) at its top left and (1, 1) at its bottom right, tangent +X (along +u).
GltfMeshArrays rectangle(float halfWidth, float halfHeight) {
    GltfMeshArrays m;
    const float corners[4][2] = {{-halfWidth, -halfHeight},
                                 {halfWidth, -halfHeight},
                                 {halfWidth, halfHeight},
                                 {-halfWidth, halfHeight}};
    for (const auto& c : corners) {
        m.positions.push_back({c[0], c[1], 0.0f});
        m.normals.push_back({0.0f, 0.0f, 1.0f});
        m.uvs.push_back(
            {(c[0] + halfWidth) / (2 * halfWidth), (halfHeight - c[1]) / (2 * halfHeight)});
        m.tangents.push_back({1.0f, 0.0f, 0.0f, 1.0f});
    }
    m.indices = {0, 1, 2, 0, 2, 3};
    return m;
}

// A box of half extents `half` with flat faces (four vertices each), counter-clockwise outside.
GltfMeshArrays box(const glm::vec3& half) {
    GltfMeshArrays m;
    for (int axis = 0; axis < 3; ++axis) {
        for (const float sign : {1.0f, -1.0f}) {
            glm::vec3 n(0.0f), u(0.0f), v(0.0f);
            n[axis] = sign;
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = 1.0f;
            if (sign < 0.0f) u = -u;  // keep u x v = n
            const auto base = std::uint32_t(m.positions.size());
            for (const auto& [a, b] :
                 {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}}) {
                m.positions.push_back(half * (n + a * u + b * v));
                m.normals.push_back(n);
                m.uvs.push_back({0.5f * (a + 1.0f), 0.5f * (1.0f - b)});
                m.tangents.push_back(glm::vec4(u, 1.0f));
            }
            for (const std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
        }
    }
    return m;
}

// `mesh` with `matrix` applied to its data: positions, normals by the inverse transpose,
// tangents by the matrix with their handedness times the sign of its determinant, and, where the
// determinant is negative, every triangle wound the other way: what a renderer must make of the
// same mesh under a node with that matrix (glTF 2.0, 3.7.4 and 3.7.2.1).
GltfMeshArrays baked(const GltfMeshArrays& mesh, const glm::dmat4& matrix) {
    const glm::dmat3 linear(matrix);
    const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(linear));
    const double sign = glm::determinant(linear) < 0.0 ? -1.0 : 1.0;
    GltfMeshArrays out = mesh;
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        out.positions[i] = glm::vec3(matrix * glm::dvec4(glm::dvec3(mesh.positions[i]), 1.0));
        out.normals[i] = glm::vec3(glm::normalize(normalMatrix * glm::dvec3(mesh.normals[i])));
        out.tangents[i] =
            glm::vec4(glm::vec3(glm::normalize(linear * glm::dvec3(glm::vec3(mesh.tangents[i])))),
                      float(sign * mesh.tangents[i].w));
    }
    if (sign < 0.0) {
        for (size_t i = 0; i + 2 < out.indices.size(); i += 3)
            std::swap(out.indices[i + 1], out.indices[i + 2]);
    }
    return out;
}

// ---- node transforms, from the numbers a node's JSON holds ----

struct Trs {
    glm::dvec3 translation{0.0};
    glm::dvec4 rotation{0.0, 0.0, 0.0, 1.0};  // glTF's order: x, y, z, w
    glm::dvec3 scale{1.0};

    glm::dmat4 matrix() const {
        const glm::dmat4 t = glm::translate(glm::dmat4(1.0), translation);
        const glm::dmat4 r =
            glm::mat4_cast(glm::dquat(rotation.w, rotation.x, rotation.y, rotation.z));
        return t * r * glm::scale(glm::dmat4(1.0), scale);
    }
    std::string json() const {
        char text[512];
        std::snprintf(text, sizeof text,
                      R"("translation":[%.17g,%.17g,%.17g],"rotation":[%.17g,%.17g,%.17g,%.17g],)"
                      R"("scale":[%.17g,%.17g,%.17g])",
                      translation.x, translation.y, translation.z, rotation.x, rotation.y,
                      rotation.z, rotation.w, scale.x, scale.y, scale.z);
        return text;
    }
};

// A unit quaternion (glTF order) turning by `degrees` about `axis`.
glm::dvec4 turn(const glm::dvec3& axis, double degrees) {
    const glm::dvec3 a = glm::normalize(axis);
    const double half = degrees * kPi / 360.0;
    return {a * std::sin(half), std::cos(half)};
}

// The unit quaternion (glTF order) turning -Z onto `direction`: a light node shining that way.
glm::dvec4 lookingAlong(const glm::dvec3& direction) {
    const glm::dvec3 from(0.0, 0.0, -1.0), to = glm::normalize(direction);
    const glm::dvec4 q(glm::cross(from, to), 1.0 + glm::dot(from, to));
    return q / glm::length(q);
}

// ---- textures ----

// A normal map from a height field of a few bumps and a ridge, none of them symmetric in u or in
// v, so that x and y of its normals vary everywhere (64 x 64, RGB).
Image bumpyNormalMap() {
    constexpr int n = 64;
    auto height = [](double u, double v) {
        const double bumps =
            std::exp(-((u - 0.3) * (u - 0.3) + (v - 0.35) * (v - 0.35)) / 0.01) -
            0.7 * std::exp(-((u - 0.7) * (u - 0.7) + (v - 0.6) * (v - 0.6)) / 0.02);
        return 0.08 * bumps + 0.02 * std::sin(2 * kPi * (1.5 * u + 2.5 * v * v));
    };
    Image image{n, n, 3, {}};
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            const double u = (x + 0.5) / n, v = (y + 0.5) / n, e = 1e-3;
            const double du = (height(u + e, v) - height(u - e, v)) / (2 * e);
            const double dv = (height(u, v + e) - height(u, v - e)) / (2 * e);
            // +Y of the normal map points up the image, i.e. towards -v
            const glm::dvec3 normal = glm::normalize(glm::dvec3(-du, dv, 1.0));
            for (int c = 0; c < 3; ++c)
                image.pixels.push_back(std::uint8_t(std::lround((normal[c] * 0.5 + 0.5) * 255.0)));
        }
    }
    return image;
}

// ---- (a) nested node transforms, for meshes and for a light ----

// Three boxes, each under the last (rotation, non-uniform scale and translation at every level,
// so the order of the products matters), a spot light under the second box and a floor at the
// root, against the same boxes with their world matrices applied to their vertices and the spot
// on a root node at its world position and direction.
TEST(SceneGraph, NestedNodeTransformsMatchBakedVertices) {
    const fs::path dir = testOutputDir("scene_graph_nested");
    const Trs level1{{0.2, 0.5, -0.3}, turn({0.3, 1.0, 0.2}, 35.0), {1.4, 0.6, 0.9}};
    const Trs level2{{0.8, 0.6, 0.3}, turn({1.0, 0.2, 0.0}, 50.0), {0.7, 1.5, 0.8}};
    const Trs level3{{0.1, 0.9, 0.5}, turn({0.0, 0.3, 1.0}, -40.0), {1.3, 0.5, 1.1}};
    const Trs spot{{-0.6, 0.8, 1.8}, turn({1.0, 0.0, 0.0}, -55.0), {1.0, 1.0, 1.0}};
    const GltfMeshArrays floor =
        baked(rectangle(2.0f, 2.0f), glm::rotate(glm::dmat4(1.0), -kPi / 2, {1.0, 0.0, 0.0}));
    const GltfMeshArrays cube = box(glm::vec3(0.3f));
    const glm::dmat4 world1 = level1.matrix();
    const glm::dmat4 world2 = world1 * level2.matrix();
    const glm::dmat4 world3 = world2 * level3.matrix();
    const glm::dmat4 spotWorld = world2 * spot.matrix();

    const std::string materials = R"("materials":[
  {"pbrMetallicRoughness":{"baseColorFactor":[0.7,0.7,0.7,1],"metallicFactor":0,"roughnessFactor":0.8}},
  {"pbrMetallicRoughness":{"baseColorFactor":[0.9,0.2,0.1,1],"metallicFactor":0,"roughnessFactor":0.5}},
  {"pbrMetallicRoughness":{"baseColorFactor":[0.1,0.8,0.2,1],"metallicFactor":0,"roughnessFactor":0.5}},
  {"pbrMetallicRoughness":{"baseColorFactor":[0.2,0.3,0.9,1],"metallicFactor":0,"roughnessFactor":0.5}}],
)";
    const std::string lights = R"("extensionsUsed":["KHR_lights_punctual"],
"extensions":{"KHR_lights_punctual":{"lights":[
  {"type":"spot","intensity":25,"color":[1,0.9,0.7],"spot":{"innerConeAngle":0.25,"outerConeAngle":0.45}},
  {"type":"directional","intensity":0.6}]}},
)";
    const std::string sun = R"({"name":"sun",)" + Trs{{}, turn({1.0, 0.4, 0.0}, -60.0)}.json() +
                            R"(,"extensions":{"KHR_lights_punctual":{"light":1}}})";
    auto light = [](const std::string& placement) {
        return R"({"name":"spot",)" + placement +
               R"(,"extensions":{"KHR_lights_punctual":{"light":0}}})";
    };
    const fs::path nested = writeTextFile(dir, "nested.gltf", R"({"asset":{"version":"2.0"},
)" + lights + meshBuffersJson({floor, cube}) + materials + R"("meshes":[
  {"primitives":[)" + meshPrimitiveJson(0, 0) + R"(]},
  {"primitives":[)" + meshPrimitiveJson(1, 1) + R"(]},
  {"primitives":[)" + meshPrimitiveJson(1, 2) + R"(]},
  {"primitives":[)" + meshPrimitiveJson(1, 3) + R"(]}],
"nodes":[{"name":"floor","mesh":0},
  {"name":"level1","mesh":1,"children":[2],)" + level1.json() + R"(},
  {"name":"level2","mesh":2,"children":[3,4],)" + level2.json() + R"(},
  {"name":"level3","mesh":3,)" + level3.json() + R"(},
  )" + light(spot.json()) + ",\n  " + sun + R"(],
"scenes":[{"nodes":[0,1,5]}],"scene":0})");

    const glm::dvec3 spotPosition(spotWorld[3]);
    const glm::dvec3 spotDirection = glm::dmat3(spotWorld) * glm::dvec3(0.0, 0.0, -1.0);
    const fs::path flat =
        writeTextFile(dir, "flat.gltf",
                      R"({"asset":{"version":"2.0"},
)" + lights +
                          meshBuffersJson({floor, baked(cube, world1), baked(cube, world2),
                                           baked(cube, world3)}) +
                          materials + R"("meshes":[
  {"primitives":[)" + meshPrimitiveJson(0, 0) +
                          R"(]},
  {"primitives":[)" + meshPrimitiveJson(1, 1) +
                          R"(]},
  {"primitives":[)" + meshPrimitiveJson(2, 2) +
                          R"(]},
  {"primitives":[)" + meshPrimitiveJson(3, 3) +
                          R"(]}],
"nodes":[{"name":"floor","mesh":0},{"mesh":1},{"mesh":2},{"mesh":3},
  )" + light(Trs{spotPosition, lookingAlong(spotDirection)}.json()) +
                          ",\n  " + sun + R"(],
"scenes":[{"nodes":[0,1,2,3,4,5]}],"scene":0})");

    // the loader places the light where the test does (the picture then shows the pool)
    const Model model = loadModel(nested);
    ASSERT_EQ(model.lights.size(), 2u);
    const auto spotLight = std::find_if(model.lights.begin(), model.lights.end(),
                                        [](const PunctualLight& l) { return l.name == "spot"; });
    ASSERT_NE(spotLight, model.lights.end());
    EXPECT_LT(glm::distance(glm::dvec3(spotLight->position), spotPosition), 1e-4);
    EXPECT_LT(glm::distance(glm::dvec3(spotLight->direction), glm::normalize(spotDirection)), 1e-4);

    const glm::vec3 eye(2.0f, 3.2f, 4.4f);
    const glm::ivec2 size(256, 192);
    expectPairAgrees("nested nodes", dir, render07(dir, nested, eye, size),
                     render07(dir, flat, eye, size), kPairGate);
}

// ---- (b), (g) a mirroring node ----

// A normal-mapped square under a node that mirrors x (scale -1), single-sided, beside an
// unmirrored twin, against the same square mirrored by the test: positions and normals
// mirrored, every triangle wound the other way (the front stays the front) and the tangent's
// handedness turned (the bitangent keeps pointing where the mirrored image's top is).
TEST(SceneGraph, MirroredNodeMatchesBakedMirror) {
    const fs::path dir = testOutputDir("scene_graph_mirror");
    writePng(dir / "bumps.png", bumpyNormalMap());
    const GltfMeshArrays square = rectangle(0.8f, 0.8f);
    const Trs mirror{{0.9, 0.0, 0.0}, turn({0.0, 1.0, 0.0}, 15.0), {-1.0, 1.0, 1.0}};
    const Trs twin{{-0.9, 0.0, 0.0}, turn({0.0, 1.0, 0.0}, -15.0), {1.0, 1.0, 1.0}};
    const std::string common = R"("asset":{"version":"2.0"},
"extensionsUsed":["KHR_lights_punctual"],
"extensions":{"KHR_lights_punctual":{"lights":[
  {"type":"directional","intensity":2.5},{"type":"point","intensity":3,"color":[1,0.8,0.6]}]}},
"images":[{"uri":"bumps.png"}],"textures":[{"source":0}],
"materials":[{"normalTexture":{"index":0},"pbrMetallicRoughness":{
  "baseColorFactor":[0.8,0.8,0.8,1],"metallicFactor":0,"roughnessFactor":0.45}}],
"meshes":[{"primitives":[)" + meshPrimitiveJson(0, 0) +
                               R"(]},{"primitives":[)" + meshPrimitiveJson(1, 0) + R"(]}],
)";
    const std::string lightNodes = R"({"name":"sun",)" +
                                   Trs{{}, lookingAlong({0.5, -0.6, -0.6})}.json() +
                                   R"(,"extensions":{"KHR_lights_punctual":{"light":0}}},
  {"name":"lamp","translation":[0.2,0.9,0.9],"extensions":{"KHR_lights_punctual":{"light":1}}})";
    const fs::path mirrored =
        writeTextFile(dir, "mirrored.gltf",
                      "{" + common + meshBuffersJson({square, square}) + R"("nodes":[
  {"name":"mirrored","mesh":0,)" +
                          mirror.json() + R"(},{"name":"twin","mesh":1,)" + twin.json() + "},\n  " +
                          lightNodes + R"(],"scenes":[{"nodes":[0,1,2,3]}],"scene":0})");
    const fs::path flat = writeTextFile(dir, "flat.gltf",
                                        "{" + common +
                                            meshBuffersJson({baked(square, mirror.matrix()),
                                                             baked(square, twin.matrix())}) +
                                            R"("nodes":[{"mesh":0},{"mesh":1},
  )" + lightNodes + R"(],"scenes":[{"nodes":[0,1,2,3]}],"scene":0})");
    const glm::vec3 eye(0.0f, 0.3f, 3.6f);
    const glm::ivec2 size(256, 144);
    expectPairAgrees("mirrored node", dir, render07(dir, mirrored, eye, size),
                     render07(dir, flat, eye, size), kPairGate, 0.2);
}

// 07's normal view reads the normal map: a square facing the eye whose normal map holds one
// tangent-space normal, (0.6, 0, 0.8) as texels (204, 128, 230), shows that normal turned by the
// square's frame (tangent +X, normal +Z) at every pixel, 0.5 + 0.5 N, as the shader decodes the
// texel (2 t - 1, normalised). A view that ignored the map would show (0, 0, 1).
TEST(SceneGraph, NormalViewReadsTheNormalMap) {
    const fs::path dir = testOutputDir("scene_graph_normal_view");
    const std::array<std::uint8_t, 3> texel = {204, 128, 230};
    Image tilted{4, 4, 3, {}};
    for (int i = 0; i < 16; ++i)
        tilted.pixels.insert(tilted.pixels.end(), texel.begin(), texel.end());
    writePng(dir / "tilted.png", tilted);
    const fs::path model =
        writeTextFile(dir, "tilted.gltf",
                      R"({"asset":{"version":"2.0"},
"images":[{"uri":"tilted.png"}],"textures":[{"source":0}],
"materials":[{"normalTexture":{"index":0}}],
"meshes":[{"primitives":[)" +
                          meshPrimitiveJson(0, 0) + R"(]}],
)" + meshBuffersJson({rectangle(0.8f, 0.8f)}) +
                          R"("nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})");
    const SampleRender render = renderSample("07_gltf_metallic_roughness", dir / "normal.png",
                                             {"--model", model.string(), "--msaa", "0", "--size",
                                              "64x64", "--camera", "0,0,2.5", "--view", "normal"});
    ASSERT_EQ(render.run.exitCode, 0) << render.run.err;
    const Image image = readImage(render.image, 3);
    glm::dvec3 n(0.0);
    for (int c = 0; c < 3; ++c) n[c] = 2.0 * texel[size_t(c)] / 255.0 - 1.0;
    n = glm::normalize(n);  // tangent (1, 0, 0), bitangent (0, +-1, 0), normal (0, 0, 1)
    int compared = 0, worst = 0;
    for (int y = 20; y < 44; ++y) {
        for (int x = 20; x < 44; ++x) {
            for (int c = 0; c < 3; ++c) {
                // the bitangent's sign does not matter: the texel's y is 0.004
                const double expected = 255.0 * (0.5 + 0.5 * n[c]);
                const int got = image.pixels[(size_t(y) * 64 + size_t(x)) * 3 + size_t(c)];
                worst = std::max(worst, int(std::lround(std::abs(got - expected))));
            }
            ++compared;
        }
    }
    std::printf("--view normal on the tilted square: %d pixels, worst channel difference %d/255\n",
                compared, worst);
    EXPECT_LE(worst, 2);
}

// ---- (d) a double-sided back face ----

// A normal-mapped double-sided square seen from behind, against a single-sided square facing the
// other way that is its back side in plain data: the normal turned around, the winding reversed
// and the whole tangent frame turned (tangent and handedness negated), so the shading normal is
// the front's perturbed normal turned around, as the specification flips the normal on a back
// face and the tangent frame with it.
TEST(SceneGraph, DoubleSidedBackFaceMatchesTurnedSheet) {
    const fs::path dir = testOutputDir("scene_graph_back_face");
    writePng(dir / "bumps.png", bumpyNormalMap());
    const GltfMeshArrays front = rectangle(1.0f, 0.8f);
    GltfMeshArrays back = front;
    for (size_t i = 0; i < back.positions.size(); ++i) {
        back.normals[i] = -back.normals[i];
        back.tangents[i] = -back.tangents[i];
    }
    for (size_t i = 0; i + 2 < back.indices.size(); i += 3)
        std::swap(back.indices[i + 1], back.indices[i + 2]);
    auto file = [&](const std::string& name, const GltfMeshArrays& mesh, bool doubleSided) {
        return writeTextFile(dir, name,
                             R"({"asset":{"version":"2.0"},
"extensionsUsed":["KHR_lights_punctual"],
"extensions":{"KHR_lights_punctual":{"lights":[
  {"type":"directional","intensity":2.5},{"type":"point","intensity":2,"color":[0.7,0.8,1]}]}},
"images":[{"uri":"bumps.png"}],"textures":[{"source":0}],
"materials":[{"normalTexture":{"index":0,"scale":1.5},"doubleSided":)" +
                                 std::string(doubleSided ? "true" : "false") +
                                 R"(,"pbrMetallicRoughness":{
  "baseColorFactor":[0.9,0.75,0.5,1],"metallicFactor":0,"roughnessFactor":0.4}}],
)" + meshBuffersJson({mesh}) + R"("meshes":[{"primitives":[)" +
                                 meshPrimitiveJson(0, 0) + R"(]}],
"nodes":[{"mesh":0},{"name":"sun",)" +
                                 Trs{{}, lookingAlong({-0.6, -0.5, 0.6})}.json() +
                                 R"(,"extensions":{"KHR_lights_punctual":{"light":0}}},
  {"name":"lamp","translation":[-0.5,0.4,-0.7],"extensions":{"KHR_lights_punctual":{"light":1}}}],
"scenes":[{"nodes":[0,1,2]}],"scene":0})");
    };
    const fs::path doubleSided = file("double_sided.gltf", front, true);
    const fs::path turned = file("turned.gltf", back, false);
    const glm::vec3 eye(0.4f, 0.3f, -3.2f);
    const glm::ivec2 size(256, 192);
    expectPairAgrees("double-sided back face", dir, render07(dir, doubleSided, eye, size),
                     render07(dir, turned, eye, size), kPairGate, 0.3);
}

// ---- (c) blending, in closed form ----

// Unlit BLEND layers over an unlit opaque backdrop, each a rectangle (centre, two half axes);
// listed nearest first in the file, so only sorting draws them back to front.
struct Layer {
    glm::dvec3 centre, halfU, halfV;
    glm::dvec3 color;  // linear
    double alpha;
};

std::optional<glm::dvec3> hitLayer(const Layer& layer, const glm::dvec3& origin,
                                   const glm::dvec3& direction) {
    const glm::dvec3 normal = glm::normalize(glm::cross(layer.halfU, layer.halfV));
    const double along = glm::dot(direction, normal);
    if (std::abs(along) < 1e-9) return std::nullopt;
    const double t = glm::dot(layer.centre - origin, normal) / along;
    const glm::dvec3 p = origin + t * direction;
    const glm::dvec3 d = p - layer.centre;
    if (std::abs(glm::dot(d, layer.halfU)) > glm::dot(layer.halfU, layer.halfU) ||
        std::abs(glm::dot(d, layer.halfV)) > glm::dot(layer.halfV, layer.halfV))
        return std::nullopt;
    return p;
}

// The blended layers composited back to front (by the view depth of their centres, the order
// the renderer promises) into an sRGB8 target: each blend in linear light, the result stored as
// 8-bit sRGB before the next, none hiding another (no depth writes among them).
TEST(SceneGraph, BlendedLayersCompositeBackToFront) {
    const fs::path dir = testOutputDir("scene_graph_blend");
    const double tilt = 35.0 * kPi / 180.0;
    // nearest first: blue, green, the tilted yellow one (its centre between green and red but its
    // left end in front of green), red, then the backdrop
    const std::vector<Layer> layers = {
        {{0.45, -0.35, 0.3}, {0.7, 0, 0}, {0, 0.45, 0}, {0.1, 0.2, 0.9}, 0.6},
        {{0.0, 0.1, -0.3}, {0.7, 0, 0}, {0, 0.45, 0}, {0.1, 0.8, 0.2}, 0.4},
        {{0.2, 0.6, -0.5}, {std::cos(tilt), 0, std::sin(tilt)}, {0, 0.3, 0}, {0.9, 0.8, 0.1}, 0.5},
        {{-0.5, 0.3, -0.9}, {0.7, 0, 0}, {0, 0.5, 0}, {0.9, 0.1, 0.1}, 0.5},
    };
    const Layer backdrop{{0.0, 0.0, -1.5}, {2.2, 0, 0}, {0, 1.6, 0}, {0.2, 0.2, 0.2}, 1.0};
    std::vector<GltfMeshArrays> meshes;
    std::string materials, meshList, nodes, sceneNodes;
    auto add = [&](const Layer& layer, bool blend) {
        GltfMeshArrays m = rectangle(1.0f, 1.0f);
        const glm::dvec3 w = glm::normalize(glm::cross(layer.halfU, layer.halfV));
        m = baked(m, glm::dmat4(glm::dvec4(layer.halfU, 0), glm::dvec4(layer.halfV, 0),
                                glm::dvec4(w, 0), glm::dvec4(layer.centre, 1)));
        const int i = int(meshes.size());
        meshes.push_back(m);
        char material[512];
        std::snprintf(material, sizeof material,
                      R"(%s{"pbrMetallicRoughness":{"baseColorFactor":[%.9g,%.9g,%.9g,%.9g]},)"
                      R"("alphaMode":"%s","extensions":{"KHR_materials_unlit":{}}})",
                      i ? "," : "", layer.color.r, layer.color.g, layer.color.b, layer.alpha,
                      blend ? "BLEND" : "OPAQUE");
        materials += material;
        meshList +=
            std::string(i ? "," : "") + R"({"primitives":[)" + meshPrimitiveJson(i, i) + "]}";
        nodes += std::string(i ? "," : "") + R"({"mesh":)" + std::to_string(i) + "}";
        sceneNodes += std::string(i ? "," : "") + std::to_string(i);
    };
    for (const Layer& layer : layers) add(layer, true);
    add(backdrop, false);
    const fs::path file =
        writeTextFile(dir, "layers.gltf",
                      R"({"asset":{"version":"2.0"},
"extensionsUsed":["KHR_materials_unlit"],
)" + meshBuffersJson(meshes) +
                          R"("materials":[)" + materials + R"(],
"meshes":[)" + meshList + R"(],"nodes":[)" +
                          nodes + R"(],"scenes":[{"nodes":[)" + sceneNodes + R"(]}],"scene":0})");

    const glm::vec3 eye(0.3f, 0.2f, 5.0f);
    const glm::ivec2 size(240, 180);
    const Image image = render07(dir, file, eye, size);
    ASSERT_FALSE(image.pixels.empty());
    const Model model = loadModel(file);
    const OrbitCamera camera = OrbitCamera::fromPosition(model.boundsMin, model.boundsMax, eye);
    const glm::dmat4 view(camera.viewMatrix());
    const glm::dmat4 toWorld =
        glm::inverse(glm::dmat4(camera.projectionMatrix(float(size.x) / float(size.y))) * view);
    std::vector<size_t> order(layers.size());  // farthest first
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return (view * glm::dvec4(layers[a].centre, 1.0)).z <
               (view * glm::dvec4(layers[b].centre, 1.0)).z;
    });
    auto store = [](double linear) {  // through the 8-bit sRGB target
        return srgbToLinear(std::round(linearToSrgb(linear) * 255.0) / 255.0);
    };
    // which layers a ray meets, as a bit set, and whether it meets the backdrop
    const unsigned onBackdrop = 1u << layers.size();
    auto cover = [&](double px, double py) {
        const glm::dvec2 ndc(2.0 * px / size.x - 1.0, 1.0 - 2.0 * py / size.y);
        const glm::dvec4 nearPoint = toWorld * glm::dvec4(ndc, -1.0, 1.0);
        const glm::dvec4 farPoint = toWorld * glm::dvec4(ndc, 1.0, 1.0);
        const glm::dvec3 o = glm::dvec3(nearPoint) / nearPoint.w;
        const glm::dvec3 d = glm::normalize(glm::dvec3(farPoint) / farPoint.w - o);
        unsigned bits = hitLayer(backdrop, o, d) ? onBackdrop : 0u;
        for (size_t i = 0; i < layers.size(); ++i)
            if (hitLayer(layers[i], o, d)) bits |= 1u << i;
        return bits;
    };
    std::map<unsigned, int> compared;  // pixels by the set of layers they show
    int worst = 0, wrong = 0;
    std::string firstWrong;
    for (int py = 0; py < size.y; ++py) {
        for (int px = 0; px < size.x; ++px) {
            const unsigned bits = cover(px + 0.5, py + 0.5);
            if (!(bits & onBackdrop)) continue;
            bool inside = true;  // the same layers a pixel and a half around: no edge near
            for (const auto& [dx, dy] :
                 {std::pair{-1.0, -1.0}, {2.0, -1.0}, {-1.0, 2.0}, {2.0, 2.0}})
                inside = inside && cover(px + dx, py + dy) == bits;
            if (!inside) continue;
            glm::dvec3 color = backdrop.color;
            for (const size_t i : order) {
                if (!(bits >> i & 1u)) continue;
                color = layers[i].alpha * layers[i].color + (1.0 - layers[i].alpha) * color;
                color = {store(color.r), store(color.g), store(color.b)};
            }
            int diff = 0;
            for (int c = 0; c < 3; ++c) {
                const int expected = int(std::lround(linearToSrgb(color[c]) * 255.0));
                diff = std::max(diff, std::abs(int(image.at(px, py, c)) - expected));
            }
            worst = std::max(worst, diff);
            if (diff > 1 && wrong++ < 5) {
                firstWrong += "\n  pixel (" + std::to_string(px) + ", " + std::to_string(py) +
                              ") showing layers " + std::to_string(bits & ~onBackdrop) +
                              ": off by " + std::to_string(diff);
            }
            ++compared[bits & ~onBackdrop];
        }
    }
    EXPECT_EQ(wrong, 0) << "pixels off by more than 1/255 from the composite, the first:"
                        << firstWrong;
    std::printf("blended layers: worst channel difference %d/255 over", worst);
    for (const auto& [bits, count] : compared) std::printf(" %u:%d", bits, count);
    std::printf(" (layer set: pixels)\n");
    // every overlap the test is about is there: each layer alone, blue over green over red,
    // the tilted layer in front of green (drawn before it) and behind red (drawn after it)
    for (const unsigned bits : {1u, 2u, 4u, 8u, 1u | 2u | 8u, 2u | 4u, 4u | 8u, 2u | 8u})
        EXPECT_GE(compared[bits], 40) << "layer set " << bits;
}

// ---- (e) a texture transform on each slot ----

// Samples an RGB(A) image at uv with NEAREST filtering and REPEAT wrapping.
std::array<std::uint8_t, 4> nearest(const Image& image, glm::dvec2 uv) {
    uv -= glm::floor(uv);
    const int x = std::min(int(uv.x * image.width), image.width - 1);
    const int y = std::min(int(uv.y * image.height), image.height - 1);
    std::array<std::uint8_t, 4> out{0, 0, 0, 255};
    for (int c = 0; c < image.channels; ++c) out[size_t(c)] = image.at(x, y, c);
    return out;
}

// KHR_texture_transform: translation x rotation x scale, with the rotation turning the uvs
// counter-clockwise in glTF's uv space (v down): u' = c u + s v, v' = -s u + c v. This is the
// matrix of the extension's sample model and Khronos' viewers; the GLSL listing in the
// extension's README has it transposed, a known erratum (KhronosGroup/glTF issue 1563).
struct UvTransform {
    glm::dvec2 offset{0.0};
    double rotation = 0.0;
    glm::dvec2 scale{1.0};
    glm::dvec2 apply(const glm::dvec2& uv) const {
        const double c = std::cos(rotation), s = std::sin(rotation);
        const glm::dvec2 scaled = uv * scale;
        return offset + glm::dvec2(c * scaled.x + s * scaled.y, -s * scaled.x + c * scaled.y);
    }
    std::string json() const {
        char text[512];
        std::snprintf(text, sizeof text,
                      R"("extensions":{"KHR_texture_transform":{"offset":[%.17g,%.17g],)"
                      R"("rotation":%.17g,"scale":[%.17g,%.17g]}})",
                      offset.x, offset.y, rotation, scale.x, scale.y);
        return text;
    }
};

// The image `transform` shows on uv [0, 1]^2, as a `size` x `size` image without one: each
// texel the texel of `image` its centre maps to (exact when the transform maps these texels
// into single texels of `image`, as the quarter turns, halvings and doublings here do).
Image pretransformed(const Image& image, const UvTransform& transform, int size) {
    Image out{size, size, image.channels, {}};
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const auto texel =
                nearest(image, transform.apply({(x + 0.5) / size, (y + 0.5) / size}));
            out.pixels.insert(out.pixels.end(), texel.begin(), texel.begin() + image.channels);
        }
    }
    return out;
}

TEST(SceneGraph, EachTextureSlotHasItsOwnTransform) {
    const fs::path dir = testOutputDir("scene_graph_texture_transform");
    constexpr int n = 8;
    Image base{n, n, 3, {}}, metalRough{n, n, 3, {}}, emissive{n, n, 3, {}};
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            const bool odd = (x + y) % 2 != 0;
            base.pixels.insert(base.pixels.end(),
                               {std::uint8_t(odd ? 230 : 40 + 20 * x), std::uint8_t(60 + 20 * y),
                                std::uint8_t(odd ? 50 : 200)});
            // glTF: G roughness, B metallic: smooth metal against rough plastic, in stripes
            const bool metal = (x / 2 + 3 * y) % 3 == 0;
            metalRough.pixels.insert(metalRough.pixels.end(), {0, std::uint8_t(metal ? 60 : 230),
                                                               std::uint8_t(metal ? 255 : 0)});
            const bool glows = (x * 5 + y * 3) % 7 == 0;
            emissive.pixels.insert(emissive.pixels.end(), {std::uint8_t(glows ? 255 : 0),
                                                           std::uint8_t(glows ? 120 : 0), 0});
        }
    }
    Image normals = pretransformed(bumpyNormalMap(), {}, n);  // the bumps at 8 x 8
    const std::array<const Image*, 4> images = {&base, &metalRough, &normals, &emissive};
    const std::array<const char*, 4> names = {"base", "metal_rough", "normal", "emissive"};
    const std::array<UvTransform, 4> transforms = {
        UvTransform{{0.25, 0.125}, 0.0, {2.0, 1.0}},
        UvTransform{{0.5, 0.0}, kPi / 2, {1.0, 1.0}},
        // no rotation on the normal texture: its tangent frame would have to turn with it
        UvTransform{{0.0, 0.375}, 0.0, {1.0, 0.5}},
        UvTransform{{0.125, 0.25}, -kPi / 2, {0.5, 2.0}},
    };
    for (size_t i = 0; i < images.size(); ++i) {
        writePng(dir / (std::string(names[i]) + ".png"), *images[i]);
        writePng(dir / (std::string(names[i]) + "_pretransformed.png"),
                 pretransformed(*images[i], transforms[i], 4 * n));
    }
    auto file = [&](const std::string& name, bool transformed) {
        std::string images, slot[4];
        for (size_t i = 0; i < 4; ++i) {
            images += std::string(i ? "," : "") + R"({"uri":")" + names[i] +
                      (transformed ? "" : "_pretransformed") + R"(.png"})";
            slot[i] = R"({"index":)" + std::to_string(i);
            if (transformed) slot[i] += ',' + transforms[i].json();
            slot[i] += "}";
        }
        return writeTextFile(dir, name,
                             R"({"asset":{"version":"2.0"},
"extensionsUsed":["KHR_lights_punctual","KHR_texture_transform"],
"extensions":{"KHR_lights_punctual":{"lights":[
  {"type":"point","intensity":4,"color":[1,0.95,0.9]},{"type":"directional","intensity":1.5}]}},
"images":[)" + images + R"(],
"samplers":[{"magFilter":9728,"minFilter":9728}],
"textures":[{"source":0,"sampler":0},{"source":1,"sampler":0},{"source":2,"sampler":0},
  {"source":3,"sampler":0}],
"materials":[{"pbrMetallicRoughness":{"baseColorTexture":)" +
                                 slot[0] + R"(,"metallicRoughnessTexture":)" + slot[1] +
                                 R"(},"normalTexture":)" + slot[2] + R"(,"emissiveTexture":)" +
                                 slot[3] + R"(,
  "emissiveFactor":[0.6,0.6,0.6]}],
)" + meshBuffersJson({rectangle(1.0f, 1.0f)}) +
                                 R"("meshes":[{"primitives":[)" + meshPrimitiveJson(0, 0) + R"(]}],
"nodes":[{"mesh":0},{"name":"lamp","translation":[0.3,0.2,0.8],
  "extensions":{"KHR_lights_punctual":{"light":0}}},
  {"name":"sun",)" + Trs{{}, lookingAlong({0.3, -0.4, -1.0})}.json() +
                                 R"(,"extensions":{"KHR_lights_punctual":{"light":1}}}],
"scenes":[{"nodes":[0,1,2]}],"scene":0})");
    };
    const fs::path withTransforms = file("transformed.gltf", true);
    const fs::path pretransformedFile = file("pretransformed.gltf", false);
    const glm::vec3 eye(0.0f, 0.0f, 2.8f);
    const glm::ivec2 size(192, 192);
    expectPairAgrees("texture transform per slot", dir, render07(dir, withTransforms, eye, size),
                     render07(dir, pretransformedFile, eye, size),
                     // identical here; NEAREST texel borders, where a rounding of the transform
                     // may pick the next texel, get 0.5 % of the pixels (the plants: 15-69 %)
                     {.channelThreshold = 2, .maxFractionOver = 0.005, .minPsnr = 40.0}, 0.3);
}

// ---- (f) one image, two samplers ----

// Two unlit squares showing one small image magnified, the left through a LINEAR sampler and
// the right through a NEAREST one (the left's material is read first), against the same with
// the right square's image a copy of the file: one texture or two, each keeps its sampler.
TEST(SceneGraph, SharedImageKeepsEachTexturesSampler) {
    const fs::path dir = testOutputDir("scene_graph_shared_image");
    Image texels{4, 4, 3, {}};
    for (int i = 0; i < 16; ++i) {
        texels.pixels.insert(texels.pixels.end(), {std::uint8_t(i * 17), std::uint8_t(255 - i * 13),
                                                   std::uint8_t(i % 2 ? 255 : 0)});
    }
    writePng(dir / "shared.png", texels);
    fs::copy_file(dir / "shared.png", dir / "copy.png", fs::copy_options::overwrite_existing);
    auto file = [&](const std::string& name, const std::string& secondImage) {
        const GltfMeshArrays square = rectangle(0.5f, 0.5f);
        return writeTextFile(dir, name,
                             R"({"asset":{"version":"2.0"},
"extensionsUsed":["KHR_materials_unlit"],
"images":[{"uri":"shared.png"},{"uri":")" +
                                 secondImage + R"("}],
"samplers":[{"magFilter":9729,"minFilter":9729},{"magFilter":9728,"minFilter":9728}],
"textures":[{"source":0,"sampler":0},{"source":)" +
                                 std::string(secondImage == "shared.png" ? "0" : "1") +
                                 R"(,"sampler":1}],
"materials":[
  {"pbrMetallicRoughness":{"baseColorTexture":{"index":0}},"extensions":{"KHR_materials_unlit":{}}},
  {"pbrMetallicRoughness":{"baseColorTexture":{"index":1}},"extensions":{"KHR_materials_unlit":{}}}],
)" + meshBuffersJson({square}) + R"("meshes":[{"primitives":[)" +
                                 meshPrimitiveJson(0, 0) + R"(]},{"primitives":[)" +
                                 meshPrimitiveJson(0, 1) +
                                 R"(]}],
"nodes":[{"mesh":0,"translation":[-0.55,0,0]},{"mesh":1,"translation":[0.55,0,0]}],
"scenes":[{"nodes":[0,1]}],"scene":0})");
    };
    const fs::path shared = file("shared.gltf", "shared.png");
    const fs::path copied = file("copied.gltf", "copy.png");
    // the NEAREST texture reaches the renderer second, after the LINEAR one made the image's
    // texture (Assimp lists materials in the order primitives first name them)
    const Model model = loadModel(shared);
    ASSERT_GE(model.materials.size(), 2u);
    EXPECT_EQ(model.materials[0].baseColorTexture.magFilter, 9729);
    EXPECT_EQ(model.materials[1].baseColorTexture.magFilter, 9728);
    const glm::vec3 eye(0.0f, 0.0f, 2.2f);
    const glm::ivec2 size(160, 120);
    expectPairAgrees("shared image, two samplers", dir, render07(dir, shared, eye, size),
                     render07(dir, copied, eye, size),
                     // identical here (the same pixels through the same path); the lost sampler
                     // moves 23 % of the pixels by up to 186/255
                     {.channelThreshold = 1, .maxFractionOver = 0.001, .minPsnr = 50.0}, 0.3);
}

// ---- (a) again, on a real model: Debian's 2CylinderEngine ----

// A node's local matrix: its "matrix", or translation x rotation x scale.
glm::dmat4 localMatrix(const JsonValue& node) {
    if (const JsonValue* m = node.find("matrix"); m && m->items.size() == 16) {
        glm::dmat4 out;
        for (int i = 0; i < 16; ++i) out[i / 4][i % 4] = m->items[size_t(i)].number;
        return out;
    }
    Trs trs;
    auto read = [&](const char* key, double* to, size_t count) {
        if (const JsonValue* v = node.find(key); v && v->items.size() == count)
            for (size_t i = 0; i < count; ++i) to[i] = v->items[i].number;
    };
    read("translation", &trs.translation.x, 3);
    read("rotation", &trs.rotation.x, 4);
    read("scale", &trs.scale.x, 3);
    return trs.matrix();
}

// The engine (a GLB with a node hierarchy up to several levels deep, turned and moved at each)
// against a .gltf of the same buffer whose nodes are one level: each node with a mesh at the
// root, its matrix the world matrix the test multiplied down the hierarchy (parent x child), in
// the order the hierarchy lists them.
TEST(SceneGraph, TwoCylinderEngineMatchesItsFlattenedHierarchy) {
    PBR_NEED_ASSIMP_MODELS(models);
    const fs::path engine = models / "2CylinderEngine-glTF-Binary" / "2CylinderEngine.glb";
    if (!fs::exists(engine)) GTEST_SKIP() << engine << " is not installed (assimp-testmodels)";
    const fs::path dir = testOutputDir("scene_graph_engine");
    const std::string bytes = readBytes(engine);
    auto document = gltfJson(bytes);
    ASSERT_TRUE(document);
    // the GLB's binary chunk, the second after the 12-byte header and the JSON chunk
    auto word = [&](size_t at) {
        std::uint32_t v = 0;
        std::memcpy(&v, bytes.data() + at, 4);
        return v;
    };
    const size_t binAt = 12 + 8 + word(12);
    ASSERT_LT(binAt + 8, bytes.size());
    ASSERT_EQ(word(binAt + 4), 0x004E4942u);  // "BIN\0"
    {
        std::ofstream bin(dir / "engine.bin", std::ios::binary);
        bin.write(bytes.data() + binAt + 8, std::streamsize(word(binAt)));
        ASSERT_TRUE(bin.flush());
    }
    const JsonValue* nodes = document->find("nodes");
    const JsonValue* scenes = document->find("scenes");
    ASSERT_TRUE(nodes && scenes && !scenes->items.empty());
    const JsonValue* sceneIndex = document->find("scene");
    const JsonValue& scene = scenes->items[sceneIndex ? size_t(sceneIndex->number) : 0];
    std::string flatNodes;
    int flatCount = 0, deepest = 0;
    std::function<void(size_t, const glm::dmat4&, int)> visit =
        [&](size_t index, const glm::dmat4& parent, int depth) {
            const JsonValue& node = nodes->items.at(index);
            const glm::dmat4 world = parent * localMatrix(node);
            deepest = std::max(deepest, depth);
            if (const JsonValue* mesh = node.find("mesh")) {
                flatNodes += std::string(flatCount++ ? ",\n" : "") + R"({"mesh":)" +
                             std::to_string(int(mesh->number)) + R"(,"matrix":)" +
                             matrixJson(world) + "}";
            }
            if (const JsonValue* children = node.find("children"))
                for (const JsonValue& child : children->items)
                    visit(size_t(child.number), world, depth + 1);
        };
    for (const JsonValue& root : scene.find("nodes")->items)
        visit(size_t(root.number), glm::dmat4(1.0), 1);
    std::printf("2CylinderEngine: %d mesh nodes, hierarchy %d levels deep\n", flatCount, deepest);
    ASSERT_GE(deepest, 3);
    // everything but the nodes and scenes as the engine has it; the buffer now a file beside it
    std::string members;
    for (const auto& [key, value] : document->members) {
        if (key == "nodes" || key == "scenes" || key == "scene" || key == "buffers") continue;
        members += "\"" + key + "\":" + jsonText(value) + ",\n";
    }
    std::string sceneList;
    for (int i = 0; i < flatCount; ++i) {
        if (i) sceneList += ",";
        sceneList += std::to_string(i);
    }
    const fs::path flat = writeTextFile(dir, "engine_flat.gltf",
                                        "{" + members + R"("buffers":[{"byteLength":)" +
                                            std::to_string(word(binAt)) +
                                            R"(,"uri":"engine.bin"}],
"nodes":[)" + flatNodes + R"(],
"scenes":[{"nodes":[)" + sceneList + R"(]}],"scene":0})");
    const Model model = loadModel(flat);
    const glm::vec3 centre = 0.5f * (model.boundsMin + model.boundsMax);
    const float radius = 0.5f * glm::length(model.boundsMax - model.boundsMin);
    const glm::vec3 eye = centre + radius * glm::vec3(0.8f, 0.9f, 1.4f);
    const glm::ivec2 size(256, 192);
    expectPairAgrees("2CylinderEngine flattened", dir, render07(dir, engine, eye, size),
                     render07(dir, flat, eye, size), kPairGate, 0.15);
}

}  // namespace
}  // namespace pbr::test
