// The recipe for the project's own glTF 2.0 asset for sample 07 (run by the build):
//   make_pbr_showcase OUT_DIR
// writes OUT_DIR/pbr_showcase.gltf, pbr_showcase.bin and its textures pbr_showcase_*.png, all of
// them or none. Y up, metres, meant to be seen from +Z looking down -Z; everything fits in
// x -3.5..3.5, y 0..3.9, z -2..2. Each object shows parts of glTF's metallic-roughness model:
//
// object (node translation)       what it shows
// sphere_metal_0..4               metallicRoughnessTexture (4x4, solid) x metallicFactor 1 x
//   (-2, -1, 0, 1, 2; 1.5; 0),    roughnessFactor 1: B = 255 (metal), G = roughness 0, 64, 128,
//   radius 0.4                    191, 255 left to right; baseColorFactor gold (1, 0.766, 0.336)
// sphere_dielectric_0..4          the same with B = 0, baseColorFactor red (0.8, 0.1, 0.1): top
//   (-2 .. 2; 0.5; 0)             left is smooth metal, bottom right rough dielectric
// floor                           magFilter NEAREST (a 32 px pixel-art checker, one every 2 m:
//   y = 0, x -3.5..3.5, z -2..2   checks of 0.5 m), REPEAT; a normalTexture (tile joints) with
//                                 TANGENT; the point light's range and the spot light's cone
//                                 show on it
// tile_panel                      normalTexture (scale 0.8) with TANGENT from the file;
//   (0, 3, -0.8), a 1.3 x 1.3     occlusionTexture on TEXCOORD_1 (strength 0.9; an atlas laid out
//   x 0.16 box                    unlike TEXCOORD_0: AO read with the wrong set misses the
//                                 grooves); emissiveTexture (sRGB) x emissiveFactor (1, 0.9, 0.8):
//                                 glowing rings; metallicRoughnessTexture (metal rings, rough
//                                 grout, glossy tiles)
// leaf                            alphaMode MASK, alphaCutoff 0.4: the outline is the texture's
//   (-2.4, 3, -0.6), its back     alpha; of three bite marks the two upper ones (alpha 0.45) stay,
//   to the camera                 the lower one (0.3) is a hole (at the default 0.5 all three
//                                 would be holes); doubleSided: culled, the leaf vanishes
// ribbon                          doubleSided: a wave-bent sheet with half a twist, its front seen
//   (-1.2, 2.25..3.75, -0.6)      at the bottom, its back at the top; COLOR_0 (orange to blue) x
//                                 baseColorTexture x baseColorFactor; MIRRORED_REPEAT: the
//                                 stripes zig-zag where the texture repeats
// glass_pane                      alphaMode BLEND: baseColorFactor alpha 0.7 x texture alpha
//   (0.75, 3, -0.25)              (frame 1, glass 0.5, frosted bands 0.75), in front of the
//                                 panel's right column
// label                           KHR_texture_transform (offset, rotation 90 degrees, scale): "PBR
//   (1.95, 3, -0.6), turned 15    07" reads upright only with the transform; CLAMP_TO_EDGE;
//   degrees to the centre         magenta stripes wherever a wrong transform samples
// point_light (-1.5, 1.6, 1.2)    KHR_lights_punctual point, 20 cd, range 2.2 m: a warm disc of
//                                 1.5 m radius on the floor in front of the left spheres, ended
//                                 by the range
// spot_light (1.6, 2.6, 1.8)      spot, 60 cd, cones 0.3 / 0.4 rad, aimed at the floor at
//                                 (1.6, 0, 1): a cool disc of about 1.1 m radius on the floor in
//                                 front of the right spheres; its edge grazes the lower fronts of
//                                 sphere_dielectric_3 and _4
// fill_light                      directional, 1.5 lux, travelling along (0.4, -0.6, -0.7)
//
// Samplers: REPEAT (floor, spheres, panel), CLAMP_TO_EDGE (label, leaf, pane, panel occlusion),
// MIRRORED_REPEAT (ribbon); magFilter NEAREST on the floor's colour, LINEAR elsewhere, minFilter
// LINEAR_MIPMAP_LINEAR everywhere. Deterministic: the same bytes every run.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "base/error.h"
#include "base/output.h"
#include "files/image.h"
#include "gl/mesh.h"
#include "gltf_writer.h"
#include "procedural.h"

