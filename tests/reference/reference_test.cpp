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
#include "support/golden.h"
#include "support/mesh_hit.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

// The grid scene of samples 01 and 02, from SAMPLES.md (not from the samples' code).
constexpr int kWidth = 1280, kHeight = 720;
constexpr double kFovY = 45.0 * std::numbers::pi / 180.0;
const glm::dvec3 kCamera(0.0, 0.0, 23.0);  // the default camera, yaw -90 (looking down -Z)

glm::dvec3 sphereCentre(int row, int col) {
    return {(col - 3) * 2.5, (row - 3) * 2.5, 0.0};
}

struct Hit {
    glm::dvec3 position, normal;
    double ndotv;
};

// The ray through image point (x right, y down, in pixels; +0.5 is a pixel centre) against the
// unit sphere of grid cell (row, col).
std::optional<Hit> hitSphere(double x, double y, int row, int col) {
    const double t = std::tan(kFovY / 2.0);
    const glm::dvec3 dir = glm::normalize(glm::dvec3(
        (2.0 * x / kWidth - 1.0) * t * kWidth / kHeight, (1.0 - 2.0 * y / kHeight) * t, -1.0));
    const glm::dvec3 oc = kCamera - sphereCentre(row, col);
    const double b = glm::dot(oc, dir);
    const double disc = b * b - (glm::dot(oc, oc) - 1.0);
    if (disc <= 0.0) return std::nullopt;
    Hit hit;
    hit.position = kCamera + (-b - std::sqrt(disc)) * dir;
    hit.normal = glm::normalize(hit.position - sphereCentre(row, col));
    hit.ndotv = -glm::dot(hit.normal, dir);
    return hit;
}

// What the CPU predicts (0..255 per channel) at an image point on sphere (row, col); nullopt
// where the point must not be compared (off the sphere, near the rim, or ambiguous).
using Predictor = std::function<std::optional<glm::dvec3>(double x, double y, int row, int col)>;

struct Comparison {
    int checked = 0, skipped = 0, failed = 0;
    double worst = 0.0;
};

// Walks a grid of pixels around each sphere's centre and compares those the predictor accepts
// and whose prediction is steady a quarter pixel away (not on a pin-point highlight, where the
// tessellated sphere's normal cannot match the analytic one).
Comparison compareGrid(const Image& image, const Predictor& predict) {
    Comparison result;
    const double t = std::tan(kFovY / 2.0);
    for (int row = 0; row < 7; ++row) {
        for (int col = 0; col < 7; ++col) {
            const glm::dvec3 c = sphereCentre(row, col);
            const double cx = (c.x / (kCamera.z * t * kWidth / kHeight) + 1.0) / 2.0 * kWidth;
            const double cy = (1.0 - c.y / (kCamera.z * t)) / 2.0 * kHeight;
            int checkedHere = 0;
            for (int dy = -24; dy <= 24; dy += 4) {
                for (int dx = -24; dx <= 24; dx += 4) {
                    const int px = int(std::floor(cx)) + dx, py = int(std::floor(cy)) + dy;
                    const auto expected = predict(px + 0.5, py + 0.5, row, col);
                    if (!expected) continue;
                    bool steady = true;
                    for (auto [ox, oy] :
                         {std::pair{0.25, 0.0}, {-0.25, 0.0}, {0.0, 0.25}, {0.0, -0.25}}) {
                        const auto near = predict(px + 0.5 + ox, py + 0.5 + oy, row, col);
                        if (!near || glm::length(*near - *expected) > 1.0) steady = false;
                    }
                    if (!steady) {
                        ++result.skipped;
                        continue;
                    }
                    for (int ch = 0; ch < 3; ++ch) {
                        const double rendered = image.at(px, py, ch);
                        const double diff = std::abs(rendered - std::round((*expected)[ch]));
                        result.worst = std::max(result.worst, diff);
                        // the first few pixels off say where; the count says how many
                        if (diff > 2.0 && ++result.failed <= 5) {
                            ADD_FAILURE() << "sphere row " << row << " col " << col << " pixel ("
                                          << px << ", " << py << ") channel " << ch
                                          << ": rendered " << rendered << ", CPU "
                                          << (*expected)[ch];
                        }
                    }
                    ++checkedHere;
                }
            }
            EXPECT_GE(checkedHere, 1)
                << "no comparable pixel on sphere row " << row << " col " << col;
            result.checked += checkedHere;
        }
    }
    EXPECT_EQ(result.failed, 0) << "channels off by more than 2/255";
    return result;
}

// Sample 01's lights and the material of its sphere (row, col), from SAMPLES.md.
const std::array<cpu::PointLight, 4> kGridLights = {{
    {{-10.0f, 10.0f, 10.0f}, {300.0f, 300.0f, 300.0f}},
    {{10.0f, 10.0f, 10.0f}, {300.0f, 300.0f, 300.0f}},
    {{-10.0f, -10.0f, 10.0f}, {300.0f, 300.0f, 300.0f}},
    {{10.0f, -10.0f, 10.0f}, {300.0f, 300.0f, 300.0f}},
}};

