#include "procedural.h"

#include <stb_perlin.h>

#include <algorithm>
#include <cmath>
#include <thread>

namespace pbr::procedural {

float tilingFbm(float u, float v, int cells, int octaves, float gain, int seed, int stretch) {
    float sum = 0.0f, amplitude = 1.0f, norm = 0.0f;
    int frequency = cells;
    for (int octave = 0; octave < octaves; ++octave) {
        const int across = frequency, down = std::max(1, frequency / stretch);
        // stb_perlin wraps the lattice at powers of two up to 256; past that, stop adding detail.
        if (across > 256) break;
        sum += amplitude * stb_perlin_noise3_seed(u * float(across), v * float(down),
                                                  float(seed) * 0.37f, across, down, 0, seed);
        norm += amplitude;
        amplitude *= gain;
        frequency *= 2;
    }
    return norm > 0.0f ? sum / norm * 1.6f : 0.0f;  // perlin rarely reaches +-0.6 alone
}

float hash01(std::uint32_t x, std::uint32_t y, std::uint32_t seed) {
    std::uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return float(h >> 8) / float(1u << 24);
}

float smoothstep(float edge0, float edge1, float x) {
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

Field makeField(int size, const std::function<float(float, float, int, int)>& f) {
    Field field{size, std::vector<float>(size_t(size) * size_t(size))};
    const unsigned workers = std::max(1u, std::min(8u, std::thread::hardware_concurrency()));
    std::vector<std::thread> threads;
    for (unsigned w = 0; w < workers; ++w) {
        threads.emplace_back([&, w] {
            for (int y = int(w); y < size; y += int(workers)) {
                for (int x = 0; x < size; ++x) {
                    field.at(x, y) =
                        f((float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size), x, y);
                }
            }
        });
    }
    for (std::thread& t : threads) t.join();
    return field;
}

namespace {
Field boxBlurOnce(const Field& in, int radius) {
    Field horizontal = in, out = in;
    const float scale = 1.0f / float(2 * radius + 1);
    for (int y = 0; y < in.size; ++y) {
        float sum = 0.0f;
        for (int x = -radius; x <= radius; ++x) sum += in.at(x, y);
        for (int x = 0; x < in.size; ++x) {
            horizontal.at(x, y) = sum * scale;
            sum += in.at(x + radius + 1, y) - in.at(x - radius, y);
        }
    }
    for (int x = 0; x < in.size; ++x) {
        float sum = 0.0f;
        for (int y = -radius; y <= radius; ++y) sum += horizontal.at(x, y);
        for (int y = 0; y < in.size; ++y) {
            out.at(x, y) = sum * scale;
            sum += horizontal.at(x, y + radius + 1) - horizontal.at(x, y - radius);
        }
    }
    return out;
}
}  // namespace

Field blur(const Field& field, int radius) {
    return boxBlurOnce(boxBlurOnce(field, radius), radius);
}

std::vector<glm::vec3> normalsFromHeight(const Field& height, float depth) {
    std::vector<glm::vec3> normals(height.values.size());
    const float scale = depth * float(height.size) * 0.5f;  // central difference over 2 texels
    for (int y = 0; y < height.size; ++y) {
        for (int x = 0; x < height.size; ++x) {
            const float dx = (height.at(x + 1, y) - height.at(x - 1, y)) * scale;
            const float dUp =
                (height.at(x, y - 1) - height.at(x, y + 1)) * scale;  // row 0 is the top
            normals[height.index(x, y)] = glm::normalize(glm::vec3(-dx, -dUp, 1.0f));
        }
    }
    return normals;
}

Field occlusionFromHeight(const Field& height, int radius, float strength) {
    const Field around = blur(height, radius);
    Field ao = height;
    for (size_t i = 0; i < ao.values.size(); ++i) {
        ao.values[i] = std::clamp(
            1.0f - strength * std::max(0.0f, around.values[i] - height.values[i]), 0.0f, 1.0f);
    }
    return ao;
}

}  // namespace pbr::procedural
