#include "reference/linear_sky.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "files/image.h"
#include "math/brdf.h"

namespace pbr::test {

namespace fs = std::filesystem;

glm::dvec3 skySlope(const glm::dvec3& w) {
    return {0.4 * w.x, 0.3 * w.y, -0.35 * w.z};
}

glm::dvec3 sky(const glm::dvec3& w) {
    return kSkyMean + skySlope(w);
}

fs::path writeLinearSky(const fs::path& dir) {
    constexpr int kW = 512, kH = 256;
    HdrImage image{kW, kH, {}};
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const double phi = ((x + 0.5) / kW - 0.5) * 2.0 * std::numbers::pi;
            const double lat = (0.5 - (y + 0.5) / kH) * std::numbers::pi;
            const glm::dvec3 w(std::cos(lat) * std::cos(phi), std::sin(lat),
                               std::cos(lat) * std::sin(phi));
            const glm::dvec3 L = sky(w);
            image.pixels.insert(image.pixels.end(), {float(L.r), float(L.g), float(L.b)});
        }
    }
    fs::create_directories(dir);
    const fs::path path = dir / "linear_sky.hdr";
    writeHdr(path, image);
    return path;
}

// By Simpson's rule in the half vector's angle t from R, L at 2t from it:
//   k = integral of cos^2(2t) D(t) cos t sin t / integral of cos(2t) D(t) cos t sin t,
// t from 0 to pi/4 (NdotL > 0), D = GGX with alpha = r^2.
double lobeMean(double roughness) {
    const double a2 = std::pow(roughness, 4.0);
    constexpr int kSteps = 20000;
    const double h = (std::numbers::pi / 4.0) / kSteps;
    double top = 0.0, bottom = 0.0;
    for (int i = 0; i <= kSteps; ++i) {
        const double t = i * h, c = std::cos(t);
        const double d = c * c * (a2 - 1.0) + 1.0;
        const double weight = (i == 0 || i == kSteps ? 1.0 : (i % 2 ? 4.0 : 2.0)) * a2 /
                              (std::numbers::pi * d * d) * c * std::sin(t) * std::cos(2.0 * t);
        top += weight * std::cos(2.0 * t);
        bottom += weight;
    }
    return top / bottom;
}

namespace {
// cpu::splitSumQuadrature (or `gltf`, cpu::gltfSplitSumQuadrature) at NdotV = 24/64, 25/64, ...
// 1 for each roughness asked for, linearly interpolated (the quadrature is smooth there: the
// interpolation errs by under 0.001) and computed once, when first asked for: each point takes
// milliseconds.
glm::dvec2 lut(double NdotV, double roughness, bool gltf) {
    static std::map<std::pair<bool, double>, std::vector<glm::dvec2>> rows;
    const auto quadrature = gltf ? cpu::gltfSplitSumQuadrature : cpu::splitSumQuadrature;
    constexpr int kFirst = 24, kLast = 64;
    if (NdotV < kFirst / 64.0) return quadrature(NdotV, roughness);
    std::vector<glm::dvec2>& row = rows[{gltf, roughness}];
    if (row.empty()) {
        for (int i = kFirst; i <= kLast; ++i) row.push_back(quadrature(i / 64.0, roughness));
    }
    const double x = NdotV * 64.0 - kFirst;
    const int i = std::min(int(x), kLast - kFirst - 1);
    return glm::mix(row[size_t(i)], row[size_t(i + 1)], x - i);
}
}  // namespace

LinearSkyReads::LinearSkyReads(bool gltf) : gltf_(gltf) {
    for (int level = 1; level <= 4; ++level) levelMean_[size_t(level)] = lobeMean(level / 4.0);
}

SkyReads LinearSkyReads::at(const glm::dvec3& N, const glm::dvec3& V, double roughness,
                            bool withLut) const {
    SkyReads reads;
    reads.irradiance = kSkyMean + skySlope(2.0 / 3.0 * N);
    // The prefiltered map's five levels are roughness 0, 1/4, ... 1, read trilinearly at level
    // 4 r; below level 1 the environment itself stands for level 0.
    const glm::dvec3 R = glm::reflect(-V, N);
    const double lod = std::clamp(roughness, 0.0, 1.0) * 4.0;
    const int below = std::min(int(lod), 3);
    reads.prefiltered =
        kSkyMean + skySlope(R) * glm::mix(levelMean_[size_t(below)],
                                          levelMean_[size_t(below + 1)], lod - below);
    // the LUT's rows hold roughness (j + 0.5) / 512: a roughness of 0 reads the first
    if (withLut)
        reads.lut = lut(std::max(glm::dot(N, V), 0.0), std::max(roughness, 0.5 / 512.0), gltf_);
    return reads;
}

}  // namespace pbr::test
