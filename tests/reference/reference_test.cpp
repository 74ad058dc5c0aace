// The GPU against an independent CPU evaluation of the same BRDF (common/brdf.cpp, GLM only).
// For pixels on every sphere of sample 01 (rendered without MSAA) the ray through the pixel
// centre is intersected with the analytic sphere, the surface is shaded on the CPU at the hit
// point with the analytic normal, and the result must match the rendered pixel within 2/255.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>

#include "brdf.h"
#include "support/golden.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

// The scene of sample 01, from SAMPLES.md (not from the sample's code).
constexpr int kWidth = 1280, kHeight = 720;
constexpr double kFovY = 45.0 * M_PI / 180.0;
const glm::dvec3 kCamera(0.0, 0.0, 23.0);  // the default camera, yaw -90 (looking down -Z)
const std::array<cpu::PointLight, 4> kLights = {{
    {{-10.0f, 10.0f, 10.0f}, {300.0f, 300.0f, 300.0f}},
    {{10.0f, 10.0f, 10.0f}, {300.0f, 300.0f, 300.0f}},
    {{-10.0f, -10.0f, 10.0f}, {300.0f, 300.0f, 300.0f}},
    {{10.0f, -10.0f, 10.0f}, {300.0f, 300.0f, 300.0f}},
}};

glm::dvec3 sphereCentre(int row, int col) {
    return {(col - 3) * 2.5, (row - 3) * 2.5, 0.0};
}

// Ray through a point of the image (x right, y down, in pixels; +0.5 is a pixel centre).
glm::dvec3 rayDirection(double x, double y) {
    const double ndcX = 2.0 * x / kWidth - 1.0;
    const double ndcY = 1.0 - 2.0 * y / kHeight;
    const double t = std::tan(kFovY / 2.0);
    return glm::normalize(glm::dvec3(ndcX * t * kWidth / kHeight, ndcY * t, -1.0));
}

// The 8-bit colour the CPU predicts for image point (x, y) on sphere (row, col), if the ray hits.
std::optional<glm::dvec3> predict(double x, double y, int row, int col, double* ndotv = nullptr) {
    const glm::dvec3 dir = rayDirection(x, y);
    const glm::dvec3 oc = kCamera - sphereCentre(row, col);
    const double b = glm::dot(oc, dir);
    const double disc = b * b - (glm::dot(oc, oc) - 1.0);
    if (disc <= 0.0) return std::nullopt;
    const glm::dvec3 hit = kCamera + (-b - std::sqrt(disc)) * dir;
    const glm::dvec3 normal = glm::normalize(hit - sphereCentre(row, col));
    if (ndotv) *ndotv = -glm::dot(normal, dir);
    cpu::SurfacePoint surface;
    surface.position = glm::vec3(hit);
    surface.normal = glm::vec3(normal);
    surface.albedo = {0.5f, 0.0f, 0.0f};
    surface.metallic = float(row) / 7.0f;
    surface.roughness = std::clamp(float(col) / 7.0f, 0.05f, 1.0f);
    surface.ao = 1.0f;
    const glm::vec3 color =
        cpu::reinhardGamma(cpu::shadePointLights(surface, glm::vec3(kCamera), kLights));
    return glm::dvec3(color) * 255.0;
}

TEST(Reference, EverySphereMatchesTheCpuBrdf) {
    const fs::path dir = testOutputDir("reference_01");
    const SampleRender render =
        renderSample("01_lighting", dir / "01_lighting_nomsaa.png", {"--msaa", "0"});
    ASSERT_EQ(render.run.exitCode, 0) << render.run.err;
    const Image image = readImage(render.image, 3);
    ASSERT_EQ(image.width, kWidth);
    ASSERT_EQ(image.height, kHeight);

    int checked = 0, skippedSteep = 0;
    double worst = 0.0;
    for (int row = 0; row < 7; ++row) {
        for (int col = 0; col < 7; ++col) {
            // The sphere's centre in the image, and a grid of pixels around it.
            const glm::dvec3 c = sphereCentre(row, col);
            const double t = std::tan(kFovY / 2.0);
            const double cx = (c.x / (kCamera.z * t * kWidth / kHeight) + 1.0) / 2.0 * kWidth;
            const double cy = (1.0 - c.y / (kCamera.z * t)) / 2.0 * kHeight;
            int checkedHere = 0;
            for (int dy = -24; dy <= 24; dy += 6) {
                for (int dx = -24; dx <= 24; dx += 6) {
                    const int px = int(std::floor(cx)) + dx, py = int(std::floor(cy)) + dy;
                    double ndotv = 0.0;
                    const auto expected = predict(px + 0.5, py + 0.5, row, col, &ndotv);
                    if (!expected || ndotv < 0.5) continue;  // off the sphere or near its rim
                    // Compare only where the shading is smooth at pixel scale: a quarter pixel
                    // away it must change by less than one level (not on a pin-point highlight,
                    // where the tessellated sphere's normal cannot match the analytic one).
                    bool smooth = true;
                    for (auto [ox, oy] :
                         {std::pair{0.25, 0.0}, {-0.25, 0.0}, {0.0, 0.25}, {0.0, -0.25}}) {
                        const auto near = predict(px + 0.5 + ox, py + 0.5 + oy, row, col);
                        if (!near || glm::length(*near - *expected) > 1.0) smooth = false;
                    }
                    if (!smooth) {
                        ++skippedSteep;
                        continue;
                    }
                    for (int ch = 0; ch < 3; ++ch) {
                        const double rendered = image.at(px, py, ch);
                        const double diff = std::abs(rendered - std::round((*expected)[ch]));
                        worst = std::max(worst, diff);
                        EXPECT_LE(diff, 2.0)
                            << "sphere row " << row << " col " << col << " pixel (" << px << ", "
                            << py << ") channel " << ch << ": rendered " << rendered << ", CPU "
                            << (*expected)[ch];
                    }
                    ++checkedHere;
                }
            }
            EXPECT_GE(checkedHere, 1)
                << "no comparable pixel on sphere row " << row << " col " << col;
            checked += checkedHere;
        }
    }
    std::printf(
        "compared %d pixels on 49 spheres (skipped %d on steep highlights); worst channel diff "
        "%.0f/255\n",
        checked, skippedSteep, worst);
    EXPECT_GE(checked, 49 * 20);
}

}  // namespace
}  // namespace pbr::test