cpu::SurfacePoint gridSurface(const glm::dvec3& position, const glm::dvec3& normal, int row,
                              int col) {
    cpu::SurfacePoint surface;
    surface.position = glm::vec3(position);
    surface.normal = glm::vec3(normal);
    surface.albedo = {0.5f, 0.0f, 0.0f};
    surface.metallic = float(row) / 7.0f;
    surface.roughness = std::clamp(float(col) / 7.0f, 0.05f, 1.0f);
    surface.ao = 1.0f;
    return surface;
}

glm::dvec3 toBytes(const glm::vec3& linear) {
    return glm::dvec3(cpu::reinhardGamma(linear)) * 255.0;
}

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
                                                 glm::vec3(kCamera), kGridLights));
        });
    std::printf(
        "compared %d pixels on 49 spheres (skipped %d on steep highlights); worst channel diff "
        "%.0f/255\n",
        result.checked, result.skipped, result.worst);
    EXPECT_GE(result.checked, 49 * 20);
}

// 01's term views (--view NAME) against the CPU, each by its definition in 01's README: the
// inputs as they are (the normal as 0.5 + 0.5 N), a light-dependent term summed over the lights
// above the horizon (NdotL > 0) and shown as x / (1 + x), the direct light alone through the
// picture's Reinhard and gamma. The terms come from the CPU mirror (cpu::cookTorrance); which
// term, which lights, which channel and which encoding each view shows is this test's reading.
glm::dvec3 lighting01View(const std::string& view, const cpu::SurfacePoint& s,
                          const glm::vec3& camera) {
    const glm::vec3 N = s.normal, V = glm::normalize(camera - s.position);
    if (view == "albedo") return glm::dvec3(s.albedo);
    if (view == "normal") return 0.5 + 0.5 * glm::dvec3(N);
    if (view == "metallic") return glm::dvec3(s.metallic);
    if (view == "roughness") return glm::dvec3(s.roughness);
    if (view == "ao") return glm::dvec3(s.ao);
    if (view == "f0") return glm::dvec3(glm::mix(glm::vec3(0.04f), s.albedo, s.metallic));
    glm::dvec3 sum(0.0), direct(0.0);
    for (const cpu::PointLight& light : kGridLights) {
        const glm::vec3 L = glm::normalize(light.position - s.position);
        const float distance = glm::length(light.position - s.position);
        direct += glm::dvec3(cpu::directLight(N, V, L, light.color / (distance * distance),
                                              s.albedo, s.metallic, s.roughness));
        if (glm::dot(N, L) <= 0.0f) continue;
        const cpu::CookTorrance t = cpu::cookTorrance(N, V, L, s.albedo, s.metallic, s.roughness);
        if (view == "d") sum += glm::dvec3(t.D);
        if (view == "g") sum += glm::dvec3(t.G);
        if (view == "f") sum += glm::dvec3(t.F);
        if (view == "specular") sum += glm::dvec3(t.specular);
        if (view == "diffuse") sum += glm::dvec3(t.kD * s.albedo / std::numbers::pi_v<float>);
        if (view == "ndotl") sum += glm::dvec3(t.NdotL);
    }
    if (view == "direct") return glm::dvec3(cpu::reinhardGamma(glm::vec3(direct)));
    return sum / (1.0 + sum);
}

