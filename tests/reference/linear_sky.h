#pragma once
// The environment of the image-based light's reference tests: linear in the direction w, along
// another axis in each channel (a swapped channel or a mirrored axis shows), and never far from 1:
//   L(w) = a + b w (per channel), a = (0.6, 0.5, 0.45), b = (0.4 w.x, 0.3 w.y, -0.35 w.z).
// Its convolutions have closed forms. The irradiance map holds the cosine-weighted mean of L over
// the hemisphere around N (the irradiance over pi), and the cosine-weighted mean of w there is
// (2/3) N. The prefiltered map's level for roughness r holds the mean of L over the GGX lobe
// around R as the text weighs it (half vectors H drawn from D(H) NdotH, each L weighted by
// NdotL, with N = V = R); the lobe is symmetric about R, so the mean of w is k(r) R (lobeMean).
#include <array>
#include <filesystem>

#include <glm/glm.hpp>

namespace pbr::test {

inline constexpr glm::dvec3 kSkyMean{0.6, 0.5, 0.45};
glm::dvec3 skySlope(const glm::dvec3& w);
glm::dvec3 sky(const glm::dvec3& w);

// The environment as an equirectangular .hdr in `dir`: column u = atan(w.z, w.x) / 2 pi + 1/2
// and the top row straight up, as LearnOpenGL's SampleSphericalMap reads it (with the image's
// rows top first).
std::filesystem::path writeLinearSky(const std::filesystem::path& dir);

// k(r): the mean of w.R over the lobe of roughness r.
double lobeMean(double roughness);

// The three reads of the split sum at a surface point, from the closed forms.
struct SkyReads {
    glm::dvec3 irradiance, prefiltered;
    glm::dvec2 lut{0.0};
};

class LinearSkyReads {
public:
    // `gltf`: the LUT is the glTF BRDF's (cpu::gltfSplitSumQuadrature, 07 and 08's table), else
    // the texts' (cpu::splitSumQuadrature, 05's).
    explicit LinearSkyReads(bool gltf = false);
    // The reads at a point of normal N seen from V, of roughness `roughness` (one of a few: its
    // LUT row is kept in a table of NdotV); the LUT is read only `withLut`.
    SkyReads at(const glm::dvec3& N, const glm::dvec3& V, double roughness, bool withLut) const;

private:
    std::array<double, 5> levelMean_{1.0, 0.0, 0.0, 0.0, 0.0};  // level 0: the mirror
    bool gltf_ = false;
};

}  // namespace pbr::test
