#include "materials.h"

#include <algorithm>
#include <cmath>

#include "base/error.h"
#include "procedural.h"

namespace pbr::materials {

namespace {

using procedural::Field;
using procedural::hash01;
using procedural::makeField;
using procedural::smoothstep;
using procedural::tilingFbm;

std::uint8_t toByte(float value) {
    return std::uint8_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
}

float linearToSrgb(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

Field constant(int size, float value) {
    return Field{size, std::vector<float>(size_t(size) * size_t(size), value)};
}

// The maps of one set, as float fields, before they become images.
struct Maps {
    explicit Maps(int size)
        : r(constant(size, 0.0f)),
          g(r),
          b(r),
          height(r),
          metallic(r),
          roughness(r),
          cavity(constant(size, 1.0f)) {}

    Field r, g, b;  // albedo, authored in sRGB
    Field height;   // for the normal map and the occlusion
    Field metallic, roughness;
    Field cavity;          // extra occlusion painted by the recipe (1 = none)
    float depth = 0.005f;  // normal-map depth: height 1 as a fraction of the texture width
    int aoRadius = 4;
    float aoStrength = 3.0f;
};

Image grey(const Field& field, bool srgb) {
    Image image{field.size, field.size, 1, std::vector<std::uint8_t>(field.values.size())};
    for (size_t i = 0; i < field.values.size(); ++i) {
        image.pixels[i] = toByte(srgb ? linearToSrgb(field.values[i]) : field.values[i]);
    }
    return image;
}

MaterialSet finish(const std::string& name, const Maps& m) {
    const int size = m.height.size;
    MaterialSet set;
    set.name = name;
    set.albedo = {size, size, 3, std::vector<std::uint8_t>(size_t(size) * size_t(size) * 3)};
    set.normal = set.albedo;
    const std::vector<glm::vec3> normals = procedural::normalsFromHeight(m.height, m.depth);
    for (size_t i = 0; i < m.height.values.size(); ++i) {
        set.albedo.pixels[i * 3 + 0] = toByte(m.r.values[i]);
        set.albedo.pixels[i * 3 + 1] = toByte(m.g.values[i]);
        set.albedo.pixels[i * 3 + 2] = toByte(m.b.values[i]);
        for (int c = 0; c < 3; ++c)
            set.normal.pixels[i * 3 + size_t(c)] = toByte(normals[i][c] * 0.5f + 0.5f);
    }
    set.metallic = grey(m.metallic, false);
    set.roughness = grey(m.roughness, false);
    Field ao = procedural::occlusionFromHeight(m.height, m.aoRadius, m.aoStrength);
    for (size_t i = 0; i < ao.values.size(); ++i) ao.values[i] *= m.cavity.values[i];
    set.ao = grey(ao, false);  // occlusion is linear data (glTF, and the text's code)
    return set;
}

// Dark metallic iron with orange-brown patches of rough, non-metallic rust, and pitting.
MaterialSet rustedIron(int size) {
    Maps m(size);
    const Field rust = makeField(size, [](float u, float v, int, int) {
        const float patches =
            tilingFbm(u, v, 4, 6, 0.55f, 11) + 0.35f * tilingFbm(u, v, 32, 3, 0.5f, 12);
        return smoothstep(0.02f, 0.22f, patches);
    });
    const Field pits = makeField(size, [](float u, float v, int, int) {
        return smoothstep(0.42f, 0.62f, tilingFbm(u, v, 64, 2, 0.5f, 13));
    });
    const Field grain = makeField(
        size, [](float u, float v, int, int) { return tilingFbm(u, v, 128, 2, 0.5f, 14); });
    const Field tone = makeField(
        size, [](float u, float v, int, int) { return tilingFbm(u, v, 16, 4, 0.5f, 15); });
    for (size_t i = 0; i < rust.values.size(); ++i) {
        const float r = rust.values[i], p = pits.values[i], g = grain.values[i], t = tone.values[i];
        const glm::vec3 iron = glm::vec3(0.36f, 0.37f, 0.39f) * (1.0f + 0.12f * t + 0.05f * g);
        const glm::vec3 rustColor =
            glm::mix(glm::vec3(0.33f, 0.14f, 0.06f), glm::vec3(0.70f, 0.33f, 0.12f),
                     std::clamp(0.5f + 0.8f * t, 0.0f, 1.0f));
        glm::vec3 albedo = glm::mix(iron, rustColor, r) * (1.0f - 0.45f * p * (1.0f - r));
        m.r.values[i] = albedo.r;
        m.g.values[i] = albedo.g;
        m.b.values[i] = albedo.b;
        m.metallic.values[i] = (1.0f - r) * (1.0f - 0.5f * p);
        m.roughness.values[i] = std::clamp(
            glm::mix(0.32f + 0.1f * t + 0.05f * g, 0.88f + 0.08f * g, r) + 0.15f * p, 0.0f, 1.0f);
        m.height.values[i] = 0.5f + r * (0.25f + 0.1f * g) - 0.6f * p * (1.0f - r) + 0.03f * g;
    }
    m.depth = 0.004f;
    return finish("rusted_iron", m);
}

// Smooth metallic gold with light wear: fine scratches and a few duller smudges.
MaterialSet gold(int size) {
    Maps m(size);
    const Field scratches = makeField(size, [](float u, float v, int, int) {
        // thin ridges of stretched noise, two directions
        const float a = 1.0f - std::abs(tilingFbm(u, v, 256, 1, 0.5f, 21, 32));
        const float b = 1.0f - std::abs(tilingFbm(v, u, 256, 1, 0.5f, 22, 32));
        // in worn patches only, so the scratches read as wear, not as a pattern
        const float worn = smoothstep(0.0f, 0.5f, tilingFbm(u, v, 4, 3, 0.5f, 25));
        return std::pow(std::max(a, b), 80.0f) * worn;
    });
    const Field smudge = makeField(size, [](float u, float v, int, int) {
        return smoothstep(0.15f, 0.6f, tilingFbm(u, v, 8, 5, 0.5f, 23));
    });
    const Field dents = makeField(
        size, [](float u, float v, int, int) { return tilingFbm(u, v, 32, 3, 0.5f, 24); });
    for (size_t i = 0; i < scratches.values.size(); ++i) {
        const float s = scratches.values[i], w = smudge.values[i], d = dents.values[i];
        const glm::vec3 albedo =
            glm::vec3(1.0f, 0.86f, 0.57f) * (1.0f - 0.08f * w - 0.05f * s + 0.02f * d);
        m.r.values[i] = albedo.r;
        m.g.values[i] = albedo.g;
        m.b.values[i] = albedo.b;
        m.metallic.values[i] = 1.0f;
        m.roughness.values[i] = 0.14f + 0.12f * w + 0.25f * s + 0.03f * d;
        m.height.values[i] = 0.5f - 0.35f * s + 0.08f * d;
    }
    m.depth = 0.002f;
    m.aoStrength = 1.0f;
    return finish("gold", m);
}

// Green blades in clumps over dark soil: a rough dielectric.
MaterialSet grass(int size) {
    Maps m(size);
    const Field blades = makeField(size, [](float u, float v, int, int) {
        // vertical streaks: fine across, coarse along v; two layers
        const float a = 1.0f - std::abs(tilingFbm(u, v, 128, 2, 0.6f, 31, 16));
        const float b = 1.0f - std::abs(tilingFbm(u + 0.37f, v, 256, 1, 0.6f, 32, 16));
        return std::max(std::pow(a, 6.0f), 0.8f * std::pow(b, 8.0f));
    });
    const Field clumps = makeField(size, [](float u, float v, int, int) {
        return 0.5f + 0.5f * tilingFbm(u, v, 8, 4, 0.55f, 33);
    });
    const Field tint = makeField(
        size, [](float u, float v, int, int) { return tilingFbm(u, v, 16, 3, 0.5f, 34); });
    for (size_t i = 0; i < blades.values.size(); ++i) {
        const float b = blades.values[i], c = clumps.values[i], t = tint.values[i];
        const float h = std::clamp(b * (0.55f + 0.6f * c), 0.0f, 1.0f);
        const glm::vec3 soil(0.20f, 0.14f, 0.08f);
        const glm::vec3 dark(0.10f, 0.30f, 0.05f), bright(0.38f, 0.62f, 0.12f),
            dry(0.60f, 0.62f, 0.22f);
        glm::vec3 leaf = glm::mix(dark, bright, std::clamp(h * 1.2f, 0.0f, 1.0f));
        leaf = glm::mix(leaf, dry, smoothstep(0.35f, 0.8f, t) * 0.6f);
        const glm::vec3 albedo = glm::mix(soil, leaf, smoothstep(0.08f, 0.3f, h));
        m.r.values[i] = albedo.r;
        m.g.values[i] = albedo.g;
        m.b.values[i] = albedo.b;
        m.roughness.values[i] = std::clamp(0.78f + 0.15f * (1.0f - h) + 0.05f * t, 0.0f, 1.0f);
        m.height.values[i] = h;
    }
    m.depth = 0.006f;
    m.aoRadius = 6;
    m.aoStrength = 2.5f;
    return finish("grass", m);
}

// A smooth, saturated blue dielectric with a faint orange-peel texture.
MaterialSet plastic(int size) {
    Maps m(size);
    const Field peel = makeField(
        size, [](float u, float v, int, int) { return tilingFbm(u, v, 64, 3, 0.5f, 41); });
    for (size_t i = 0; i < peel.values.size(); ++i) {
        const float p = peel.values[i];
        m.r.values[i] = 0.08f;
        m.g.values[i] = 0.30f + 0.01f * p;
        m.b.values[i] = 0.80f + 0.01f * p;
        m.roughness.values[i] = 0.22f + 0.03f * p;
        m.height.values[i] = 0.5f + 0.5f * p;
    }
    m.depth = 0.0004f;
    m.aoStrength = 0.0f;
    return finish("plastic", m);
}

// Bricks in running bond with recessed mortar joints.
MaterialSet wall(int size) {
    Maps m(size);
    constexpr int kRows = 16, kColumns = 16;  // square in the texture: 2:1 bricks on the sphere
    constexpr float kMortar = 0.09f;          // joint width, as a fraction of a brick's height
    struct Brick {
        float inside;  // 0 in the joint, rising to 1 a little inside the brick
        std::uint32_t id;
    };
    auto brickAt = [](float u, float v) {
        const float row = v * kRows;
        const int rowIndex = int(std::floor(row));
        const float shifted = u * kColumns + (rowIndex % 2 ? 0.5f : 0.0f);
        const int column = int(std::floor(shifted));
        const float fx = shifted - float(column), fy = row - float(rowIndex);
        // distance to the nearest joint, in brick heights (a brick is 1 high, 1 wide in texture)
        const float edge = std::min(std::min(fx, 1.0f - fx), std::min(fy, 1.0f - fy));
        const std::uint32_t wrapped = std::uint32_t((column % kColumns + kColumns) % kColumns);
        return Brick{smoothstep(kMortar * 0.5f, kMortar * 0.5f + 0.06f, edge),
                     wrapped * 131u + std::uint32_t(rowIndex)};
    };
    const Field surface = makeField(
        size, [](float u, float v, int, int) { return tilingFbm(u, v, 64, 4, 0.55f, 51); });
    const Field blotch = makeField(
        size, [](float u, float v, int, int) { return tilingFbm(u, v, 16, 3, 0.5f, 52); });
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const size_t i = size_t(y) * size_t(size) + size_t(x);
            const Brick brick =
                brickAt((float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size));
            const float s = surface.values[i], b = blotch.values[i];
            const float shade = hash01(brick.id, 7u, 53u), hue = hash01(brick.id, 9u, 54u);
            const glm::vec3 brickColor =
                glm::vec3(0.56f + 0.12f * hue, 0.25f + 0.05f * hue, 0.17f) *
                (0.72f + 0.4f * shade) * (1.0f + 0.08f * s + 0.06f * b);
            const glm::vec3 mortar = glm::vec3(0.66f, 0.64f, 0.60f) * (1.0f + 0.08f * s);
            const glm::vec3 albedo = glm::mix(mortar, brickColor, brick.inside);
            m.r.values[i] = albedo.r;
            m.g.values[i] = albedo.g;
            m.b.values[i] = albedo.b;
            m.roughness.values[i] = glm::mix(0.95f, 0.82f + 0.08f * s, brick.inside);
            m.height.values[i] = 0.15f * (0.5f + 0.3f * s) + brick.inside * (0.85f + 0.06f * s);
            m.cavity.values[i] = 0.65f + 0.35f * brick.inside;
        }
    }
    m.depth = 0.01f;
    m.aoRadius = 3;
    m.aoStrength = 1.5f;
    return finish("wall", m);
}

}  // namespace