namespace {

namespace fs = std::filesystem;
namespace gltf = pbr::gltf;
using gltf::quoted;
using gltf::rotation;
using gltf::vec;
using pbr::Image;
using pbr::MeshData;
using pbr::procedural::Field;
using pbr::procedural::smoothstep;

constexpr float kPi = std::numbers::pi_v<float>;

// --- geometry ------------------------------------------------------------------------------

// A grid of (columns + 1) x (rows + 1) vertices over (s, t) in [0, 1]^2 at `position(s, t)`; the
// front is cross(dP/ds, dP/dt) (counter-clockwise seen from it), normals from the derivatives;
// uv = (s, 1 - t) mapped by `uvScale` (t runs up the image, as glTF's v runs down). With
// `tangents`, TANGENT too: xyz along dP/ds made normal to the normal, w = +1 when
// cross(normal, tangent) runs along dP/dt (up the image), as glTF's bitangent does.
MeshData sheet(int columns, int rows, const std::function<glm::vec3(float, float)>& position,
               glm::vec2 uvScale = {1.0f, 1.0f}, bool tangents = false) {
    MeshData mesh;
    constexpr float h = 1e-3f;
    for (int j = 0; j <= rows; ++j) {
        for (int i = 0; i <= columns; ++i) {
            const float s = float(i) / float(columns), t = float(j) / float(rows);
            mesh.positions.push_back(position(s, t));
            const glm::vec3 ds = position(s + h, t) - position(s - h, t);
            const glm::vec3 dt = position(s, t + h) - position(s, t - h);
            const glm::vec3 normal = glm::normalize(glm::cross(ds, dt));
            mesh.normals.push_back(normal);
            mesh.uvs.push_back(glm::vec2(s, 1.0f - t) * uvScale);
            if (tangents) {
                const glm::vec3 tangent = glm::normalize(ds - normal * glm::dot(normal, ds));
                const float w = glm::dot(glm::cross(normal, tangent), dt) >= 0.0f ? 1.0f : -1.0f;
                mesh.tangents.push_back(glm::vec4(tangent, w));
            }
        }
    }
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < columns; ++i) {
            const auto a = std::uint32_t(j * (columns + 1) + i), c = a + std::uint32_t(columns) + 1;
            mesh.indices.insert(mesh.indices.end(), {a, a + 1, c + 1, a, c + 1, c});
        }
    }
    return mesh;
}

// Where the panel's faces lie in its occlusion atlas (TEXCOORD_1), in texels of kAtlasSize: the
// front large, the sides in strips, the back in a corner; unlike TEXCOORD_0 (front = whole image).
constexpr int kAtlasSize = 128;
struct Rect {
    float x0, y0, x1, y1;
};
constexpr Rect kAtlasFront{4, 4, 100, 100}, kAtlasBack{104, 104, 126, 126};
constexpr Rect kAtlasSides[4] = {{116, 4, 126, 100},   // +x
                                 {104, 4, 114, 100},   // -x
                                 {4, 104, 100, 114},   // +y
                                 {4, 116, 100, 126}};  // -y

// A box with half extents `half`, 24 vertices, with tangents (w = 1: the image's top lies along
// cross(N, T)); TEXCOORD_0 maps the whole image on the front and back, a strip of its left or top
// edge on the sides; TEXCOORD_1 (uvs1) the atlas layout above.
MeshData panelBox(glm::vec3 half) {
    struct Face {
        glm::vec3 normal, tangent;
        Rect atlas;
    };
    const Face faces[] = {
        {{0, 0, 1}, {1, 0, 0}, kAtlasFront},     {{0, 0, -1}, {-1, 0, 0}, kAtlasBack},
        {{1, 0, 0}, {0, 0, -1}, kAtlasSides[0]}, {{-1, 0, 0}, {0, 0, 1}, kAtlasSides[1]},
        {{0, 1, 0}, {1, 0, 0}, kAtlasSides[2]},  {{0, -1, 0}, {1, 0, 0}, kAtlasSides[3]},
    };
    MeshData mesh;
    for (const Face& face : faces) {
        const glm::vec3 bitangent = glm::cross(face.normal, face.tangent);
        const float alongT = glm::dot(glm::abs(face.tangent), half),
                    alongB = glm::dot(glm::abs(bitangent), half);
        const float width = std::max(half.x, half.y);
        const auto base = std::uint32_t(mesh.positions.size());
        for (const glm::vec2 corner : {glm::vec2(-1, -1), {1, -1}, {1, 1}, {-1, 1}}) {
            mesh.positions.push_back(face.normal * glm::dot(glm::abs(face.normal), half) +
                                     face.tangent * corner.x * alongT +
                                     bitangent * corner.y * alongB);
            mesh.normals.push_back(face.normal);
            mesh.tangents.push_back(glm::vec4(face.tangent, 1.0f));
            const glm::vec2 a(corner.x * 0.5f + 0.5f, 0.5f - corner.y * 0.5f);
            mesh.uvs.push_back(a * glm::vec2(alongT, alongB) / width);
            mesh.uvs1.push_back(glm::vec2(face.atlas.x0 + a.x * (face.atlas.x1 - face.atlas.x0),
                                          face.atlas.y0 + a.y * (face.atlas.y1 - face.atlas.y0)) /
                                float(kAtlasSize));
        }
        for (std::uint32_t i : {0, 1, 2, 0, 2, 3}) mesh.indices.push_back(base + i);
    }
    return mesh;
}

