// The GPU against an independent CPU evaluation of the same BRDF (common/math/brdf.cpp, GLM only).
// For pixels on every sphere of the grid (rendered without MSAA) the ray through the pixel
// centre is intersected with the analytic sphere, the surface is shaded on the CPU at the hit
// point with the analytic normal, and the result must match the rendered pixel within 2/255.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/mesh.h"
#include "math/brdf.h"
#include "reference/grid_scene.h"
#include "support/golden.h"
#include "support/mesh_hit.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

TEST(Reference, Lighting01EverySphereMatchesTheCpuBrdf) {
    const fs::path dir = testOutputDir("reference_01");
    const SampleRender render =
        renderSample("01_lighting", dir / "01_lighting_nomsaa.png", {"--msaa", "0"});
    ASSERT_EQ(render.run.exitCode, 0) << render.run.err;
    const Image image = readImage(render.image, 3);
    ASSERT_EQ(image.width, kWidth);

    const Comparison result =
        compareGrid(image, [&](double x, double y, int row, int col) -> std::optional<glm::dvec3> {
            const auto hit = hitSphere(x, y, row, col);
            if (!hit || hit->ndotv < 0.5) return std::nullopt;
            return toBytes(cpu::shadePointLights(gridSurface(hit->position, hit->normal, row, col),
                                                 glm::vec3(gridCamera()), kGridLights));
        });
    std::printf(
        "compared %d pixels on 49 spheres (skipped %d on steep highlights); worst channel diff "
        "%.0f/255\n",
        result.checked, result.skipped, result.worst);
    EXPECT_GE(result.checked, 49 * 20);
}

// Against the light, at grazing angles. From (0, 0, -23), looking down +Z (yaw 90), the four
// lights at z = 10 stand behind the spheres: what lights the visible side arrives at grazing
// angles, V and L nearly opposed, so the half vector stands almost at right angles to the view
// and Fresnel, (1 - VdotH)^5, is near its steep end. The CPU shades the sphere the GPU draws:
// the ray meets the very triangles of the 64 x 64 sphere and the vertex normals are interpolated
// at the hit (support/mesh_hit.h), so the rims are compared too, down to NdotV 0.02.
TEST(Reference, Lighting01AgainstTheLightAtGrazingAngles) {
    const fs::path dir = testOutputDir("reference_01_grazing");
    const SampleRender render = renderSample("01_lighting", dir / "01_from_behind.png",
                                             {"--msaa", "0", "--camera", "0,0,-23,90,0"});
    ASSERT_EQ(render.run.exitCode, 0) << render.run.err;
    const Image image = readImage(render.image, 3);
    ASSERT_EQ(image.width, kWidth);

    const glm::dvec3 camera(0.0, 0.0, -23.0), front(0.0, 0.0, 1.0);
    const MeshData sphere = uvSphere(64, 64);
    auto predict = [&](double x, double y, int row, int col) -> std::optional<glm::dvec3> {
        const glm::dvec3 ray = cameraRay(front, kFovY, kWidth, kHeight, x, y);
        const glm::dmat4 model = glm::translate(glm::dmat4(1.0), sphereCentre(row, col));
        const auto hit = hitUvSphere(sphere, 64, 64, model, camera, ray);
        if (!hit) return std::nullopt;
        return toBytes(cpu::shadePointLights(gridSurface(hit->position, hit->normal, row, col),
                                             glm::vec3(camera), kGridLights));
    };
    int checked = 0, grazing = 0, grazingLit = 0, skipped = 0;
    double worst = 0.0;
    for (int row = 0; row < 7; ++row) {
        for (int col = 0; col < 7; ++col) {
            // The sphere's box on screen, from its centre's projection (x mirrored: the camera
            // looks down +Z, so +X is to the left).
            const glm::dvec3 c = sphereCentre(row, col);
            const double t = std::tan(kFovY / 2.0), depth = c.z - camera.z;
            const double cx = (-c.x / (depth * t * kWidth / kHeight) + 1.0) / 2.0 * kWidth;
            const double cy = (1.0 - c.y / (depth * t)) / 2.0 * kHeight;
            const double radius = kHeight / (2.0 * depth * t) * 1.1;
            for (int py = int(cy - radius); py <= int(cy + radius); ++py) {
                for (int px = int(cx - radius); px <= int(cx + radius); ++px) {
                    const auto expected = predict(px + 0.5, py + 0.5, row, col);
                    if (!expected) continue;
                    bool steady = true;  // not on a pin-point highlight or the very silhouette
                    for (auto [ox, oy] :
                         {std::pair{0.25, 0.0}, {-0.25, 0.0}, {0.0, 0.25}, {0.0, -0.25}}) {
                        const auto near = predict(px + 0.5 + ox, py + 0.5 + oy, row, col);
                        if (!near || glm::length(*near - *expected) > 1.0) steady = false;
                    }
                    if (!steady) {
                        ++skipped;
                        continue;
                    }
                    const glm::dvec3 ray =
                        cameraRay(front, kFovY, kWidth, kHeight, px + 0.5, py + 0.5);
                    const auto hit = hitUvSphere(sphere, 64, 64, glm::translate(glm::dmat4(1.0), c),
                                                 camera, ray);
                    const double NdotV = -glm::dot(hit->normal, ray);
                    double diff = 0.0;
                    for (int ch = 0; ch < 3; ++ch) {
                        diff = std::max(diff, std::abs(double(image.at(px, py, ch)) -
                                                       std::round((*expected)[ch])));
                    }
                    worst = std::max(worst, diff);
                    EXPECT_LE(diff, 2.0) << "sphere row " << row << " col " << col << " pixel ("
                                         << px << ", " << py << "), NdotV " << NdotV;
                    ++checked;
                    if (NdotV < 0.3) {
                        ++grazing;
                        if (expected->r > 40.0) ++grazingLit;
                    }
                }
            }
        }
    }
    std::printf(
        "from behind: compared %d pixels (%d with NdotV < 0.3, %d of them lit), skipped "
        "%d; worst channel diff %.0f/255\n",
        checked, grazing, grazingLit, skipped, worst);
    EXPECT_GE(grazing, 5000);
    EXPECT_GE(grazingLit, 1000);  // the lights reach the rims: the test sees grazing Fresnel
}