MaterialSet bake(const std::string& name, int size) {
    if (size < 16 || (size & (size - 1)) != 0)
        throw Error("material size must be a power of two >= 16");
    if (name == "rusted_iron") return rustedIron(size);
    if (name == "gold") return gold(size);
    if (name == "grass") return grass(size);
    if (name == "plastic") return plastic(size);
    if (name == "wall") return wall(size);
    throw Error("unknown material set '" + name + "'");
}

void write(const MaterialSet& set, const std::filesystem::path& dir) {
    const std::filesystem::path folder = dir / set.name;
    std::filesystem::create_directories(folder);  // the build's own folder
    writePng(folder / "albedo.png", set.albedo, PngEncoding::Small);
    writePng(folder / "normal.png", set.normal, PngEncoding::Small);
    writePng(folder / "metallic.png", set.metallic, PngEncoding::Small);
    writePng(folder / "roughness.png", set.roughness, PngEncoding::Small);
    writePng(folder / "ao.png", set.ao, PngEncoding::Small);
}

Image contactSheet(const std::vector<MaterialSet>& sets, int thumb) {
    const int gap = 4;
    const int columns = 5;
    Image sheet{columns * (thumb + gap) + gap, int(sets.size()) * (thumb + gap) + gap, 3, {}};
    sheet.pixels.assign(size_t(sheet.width) * size_t(sheet.height) * 3, 96);  // grey gaps
    for (size_t row = 0; row < sets.size(); ++row) {
        const Image* maps[] = {&sets[row].albedo, &sets[row].normal, &sets[row].metallic,
                               &sets[row].roughness, &sets[row].ao};
        for (int column = 0; column < columns; ++column) {
            const Image& map = *maps[column];
            for (int y = 0; y < thumb; ++y) {
                for (int x = 0; x < thumb; ++x) {
                    // the average of the source texels under this thumbnail pixel
                    const int step = map.width / thumb;
                    for (int c = 0; c < 3; ++c) {
                        int sum = 0;
                        for (int sy = 0; sy < step; ++sy)
                            for (int sx = 0; sx < step; ++sx)
                                sum +=
                                    map.at(x * step + sx, y * step + sy, map.channels == 1 ? 0 : c);
                        const size_t out =
                            (size_t(gap + int(row) * (thumb + gap) + y) * size_t(sheet.width) +
                             size_t(gap + column * (thumb + gap) + x)) *
                                3 +
                            size_t(c);
                        sheet.pixels[out] = std::uint8_t(sum / (step * step));
                    }
                }
            }
        }
    }
    return sheet;
}

}  // namespace pbr::materials