// --- textures ------------------------------------------------------------------------------

std::uint8_t toByte(float value) {
    return std::uint8_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
}

// An image of `channels` from `texel(x, y)` (values 0..1, sRGB or linear as the map wants).
Image makeImage(int size, int channels, const std::function<glm::vec4(int x, int y)>& texel) {
    Image image{size, size, channels, {}};
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const glm::vec4 value = texel(x, y);
            for (int c = 0; c < channels; ++c) image.pixels.push_back(toByte(value[c]));
        }
    }
    return image;
}

Image normalMap(const Field& height, float depth) {
    const std::vector<glm::vec3> normals = pbr::procedural::normalsFromHeight(height, depth);
    return makeImage(height.size, 3, [&](int x, int y) {
        return glm::vec4(normals[height.index(x, y)] * 0.5f + 0.5f, 1.0f);
    });
}

// Bilinear, wrapping (the fields tile).
float sample(const Field& field, float u, float v) {
    const float x = u * float(field.size) - 0.5f, y = v * float(field.size) - 0.5f;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const float fx = x - float(x0), fy = y - float(y0);
    return glm::mix(glm::mix(field.at(x0, y0), field.at(x0 + 1, y0), fx),
                    glm::mix(field.at(x0, y0 + 1), field.at(x0 + 1, y0 + 1), fx), fy);
}

// The floor's colour: 32 px, 4 x 4 checks of 8, pixel art (lit top-left edges, shaded
// bottom-right ones, a diamond on the light checks); magnified with NEAREST, so the pixels show.
Image floorColor() {
    return makeImage(32, 3, [](int x, int y) {
        const int cx = x / 8, cy = y / 8, lx = x % 8, ly = y % 8;
        const bool light = (cx + cy) % 2 == 0;
        glm::vec3 c = light ? glm::vec3(0.56f, 0.53f, 0.48f) : glm::vec3(0.32f, 0.29f, 0.27f);
        c *= 0.96f + 0.08f * pbr::procedural::hash01(std::uint32_t(cx), std::uint32_t(cy), 7);
        if (lx == 0 || ly == 0) c *= 1.12f;
        if (lx == 7 || ly == 7) c *= 0.72f;
        if (light && std::abs(2 * lx - 7) + std::abs(2 * ly - 7) <= 3) c = {0.62f, 0.40f, 0.26f};
        return glm::vec4(c, 1.0f);
    });
}

// The floor's height at 128 px a repeat: tiles of 32 px (the checks) with bevelled edges.
Field floorHeight() {
    return pbr::procedural::makeField(128, [](float u, float v, int x, int y) {
        const float lx = float(x % 32) + 0.5f, ly = float(y % 32) + 0.5f;
        const float edge = std::min({lx, 32.0f - lx, ly, 32.0f - ly});
        return smoothstep(0.5f, 3.5f, edge) +
               0.04f * pbr::procedural::tilingFbm(u, v, 8, 3, 0.5f, 31);
    });
}

// The panel's tiles: 128 px over the front, 4 x 4 tiles of 32 px: grout grooves, bevels, and on
// five tiles a ring groove (metal, glowing) of radius 9 px.
struct PanelTexel {
    float height, groove, ring, glow;  // ring, glow: 0..1
    int tileX, tileY;
};
PanelTexel panelTexel(int x, int y) {
    PanelTexel t{};
    t.tileX = x / 32, t.tileY = y / 32;
    const float lx = float(x % 32) + 0.5f, ly = float(y % 32) + 0.5f;
    const float edge = std::min({lx, 32.0f - lx, ly, 32.0f - ly});
    t.groove = 1.0f - smoothstep(1.0f, 2.0f, edge);
    t.height = smoothstep(1.0f, 5.0f, edge);
    if ((t.tileX + t.tileY) % 3 == 1) {
        const float off = std::abs(std::hypot(lx - 16.0f, ly - 16.0f) - 9.0f);
        t.ring = 1.0f - smoothstep(1.2f, 2.2f, off);
        t.glow = 1.0f - smoothstep(0.5f, 1.5f, off);
        t.height -= 0.6f * t.ring;
    }
    return t;
}

struct PanelMaps {
    Image color, metallicRoughness, normal, occlusion, emissive;
};

