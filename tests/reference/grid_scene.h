#pragma once
// The sphere grid of samples 01, 02, 04 and 05, from SAMPLES.md (not from the samples' code), for
// the reference tests that compare its pixels with the CPU: a 7 x 7 grid of unit spheres 2.5
// apart in the plane z = gridZ (0 in 01 and 02, -2 in 04 and 05), seen from 23 in front of it
// at 1280 x 720 with a vertical field of view of 45 degrees, lit by four point lights.
#include <array>
#include <functional>
#include <numbers>
#include <optional>

#include <glm/glm.hpp>

#include "math/brdf.h"
#include "support/golden.h"

namespace pbr::test {

inline constexpr int kWidth = 1280, kHeight = 720;
inline constexpr double kFovY = 45.0 * std::numbers::pi / 180.0;

// A picture of the grid: its size (--size; 1280 x 720 by default) and the grid's plane z = gridZ.
struct GridFrame {
    int width = kWidth, height = kHeight;
    double gridZ = 0.0;
};

// The camera of a grid in the plane z = gridZ: 23 in front of it, looking down -Z (yaw -90).
inline glm::dvec3 gridCamera(double gridZ = 0.0) {
    return {0.0, 0.0, gridZ + 23.0};
}
glm::dvec3 sphereCentre(int row, int col, double gridZ = 0.0);

struct Hit {
    glm::dvec3 position, normal;
    double ndotv;
};
// The ray through image point (x right, y down, in pixels; +0.5 is a pixel centre) against the
// analytic unit sphere of grid cell (row, col).
std::optional<Hit> hitSphere(double x, double y, int row, int col, const GridFrame& frame = {});

// What the CPU predicts (0..255 per channel) at an image point on sphere (row, col); nullopt
// where the point must not be compared (off the sphere, near the rim, or ambiguous).
using Predictor = std::function<std::optional<glm::dvec3>(double x, double y, int row, int col)>;

struct Comparison {
    int checked = 0, skipped = 0, failed = 0;
    double worst = 0.0;
};
// Walks a grid of pixels around each sphere's centre (13 x 13, 4 pixels apart at 1280 x 720,
// closer in a smaller picture) and compares those the predictor accepts
// and whose prediction is steady a quarter pixel (of 1280 x 720) away (not on a pin-point highlight, where the
// tessellated sphere's normal cannot match the analytic one): every channel within 2/255.
// Reports the first few pixels off and fails the test when any is.
Comparison compareGrid(const Image& image, const Predictor& predict);  // at the image's size

// Sample 01's lights (04 and 05 keep them), from SAMPLES.md.
inline const std::array<cpu::PointLight, 4> kGridLights = {{
    {{-10.0f, 10.0f, 10.0f}, {300.0f, 300.0f, 300.0f}},
    {{10.0f, 10.0f, 10.0f}, {300.0f, 300.0f, 300.0f}},
    {{-10.0f, -10.0f, 10.0f}, {300.0f, 300.0f, 300.0f}},
    {{10.0f, -10.0f, 10.0f}, {300.0f, 300.0f, 300.0f}},
}};

// The material of sphere (row, col): albedo (0.5, 0, 0), metallic row / 7, roughness col / 7
// kept at 0.05 or above, ao 1.
cpu::SurfacePoint gridSurface(const glm::dvec3& position, const glm::dvec3& normal, int row,
                              int col);

// Reinhard and gamma, as 0..255.
glm::dvec3 toBytes(const glm::vec3& linear);

// Sample 02's one light, from SAMPLES.md.
inline const cpu::PointLight kTexturedGridLight{{0.0f, 0.0f, 10.0f}, {150.0f, 150.0f, 150.0f}};

// A material folder of 64 x 64 random texels in plausible ranges, for 02 drawn with nearest
// filtering (--filter nearest: mip level 0, one texel a pixel), so that the CPU can read the very
// texel the GPU reads.
struct TexelMaterial {
    Image albedo, normal, metallic, roughness, ao;
};
TexelMaterial randomTexels();
// Writes the five maps into `dir` (made), and returns it.
std::filesystem::path writeTexelMaterial(const TexelMaterial& material,
                                         const std::filesystem::path& dir);
// The surface at a hit on a grid sphere as 02 reads it from `material`: the texel at the analytic
// sphere's uv, the normal map in the mesh's tangent frame. nullopt within 0.15 texel of a texel
// edge, where the tessellated sphere's interpolated uv may fall in the neighbouring texel.
std::optional<cpu::SurfacePoint> texelSurface(const TexelMaterial& material, const Hit& hit);

}  // namespace pbr::test
