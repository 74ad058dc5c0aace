#include "reference/grid_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include <gtest/gtest.h>

namespace pbr::test {

glm::dvec3 sphereCentre(int row, int col, double gridZ) {
    return {(col - 3) * 2.5, (row - 3) * 2.5, gridZ};
}

std::optional<Hit> hitSphere(double x, double y, int row, int col, const GridFrame& frame) {
    const double t = std::tan(kFovY / 2.0), w = frame.width, h = frame.height;
    const glm::dvec3 dir = glm::normalize(
        glm::dvec3((2.0 * x / w - 1.0) * t * w / h, (1.0 - 2.0 * y / h) * t, -1.0));
    const glm::dvec3 camera = gridCamera(frame.gridZ);
    const glm::dvec3 oc = camera - sphereCentre(row, col, frame.gridZ);
    const double b = glm::dot(oc, dir);
    const double disc = b * b - (glm::dot(oc, oc) - 1.0);
    if (disc <= 0.0) return std::nullopt;
    Hit hit;
    hit.position = camera + (-b - std::sqrt(disc)) * dir;
    hit.normal = glm::normalize(hit.position - sphereCentre(row, col, frame.gridZ));
    hit.ndotv = -glm::dot(hit.normal, dir);
    return hit;
}

Comparison compareGrid(const Image& image, const Predictor& predict) {
    Comparison result;
    const double t = std::tan(kFovY / 2.0), distance = 23.0;  // every grid is 23 from its camera
    const double w = image.width, h = image.height;
    const int step = std::max(1, 4 * image.width / kWidth), reach = 6 * step;
    const double nudge = 0.25 * w / kWidth;  // a quarter of a pixel of 1280 x 720
    for (int row = 0; row < 7; ++row) {
        for (int col = 0; col < 7; ++col) {
            const glm::dvec3 c = sphereCentre(row, col);
            const double cx = (c.x / (distance * t * w / h) + 1.0) / 2.0 * w;
            const double cy = (1.0 - c.y / (distance * t)) / 2.0 * h;
            int checkedHere = 0;
            for (int dy = -reach; dy <= reach; dy += step) {
                for (int dx = -reach; dx <= reach; dx += step) {
                    const int px = int(std::floor(cx)) + dx, py = int(std::floor(cy)) + dy;
                    const auto expected = predict(px + 0.5, py + 0.5, row, col);
                    if (!expected) continue;
                    bool steady = true;
                    for (auto [ox, oy] : {std::pair{nudge, 0.0}, {-nudge, 0.0}, {0.0, nudge},
                                          {0.0, -nudge}}) {
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

TexelMaterial randomTexels() {
    constexpr int kTexels = 64;
    auto random = [](int x, int y, int channel) {
        std::uint32_t h = std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u ^
                          std::uint32_t(channel) * 83492791u;
        h ^= h >> 13;
        h *= 0x5bd1e995u;
        h ^= h >> 15;
        return float(h & 0xffff) / 65535.0f;
    };
    TexelMaterial m{{kTexels, kTexels, 3, {}},
                    {kTexels, kTexels, 3, {}},
                    {kTexels, kTexels, 1, {}},
                    {kTexels, kTexels, 1, {}},
                    {kTexels, kTexels, 1, {}}};
    for (int y = 0; y < kTexels; ++y) {
        for (int x = 0; x < kTexels; ++x) {
            for (int c = 0; c < 3; ++c)
                m.albedo.pixels.push_back(std::uint8_t(40 + 200 * random(x, y, c)));
            const glm::vec3 n = glm::normalize(
                glm::vec3(0.5f * random(x, y, 3) - 0.25f, 0.5f * random(x, y, 4) - 0.25f, 1.0f));
            for (int c = 0; c < 3; ++c)
                m.normal.pixels.push_back(
                    std::uint8_t(std::lround((n[c] * 0.5f + 0.5f) * 255.0f)));
            m.metallic.pixels.push_back(std::uint8_t(255 * random(x, y, 5)));
            m.roughness.pixels.push_back(std::uint8_t(50 + 205 * random(x, y, 6)));
            m.ao.pixels.push_back(std::uint8_t(128 + 127 * random(x, y, 7)));
        }
    }
    return m;
}

std::filesystem::path writeTexelMaterial(const TexelMaterial& material,
                                         const std::filesystem::path& dir) {
    std::filesystem::create_directories(dir);
    writePng(dir / "albedo.png", material.albedo);
    writePng(dir / "normal.png", material.normal);
    writePng(dir / "metallic.png", material.metallic);
    writePng(dir / "roughness.png", material.roughness);
    writePng(dir / "ao.png", material.ao);
    return dir;
}

std::optional<cpu::SurfacePoint> texelSurface(const TexelMaterial& material, const Hit& hit) {
    const int texels = material.albedo.width;
    // uv of the analytic sphere, as the mesh defines it: u around from +X towards +Z, v from the
    // north pole
    const glm::dvec3 n = hit.normal;
    double phi = std::atan2(n.z, n.x);
    if (phi < 0.0) phi += 2.0 * std::numbers::pi;
    const double u = phi / (2.0 * std::numbers::pi);
    const double v = std::acos(std::clamp(n.y, -1.0, 1.0)) / std::numbers::pi;
    const double tx = u * texels, ty = v * texels;
    const double fx = tx - std::floor(tx), fy = ty - std::floor(ty);
    if (fx < 0.15 || fx > 0.85 || fy < 0.15 || fy > 0.85) return std::nullopt;
    const int x = int(tx) % texels, y = std::min(int(ty), texels - 1);

    // tangent frame: T along +u, B = w * cross(N, T) with w = -1 (towards the image's top)
    const glm::vec3 N = glm::vec3(n);
    const glm::vec3 T =
        glm::normalize(glm::vec3(float(-std::sin(phi)), 0.0f, float(std::cos(phi))));
    const glm::vec3 B = -glm::cross(N, T);
    auto unit = [](std::uint8_t byte) { return byte / 255.0f; };
    const glm::vec3 tangentNormal(unit(material.normal.at(x, y, 0)) * 2.0f - 1.0f,
                                  unit(material.normal.at(x, y, 1)) * 2.0f - 1.0f,
                                  unit(material.normal.at(x, y, 2)) * 2.0f - 1.0f);
    auto linearOf = [](std::uint8_t byte) { return float(srgbToLinear(byte / 255.0)); };
    cpu::SurfacePoint surface;
    surface.position = glm::vec3(hit.position);
    surface.normal =
        glm::normalize(T * tangentNormal.x + B * tangentNormal.y + N * tangentNormal.z);
    surface.albedo = {linearOf(material.albedo.at(x, y, 0)), linearOf(material.albedo.at(x, y, 1)),
                      linearOf(material.albedo.at(x, y, 2))};
    surface.metallic = unit(material.metallic.at(x, y, 0));
    surface.roughness = unit(material.roughness.at(x, y, 0));
    surface.ao = unit(material.ao.at(x, y, 0));  // occlusion is linear
    return surface;
}

}  // namespace pbr::test