PanelMaps panelMaps() {
    constexpr int size = 128;
    const Field height = pbr::procedural::makeField(size, [](float u, float v, int x, int y) {
        return panelTexel(x, y).height + 0.03f * pbr::procedural::tilingFbm(u, v, 8, 3, 0.5f, 41);
    });
    PanelMaps maps;
    maps.normal = normalMap(height, 0.012f);
    maps.color = makeImage(size, 3, [](int x, int y) {
        const PanelTexel t = panelTexel(x, y);
        const bool cream = (t.tileX + t.tileY) % 2 == 0;
        glm::vec3 c = cream ? glm::vec3(0.80f, 0.76f, 0.66f) : glm::vec3(0.16f, 0.38f, 0.42f);
        c *= 0.92f +
             0.16f * pbr::procedural::hash01(std::uint32_t(t.tileX), std::uint32_t(t.tileY), 43);
        c = glm::mix(c, glm::vec3(0.90f, 0.72f, 0.38f), t.ring);    // gold inlay
        c = glm::mix(c, glm::vec3(0.12f, 0.12f, 0.13f), t.groove);  // grout
        return glm::vec4(c, 1.0f);
    });
    maps.metallicRoughness = makeImage(size, 3, [](int x, int y) {
        const PanelTexel t = panelTexel(x, y);
        const float roughness = glm::mix(glm::mix(0.35f, 0.28f, t.ring), 0.9f, t.groove);
        return glm::vec4(0.0f, roughness, t.ring * (1.0f - t.groove), 1.0f);
    });
    maps.emissive = makeImage(size, 3, [](int x, int y) {
        const PanelTexel t = panelTexel(x, y);
        const glm::vec3 c =
            t.tileX % 2 == 0 ? glm::vec3(1.0f, 0.55f, 0.15f) : glm::vec3(0.2f, 0.8f, 1.0f);
        return glm::vec4(c * t.glow, 1.0f);
    });
    // The atlas: each texel takes the nearest face's value (a few texels of bleed around each).
    const Field cavity = pbr::procedural::occlusionFromHeight(height, 3, 2.5f);
    maps.occlusion = makeImage(kAtlasSize, 3, [&](int x, int y) {
        const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
        auto distance = [&](const Rect& r) {
            return glm::length(glm::max(glm::vec2(r.x0 - p.x, r.y0 - p.y),
                                        glm::max(glm::vec2(p.x - r.x1, p.y - r.y1), glm::vec2(0))));
        };
        float ao = 0.6f, nearest = distance(kAtlasBack);  // the back
        for (const Rect& side : kAtlasSides) {
            if (distance(side) < nearest) nearest = distance(side), ao = 0.8f;
        }
        if (distance(kAtlasFront) < nearest) {
            const float s = std::clamp((p.x - kAtlasFront.x0) / (kAtlasFront.x1 - kAtlasFront.x0),
                                       0.0f, 1.0f),
                        t = std::clamp((p.y - kAtlasFront.y0) / (kAtlasFront.y1 - kAtlasFront.y0),
                                       0.0f, 1.0f);
            const float rim = smoothstep(0.0f, 0.08f, std::min({s, 1.0f - s, t, 1.0f - t}));
            ao = sample(cavity, s, t) * (0.75f + 0.25f * rim);
        }
        return glm::vec4(ao, ao, ao, 1.0f);
    });
    return maps;
}

// The leaf: 128 px RGBA, tip at the top, a stem at the bottom; alpha is the outline (soft over a
// texel or two) and three bite marks, two of alpha 0.45 and one of 0.3.
Image leafColor() {
    return makeImage(128, 4, [](int x, int y) {
        const float u = (float(x) + 0.5f) / 128.0f, t = 1.0f - (float(y) + 0.5f) / 128.0f;
        const float s = std::clamp((t - 0.12f) / 0.86f, 0.0f, 1.0f);
        const float mid = 0.5f + 0.03f * std::sin(kPi * s);
        const float halfWidth = 0.40f * std::pow(std::sin(kPi * s), 0.8f) * (1.1f - 0.3f * s);
        const float across = std::abs(u - mid);
        float alpha = smoothstep(-0.006f, 0.006f, halfWidth - across);
        if (t < 0.16f) alpha = std::max(alpha, smoothstep(-0.006f, 0.006f, 0.016f - across));
        glm::vec3 c = glm::mix(glm::vec3(0.20f, 0.45f, 0.12f), glm::vec3(0.42f, 0.62f, 0.20f),
                               std::clamp(across / 0.4f, 0.0f, 1.0f));
        const float vein = std::abs(std::fmod((t + 0.9f * across) * 7.0f, 1.0f) - 0.5f);
        if (vein < 0.05f || across < 0.012f) c = glm::mix(c, glm::vec3(0.72f, 0.80f, 0.40f), 0.6f);
        struct Bite {
            float u, t, radius, alpha;
        };
        for (const Bite& b : {Bite{0.36f, 0.62f, 0.05f, 0.45f}, Bite{0.63f, 0.72f, 0.045f, 0.45f},
                              Bite{0.60f, 0.38f, 0.055f, 0.3f}}) {
            if (std::hypot(u - b.u, t - b.t) < b.radius) {
                alpha = std::min(alpha, b.alpha);
                c = {0.45f, 0.33f, 0.15f};
            }
        }
        return glm::vec4(c, alpha);
    });
}