// 02 with texel lookups: a 64 x 64 material of random texels (randomTexels), drawn with nearest
// filtering (--filter nearest: mip level 0, one texel a pixel), so the CPU can read the very texel
// the GPU reads at the hit point's uv.
TEST(Reference, LightingTextured02MatchesTheCpuBrdfWithTexels) {
    const fs::path dir = testOutputDir("reference_02");
    const TexelMaterial material = randomTexels();
    const fs::path set = writeTexelMaterial(material, dir / "random_texels");

    const SampleRender render =
        renderSample("02_lighting_textured", dir / "02_nearest.png",
                     {"--msaa", "0", "--filter", "nearest", "--material-dir", set.string(),
                      "--camera", "0,0,23"});  // the whole grid (02 starts closer)
    ASSERT_EQ(render.run.exitCode, 0) << render.run.err;
    const Image image = readImage(render.image, 3);

    const Comparison result =
        compareGrid(image, [&](double x, double y, int row, int col) -> std::optional<glm::dvec3> {
            const auto hit = hitSphere(x, y, row, col);
            if (!hit || hit->ndotv < 0.5) return std::nullopt;
            const auto surface = texelSurface(material, *hit);
            if (!surface) return std::nullopt;
            return toBytes(cpu::shadePointLights(*surface, glm::vec3(gridCamera()),
                                                 std::span(&kTexturedGridLight, 1)));
        });
    std::printf("compared %d pixels on 49 spheres (skipped %d); worst channel diff %.0f/255\n",
                result.checked, result.skipped, result.worst);
    EXPECT_GE(result.checked, 49 * 20);
}

}  // namespace
}  // namespace pbr::test
