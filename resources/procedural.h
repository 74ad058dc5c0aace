#pragma once
// Building blocks for the project's own procedural assets (the recipes under resources/): tiling
// noise over the unit square, scalar fields, height -> normal map and ambient occlusion.
// Deterministic: the same inputs give the same floats on the same machine.
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

namespace pbr::procedural {

// Perlin fractal noise that tiles over [0,1)^2: `cells` lattice cells across at the first octave
// (a power of two), doubling each octave. `stretch` divides the cells along v (>1: streaks along
// v). About [-1, 1].
float tilingFbm(float u, float v, int cells, int octaves, float gain, int seed, int stretch = 1);

// A value in [0, 1) for an integer cell, from a seed: per-brick colours and the like.
float hash01(std::uint32_t x, std::uint32_t y, std::uint32_t seed);

float smoothstep(float edge0, float edge1, float x);

// A square scalar field with wrap-around neighbours (the textures tile).
struct Field {
    int size = 0;
    std::vector<float> values;

    float& at(int x, int y) { return values[index(x, y)]; }
    float at(int x, int y) const { return values[index(x, y)]; }
    size_t index(int x, int y) const {
        const int wx = ((x % size) + size) % size, wy = ((y % size) + size) % size;
        return size_t(wy) * size_t(size) + size_t(wx);
    }
};

// Evaluates f(u, v) at every texel centre, rows split over threads (same result either way).
Field makeField(int size, const std::function<float(float u, float v, int x, int y)>& f);

// Box blur with wrap-around, `radius` texels, applied twice (close to a Gaussian).
Field blur(const Field& field, int radius);

// Tangent-space normals of a height field, OpenGL convention: x to the image's right, y to the
// image's top, z out of the surface. `depth` is the height of 1.0 as a fraction of the texture
// width.
std::vector<glm::vec3> normalsFromHeight(const Field& height, float depth);

// Cavity occlusion: texels below their neighbourhood (blurred height) are darker.
Field occlusionFromHeight(const Field& height, int radius, float strength);

}  // namespace pbr::procedural