// The ribbon: 64 px diagonal stripes with soft edges; mirrored repeats make them zig-zag.
Image ribbonColor() {
    return makeImage(64, 3, [](int x, int y) {
        const float phase = std::fmod(float(x + y) / 16.0f, 1.0f);
        const float stripe = smoothstep(0.05f, 0.1f, phase) - smoothstep(0.45f, 0.5f, phase);
        const float line = 1.0f - smoothstep(0.0f, 0.04f, std::abs(phase - 0.75f));
        return glm::vec4(glm::vec3(0.62f + 0.33f * stripe - 0.35f * line), 1.0f);
    });
}

// The pane: 64 px RGBA, a frame of alpha 1, glass of alpha 0.5 with frosted bands of 0.75.
Image paneColor() {
    return makeImage(64, 4, [](int x, int y) {
        const int edge = std::min({x, 63 - x, y, 63 - y});
        if (edge < 3) return glm::vec4(0.85f, 0.88f, 0.92f, 1.0f);
        const bool frosted = (x + 2 * y) % 32 < 6;
        return frosted ? glm::vec4(1.0f, 1.0f, 1.0f, 0.75f) : glm::vec4(1.0f, 1.0f, 1.0f, 0.5f);
    });
}

// The label's texture transform (KHR_texture_transform: uv' = T R S uv with R(u, v) = (c u + s v,
// -s u + c v), as the extension's example, its TextureTransformTest model and Khronos' sample
// viewer turn it; not the transpose that the extension's GLSL listing prints), and the label as
// it must look: 2:1, "PBR 07".
constexpr glm::vec2 kLabelOffset(0.25f, 0.95f), kLabelScale(0.9f, 0.45f);
constexpr float kLabelRotation = kPi / 2.0f;

glm::vec3 labelLook(float u, float v) {  // u across, v down, both 0..1
    static const char* glyphs[6][7] = {
        {"11110", "10001", "10001", "11110", "10000", "10000", "10000"},  // P
        {"11110", "10001", "10001", "11110", "10001", "10001", "11110"},  // B
        {"11110", "10001", "10001", "11110", "10100", "10010", "10001"},  // R
        {"00000", "00000", "00000", "00000", "00000", "00000", "00000"},  // space
        {"01110", "10001", "10011", "10101", "11001", "10001", "01110"},  // 0
        {"11111", "00001", "00010", "00100", "01000", "01000", "01000"},  // 7
    };
    const glm::vec3 paper(0.92f, 0.88f, 0.78f), ink(0.55f, 0.08f, 0.08f), blue(0.14f, 0.22f, 0.5f);
    if (u < 0.03f || u > 0.97f || v < 0.06f || v > 0.94f) return blue;  // the frame
    if (v > 0.13f && v < 0.25f && u > 0.08f && u < 0.92f) return blue;  // a bar along the top
    if (u > 0.08f && u < 0.14f && v > 0.78f && v < 0.88f) return {0.8f, 0.1f, 0.1f};  // bottom left
    // 6 glyphs of 5 x 7 pixels with a pixel between: 35 pixels over 0.8 of the width, square
    const float pixel = 0.8f / 35.0f;
    const int column = int(std::floor((u - 0.1f) / pixel));
    const int row = int(std::floor((v - 0.36f) / (pixel * 2.0f)));
    if (column >= 0 && column < 35 && row >= 0 && row < 7 && column % 6 < 5 &&
        glyphs[column / 6][row][column % 6] == '1') {
        return ink;
    }
    return paper;
}

// The label's texture: the look above stored where the transform will fetch it (T R S maps the
// quad's uv into the image), magenta stripes everywhere else.
Image labelColor() {
    const float c = std::cos(kLabelRotation), s = std::sin(kLabelRotation);
    return makeImage(256, 3, [&](int x, int y) {
        const glm::vec2 image((float(x) + 0.5f) / 256.0f, (float(y) + 0.5f) / 256.0f);
        const glm::vec2 d = image - kLabelOffset;
        const glm::vec2 uv = glm::vec2(c * d.x - s * d.y, s * d.x + c * d.y) / kLabelScale;
        if (uv.x < -0.015f || uv.x > 1.015f || uv.y < -0.015f || uv.y > 1.015f) {
            return (x + y) % 16 < 8 ? glm::vec4(0.9f, 0.0f, 0.8f, 1.0f) : glm::vec4(0, 0, 0, 1);
        }
        return glm::vec4(labelLook(std::clamp(uv.x, 0.0f, 1.0f), std::clamp(uv.y, 0.0f, 1.0f)),
                         1.0f);
    });
}

// --- the document --------------------------------------------------------------------------

glm::quat yaw(float degrees) {
    return glm::angleAxis(glm::radians(degrees), glm::vec3(0, 1, 0));
}