TEST(Reference, Lighting01TermViewsMatchTheCpu) {
    const fs::path dir = testOutputDir("reference_01_views");
    for (const char* view : {"albedo", "normal", "metallic", "roughness", "ao", "f0", "d", "g",
                             "f", "specular", "diffuse", "ndotl", "direct"}) {
        SCOPED_TRACE(std::string("--view ") + view);
        const SampleRender render = renderSample(
            "01_lighting", dir / (std::string(view) + ".png"), {"--msaa", "0", "--view", view});
        ASSERT_EQ(render.run.exitCode, 0) << render.run.err;
        const Image image = readImage(render.image, 3);
        ASSERT_EQ(image.width, kWidth);
        const Comparison result = compareGrid(
            image, [&](double x, double y, int row, int col) -> std::optional<glm::dvec3> {
                const auto hit = hitSphere(x, y, row, col);
                if (!hit || hit->ndotv < 0.5) return std::nullopt;
                return 255.0 * lighting01View(view,
                                              gridSurface(hit->position, hit->normal, row, col),
                                              glm::vec3(kCamera));
            });
        std::printf("--view %s: compared %d pixels (skipped %d); worst channel diff %.0f/255\n",
                    view, result.checked, result.skipped, result.worst);
        EXPECT_GE(result.checked, 49 * 20);
    }
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

// 02 with texel lookups: a 64 x 64 material of random texels, drawn with nearest filtering
// (--filter nearest: mip level 0, one texel a pixel), so the CPU can read the very texel the GPU
// reads at the hit point's uv. Pixels whose uv lies within 0.15 texel of a texel edge are not
// compared: there the tessellated sphere's interpolated uv may fall in the neighbouring texel.
TEST(Reference, LightingTextured02MatchesTheCpuBrdfWithTexels) {
    const fs::path dir = testOutputDir("reference_02");
    constexpr int kTexels = 64;
    // random texels in plausible ranges
    auto random = [](int x, int y, int channel) {
        std::uint32_t h = std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u ^
                          std::uint32_t(channel) * 83492791u;
        h ^= h >> 13;
        h *= 0x5bd1e995u;
        h ^= h >> 15;
        return float(h & 0xffff) / 65535.0f;
    };
    Image albedo{kTexels, kTexels, 3, {}}, normal{kTexels, kTexels, 3, {}},
        metallic{kTexels, kTexels, 1, {}}, roughness{kTexels, kTexels, 1, {}},
        ao{kTexels, kTexels, 1, {}};
    for (int y = 0; y < kTexels; ++y) {
        for (int x = 0; x < kTexels; ++x) {
            for (int c = 0; c < 3; ++c)
                albedo.pixels.push_back(std::uint8_t(40 + 200 * random(x, y, c)));
            const glm::vec3 n = glm::normalize(
                glm::vec3(0.5f * random(x, y, 3) - 0.25f, 0.5f * random(x, y, 4) - 0.25f, 1.0f));
            for (int c = 0; c < 3; ++c)
                normal.pixels.push_back(std::uint8_t(std::lround((n[c] * 0.5f + 0.5f) * 255.0f)));
            metallic.pixels.push_back(std::uint8_t(255 * random(x, y, 5)));
            roughness.pixels.push_back(std::uint8_t(50 + 205 * random(x, y, 6)));
            ao.pixels.push_back(std::uint8_t(128 + 127 * random(x, y, 7)));
        }
    }
    const fs::path set = dir / "random_texels";
    fs::create_directory(set);
    writePng(set / "albedo.png", albedo);
    writePng(set / "normal.png", normal);
    writePng(set / "metallic.png", metallic);
    writePng(set / "roughness.png", roughness);
    writePng(set / "ao.png", ao);

    const SampleRender render =
        renderSample("02_lighting_textured", dir / "02_nearest.png",
                     {"--msaa", "0", "--filter", "nearest", "--material-dir", set.string()});
    ASSERT_EQ(render.run.exitCode, 0) << render.run.err;
    const Image image = readImage(render.image, 3);

    auto linearOf = [](std::uint8_t byte) { return float(srgbToLinear(byte / 255.0)); };
    const cpu::PointLight light{{0.0f, 0.0f, 10.0f}, {150.0f, 150.0f, 150.0f}};
    const Comparison result =
        compareGrid(image, [&](double x, double y, int row, int col) -> std::optional<glm::dvec3> {
            const auto hit = hitSphere(x, y, row, col);
            if (!hit || hit->ndotv < 0.5) return std::nullopt;
            // uv of the analytic sphere, as the mesh defines it: u around from +X towards +Z, v
            // from the north pole
            const glm::dvec3 n = hit->normal;
            double phi = std::atan2(n.z, n.x);
            if (phi < 0.0) phi += 2.0 * M_PI;
            const double u = phi / (2.0 * M_PI), v = std::acos(std::clamp(n.y, -1.0, 1.0)) / M_PI;
            const double tx = u * kTexels, ty = v * kTexels;
            const double fx = tx - std::floor(tx), fy = ty - std::floor(ty);
            if (fx < 0.15 || fx > 0.85 || fy < 0.15 || fy > 0.85) return std::nullopt;
            const int texelX = int(tx) % kTexels, texelY = std::min(int(ty), kTexels - 1);

            // tangent frame: T along +u, B = w * cross(N, T) with w = -1 (towards the image's top)
            const glm::vec3 N = glm::vec3(n);
            const glm::vec3 T =
                glm::normalize(glm::vec3(float(-std::sin(phi)), 0.0f, float(std::cos(phi))));
            const glm::vec3 B = -glm::cross(N, T);
            const glm::vec3 tangentNormal(normal.at(texelX, texelY, 0) / 255.0f * 2.0f - 1.0f,
                                          normal.at(texelX, texelY, 1) / 255.0f * 2.0f - 1.0f,
                                          normal.at(texelX, texelY, 2) / 255.0f * 2.0f - 1.0f);
            cpu::SurfacePoint surface;
            surface.position = glm::vec3(hit->position);
            surface.normal =
                glm::normalize(T * tangentNormal.x + B * tangentNormal.y + N * tangentNormal.z);
            surface.albedo = {linearOf(albedo.at(texelX, texelY, 0)),
                              linearOf(albedo.at(texelX, texelY, 1)),
                              linearOf(albedo.at(texelX, texelY, 2))};
            surface.metallic = metallic.at(texelX, texelY, 0) / 255.0f;
            surface.roughness = roughness.at(texelX, texelY, 0) / 255.0f;
            surface.ao = float(ao.at(texelX, texelY, 0)) / 255.0f;  // occlusion is linear
            return toBytes(
                cpu::shadePointLights(surface, glm::vec3(kCamera), std::span(&light, 1)));
        });
    std::printf("compared %d pixels on 49 spheres (skipped %d); worst channel diff %.0f/255\n",
                result.checked, result.skipped, result.worst);
    EXPECT_GE(result.checked, 49 * 20);
}

}  // namespace
}  // namespace pbr::test