// The rotation that turns a light's -Z onto `direction`.
glm::quat aim(glm::vec3 direction) {
    const glm::vec3 from(0.0f, 0.0f, -1.0f), to = glm::normalize(direction);
    const glm::vec3 axis = glm::cross(from, to);
    return glm::normalize(glm::quat(1.0f + glm::dot(from, to), axis.x, axis.y, axis.z));
}

// Sampler indices.
enum Sampler { kPixelArt, kRepeat, kClamp, kMirror };

struct Asset {
    gltf::Buffer buffer;
    std::vector<std::string> nodes, meshes, materials, textures, images;
    pbr::OutputBatch files;
    fs::path dir;

    int texture(const std::string& name, const Image& image, Sampler sampler) {
        const std::string file = "pbr_showcase_" + name + ".png";
        files.add(dir / file, pbr::encodePng(image, pbr::PngEncoding::Small));
        images.push_back("{\"uri\":" + quoted(file) + "}");
        textures.push_back("{\"sampler\":" + std::to_string(int(sampler)) +
                           ",\"source\":" + std::to_string(images.size() - 1) + "}");
        return int(textures.size()) - 1;
    }
    int material(const std::string& json) {
        materials.push_back(json);
        return int(materials.size()) - 1;
    }
    // A mesh of one primitive (from addPrimitive) and the node that places it.
    void object(const std::string& name, const std::string& primitive, int material,
                glm::vec3 translation, glm::quat turn = glm::quat(1, 0, 0, 0)) {
        meshes.push_back("{\"name\":" + quoted(name) + ",\"primitives\":[" + primitive +
                         ",\"material\":" + std::to_string(material) + "}]}");
        std::string node =
            "{\"name\":" + quoted(name) + ",\"mesh\":" + std::to_string(meshes.size() - 1);
        if (turn != glm::quat(1, 0, 0, 0)) node += ",\"rotation\":" + rotation(turn);
        if (translation != glm::vec3(0.0f)) node += ",\"translation\":" + vec(translation);
        nodes.push_back(node + "}");
    }
};

std::string textureInfo(int index, const std::string& extra = "") {
    return "{\"index\":" + std::to_string(index) + extra + "}";
}

}  // namespace

int main(int argc, char** argv) try {
    if (argc != 2) throw pbr::UsageError("no output folder", "usage: make_pbr_showcase OUT_DIR\n");
    Asset asset;
    asset.dir = argv[1];
    fs::create_directories(asset.dir);

    // Ten spheres, one geometry: metals on top, dielectrics below, roughness rising to the right.
    const std::string spherePrimitive = asset.buffer.addPrimitive(gltf::gridSphere(0.4f));
    const int roughnessBytes[5] = {0, 64, 128, 191, 255};
    for (int row = 0; row < 2; ++row) {
        const bool metal = row == 0;
        for (int i = 0; i < 5; ++i) {
            const std::string name =
                std::string(metal ? "sphere_metal_" : "sphere_dielectric_") + std::to_string(i);
            Image mr{4, 4, 3, {}};
            for (int texel = 0; texel < 16; ++texel) {
                mr.pixels.insert(mr.pixels.end(), {0, std::uint8_t(roughnessBytes[i]),
                                                   std::uint8_t(metal ? 255 : 0)});
            }
            const int mrTexture = asset.texture(name + "_mr", mr, kRepeat);
            const glm::vec4 base =
                metal ? glm::vec4(1.0f, 0.766f, 0.336f, 1.0f) : glm::vec4(0.8f, 0.1f, 0.1f, 1.0f);
            const int material =
                asset.material("{\"name\":" + quoted(name) +
                               ",\"pbrMetallicRoughness\":{\"baseColorFactor\":" + vec(base) +
                               ",\"metallicFactor\":1,\"roughnessFactor\":1" +
                               ",\"metallicRoughnessTexture\":" + textureInfo(mrTexture) + "}}");
            asset.object(name, spherePrimitive, material,
                         {float(i - 2), metal ? 1.5f : 0.5f, 0.0f});
        }
    }

    // The floor: pixel-art colour, tile normals with the file's tangents.
    {
        const MeshData floor = sheet(
            1, 1,
            [](float s, float t) { return glm::vec3(-3.5f + 7.0f * s, 0.0f, 2.0f - 4.0f * t); },
            {3.5f, 2.0f}, true);
        const int color = asset.texture("floor_color", floorColor(), kPixelArt);
        const int normal = asset.texture("floor_normal", normalMap(floorHeight(), 0.005f), kRepeat);
        const int material =
            asset.material("{\"name\":\"floor\",\"pbrMetallicRoughness\":{\"baseColorTexture\":" +
                           textureInfo(color) + ",\"metallicFactor\":0,\"roughnessFactor\":0.7}" +
                           ",\"normalTexture\":" + textureInfo(normal) + "}");
        asset.object("floor", asset.buffer.addPrimitive(floor), material, {0.0f, 0.0f, 0.0f});
    }

    // The tile panel: every texture slot, tangents, a second uv set for the occlusion.
    {
        const MeshData box = panelBox({0.65f, 0.65f, 0.08f});
        const PanelMaps maps = panelMaps();
        const int color = asset.texture("panel_color", maps.color, kRepeat);
        const int mr = asset.texture("panel_mr", maps.metallicRoughness, kRepeat);
        const int normal = asset.texture("panel_normal", maps.normal, kRepeat);
        const int occlusion = asset.texture("panel_occlusion", maps.occlusion, kClamp);
        const int emissive = asset.texture("panel_emissive", maps.emissive, kRepeat);
        const int material = asset.material(
            "{\"name\":\"tile_panel\",\"pbrMetallicRoughness\":{\"baseColorTexture\":" +
            textureInfo(color) + ",\"metallicRoughnessTexture\":" + textureInfo(mr) +
            "},\"normalTexture\":" + textureInfo(normal, ",\"scale\":0.8") +
            ",\"occlusionTexture\":" + textureInfo(occlusion, ",\"texCoord\":1,\"strength\":0.9") +
            ",\"emissiveTexture\":" + textureInfo(emissive) +
            ",\"emissiveFactor\":" + vec(glm::vec3(1.0f, 0.9f, 0.8f)) + "}");
        asset.object("tile_panel", asset.buffer.addPrimitive(box), material, {0.0f, 3.0f, -0.8f});
    }

    // The leaf: folded along its rib, its tip curling; turned so that its back faces +Z.
    {
        const MeshData leaf = sheet(4, 6, [](float s, float t) {
            const float across = 2.0f * s - 1.0f;
            return glm::vec3(0.45f * across, 1.2f * (t - 0.5f),
                             0.07f * (1.0f - across * across) + 0.12f * t * t);
        });
        const int color = asset.texture("leaf_color", leafColor(), kClamp);
        const int material =
            asset.material("{\"name\":\"leaf\",\"pbrMetallicRoughness\":{\"baseColorTexture\":" +
                           textureInfo(color) + ",\"metallicFactor\":0,\"roughnessFactor\":0.55}" +
                           ",\"alphaMode\":\"MASK\",\"alphaCutoff\":0.4,\"doubleSided\":true}");
        const glm::quat turn =
            yaw(200.0f) * glm::angleAxis(glm::radians(15.0f), glm::vec3(0.0f, 0.0f, 1.0f));
        asset.object("leaf", asset.buffer.addPrimitive(leaf), material, {-2.4f, 3.0f, -0.6f}, turn);
    }

    // The ribbon: 0.6 m wide, 1.5 m tall, half a twist about its wavy centre line; vertex colours.
    {
        MeshData ribbon =
            sheet(8, 48,
                  [](float s, float t) {
                      const float twist = kPi * t;
                      const glm::vec3 centre(0.12f * std::sin(2.0f * kPi * t), 1.5f * t,
                                             0.1f * std::sin(kPi * t));
                      return centre + 0.3f * (2.0f * s - 1.0f) *
                                          glm::vec3(std::cos(twist), 0.0f, -std::sin(twist));
                  },
                  {1.0f, 2.5f});
        for (const glm::vec3& p : ribbon.positions) {
            const float t = p.y / 1.5f;
            ribbon.colors.push_back(glm::vec4(
                glm::mix(glm::vec3(1.0f, 0.45f, 0.2f), glm::vec3(0.2f, 0.55f, 1.0f), t), 1.0f));
        }
        const int color = asset.texture("ribbon_color", ribbonColor(), kMirror);
        const int material =
            asset.material("{\"name\":\"ribbon\",\"pbrMetallicRoughness\":{\"baseColorFactor\":" +
                           vec(glm::vec4(0.95f, 0.95f, 0.9f, 1.0f)) + ",\"baseColorTexture\":" +
                           textureInfo(color) + ",\"metallicFactor\":0,\"roughnessFactor\":0.45}" +
                           ",\"doubleSided\":true}");
        asset.object("ribbon", asset.buffer.addPrimitive(ribbon), material, {-1.2f, 2.25f, -0.6f});
    }

    // The glass pane, blended, in front of the panel's right edge.
    {
        const MeshData pane = sheet(1, 1, [](float s, float t) {
            return glm::vec3(0.9f * (s - 0.5f), 1.0f * (t - 0.5f), 0.0f);
        });
        const int color = asset.texture("pane_color", paneColor(), kClamp);
        const int material = asset.material(
            "{\"name\":\"glass_pane\",\"pbrMetallicRoughness\":{\"baseColorFactor\":" +
            vec(glm::vec4(0.6f, 0.85f, 1.0f, 0.7f)) +
            ",\"baseColorTexture\":" + textureInfo(color) +
            ",\"metallicFactor\":0,\"roughnessFactor\":0.05}" + ",\"alphaMode\":\"BLEND\"}");
        asset.object("glass_pane", asset.buffer.addPrimitive(pane), material,
                     {0.75f, 3.0f, -0.25f});
    }

    // The label, readable only through its texture transform.
    {
        const MeshData label = sheet(1, 1, [](float s, float t) {
            return glm::vec3(1.0f * (s - 0.5f), 0.5f * (t - 0.5f), 0.0f);
        });
        const int color = asset.texture("label_color", labelColor(), kClamp);
        const std::string transform =
            ",\"extensions\":{\"KHR_texture_transform\":{\"offset\":" +
            gltf::numbers({kLabelOffset.x, kLabelOffset.y}) +
            ",\"rotation\":" + gltf::number(kLabelRotation) +
            ",\"scale\":" + gltf::numbers({kLabelScale.x, kLabelScale.y}) + "}}";
        const int material = asset.material(
            "{\"name\":\"label\",\"pbrMetallicRoughness\":{\"baseColorTexture\":" +
            textureInfo(color, transform) + ",\"metallicFactor\":0,\"roughnessFactor\":0.5}}");
        asset.object("label", asset.buffer.addPrimitive(label), material, {1.95f, 3.0f, -0.6f},
                     yaw(-15.0f));
    }

    // The lights (KHR_lights_punctual): intensities in candela (point, spot) and lux (directional).
    const std::vector<std::string> lights = {
        "{\"name\":\"point_light\",\"type\":\"point\",\"color\":" +
            vec(glm::vec3(1.0f, 0.85f, 0.7f)) + ",\"intensity\":20,\"range\":2.2}",
        "{\"name\":\"spot_light\",\"type\":\"spot\",\"color\":" +
            vec(glm::vec3(0.75f, 0.85f, 1.0f)) +
            ",\"intensity\":60,\"spot\":{\"innerConeAngle\":0.3,\"outerConeAngle\":0.4}}",
        "{\"name\":\"fill_light\",\"type\":\"directional\",\"color\":[1,1,1],\"intensity\":1.5}",
    };
    const glm::vec3 pointAt(-1.5f, 1.6f, 1.2f), spotAt(1.6f, 2.6f, 1.8f);
    const glm::quat spotTurn = aim(glm::vec3(1.6f, 0.0f, 1.0f) - spotAt);
    const glm::quat fillTurn = aim({0.4f, -0.6f, -0.7f});
    asset.nodes.push_back("{\"name\":\"point_light\",\"translation\":" + vec(pointAt) +
                          ",\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}}");
    asset.nodes.push_back("{\"name\":\"spot_light\",\"rotation\":" + rotation(spotTurn) +
                          ",\"translation\":" + vec(spotAt) +
                          ",\"extensions\":{\"KHR_lights_punctual\":{\"light\":1}}}");
    asset.nodes.push_back("{\"name\":\"fill_light\",\"rotation\":" + rotation(fillTurn) +
                          ",\"extensions\":{\"KHR_lights_punctual\":{\"light\":2}}}");

    std::vector<std::string> roots;
    for (size_t i = 0; i < asset.nodes.size(); ++i) roots.push_back(std::to_string(i));
    const char* line = ",\n";
    std::vector<std::pair<std::string, std::string>> members = {
        {"asset",
         "{\"version\":\"2.0\",\"generator\":\"pbr-samples resources/models/make_pbr_showcase\"}"},
        {"extensionsUsed", "[\"KHR_lights_punctual\",\"KHR_texture_transform\"]"},
        {"extensions", "{\"KHR_lights_punctual\":{\"lights\":" + gltf::array(lights, line) + "}}"},
        {"scene", "0"},
        {"scenes", "[{\"name\":\"pbr_showcase\",\"nodes\":" + gltf::array(roots) + "}]"},
        {"nodes", gltf::array(asset.nodes, line)},
        {"meshes", gltf::array(asset.meshes, line)},
        {"materials", gltf::array(asset.materials, line)},
        {"textures", gltf::array(asset.textures, line)},
        {"samplers",
         gltf::array({"{\"magFilter\":9728,\"minFilter\":9987,\"wrapS\":10497,\"wrapT\":10497}",
                      "{\"magFilter\":9729,\"minFilter\":9987,\"wrapS\":10497,\"wrapT\":10497}",
                      "{\"magFilter\":9729,\"minFilter\":9987,\"wrapS\":33071,\"wrapT\":33071}",
                      "{\"magFilter\":9729,\"minFilter\":9987,\"wrapS\":33648,\"wrapT\":33648}"},
                     line)},
        {"images", gltf::array(asset.images, line)},
    };
    for (auto& member : asset.buffer.members("pbr_showcase.bin")) members.push_back(member);
    asset.files.add(asset.dir / "pbr_showcase.bin", asset.buffer.bytes());
    asset.files.add(asset.dir / "pbr_showcase.gltf", gltf::document(members));
    asset.files.commit();
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
