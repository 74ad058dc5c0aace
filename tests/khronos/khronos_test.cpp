// The Khronos glTF Sample Viewer (npm @khronosgroup/gltf-viewer 1.1.0, WebGL 2 in headless
// Chromium on SwiftShader) as a reference for samples 07, 08 and 10: the same glTF file, camera,
// lights and output size drawn by both, compared pixel by pixel (see ../../shared/DESIGN.md, "The
// Khronos glTF Sample Viewer as a reference", and tests/khronos/render_viewer.js).
//
// Both sides: IBL off (but in ImageBasedLightMatchesTheSampleViewer: an environment alone), the
// file's KHR_lights_punctual lights (or, for a file without any, the one directional light 07
// adds: pbr::defaultLight()), tone mapping none, exposure 1, no MSAA, no anisotropic filtering,
// the background linear 0.02 grey. One encoding for the comparison: the
// viewer writes pow(linear, 1/2.2), ours the exact sRGB curve, so the viewer's bytes go back to
// linear by pow(2.2) and out again by the sRGB curve (round trip worth a level at most).
// Pixels next to a silhouette (a pixel whose 3 x 3 neighbourhood holds both background and
// object, in either picture) are left out: two rasterizers (llvmpipe, SwiftShader) place edge
// pixels differently by a pixel. What is left out is counted and printed.
//
// Known deliberate differences are named per case, not hidden by a loose gate:
//   - display encoding: undone as above, in every case;
//   - spec-gloss (08): we keep the archived extension's c_diff = diffuse x (1 - max(specular));
//     the viewer drops that factor, so its diffuse is scaled by it here (per case, by name);
//   - BLEND: we blend in linear light, the viewer in display space (pow(1/2.2) bytes): blended
//     cases carry their own, lower, measured gate;
//   - highlight clamp: we keep alpha = roughness^2 >= 0.002 (a point light shows on a mirror); no
//     test file of ours has roughness 0, and the assets' mirror spheres are named where they
//     matter;
//   - image-based light (ImageBasedLightMatchesTheSampleViewer alone): the viewer's
//     roughness-dependent Fresnel on the split sum's scale, mended in what it is served; the
//     multiple-scattering share, which it lights by the prefiltered map and we by the irradiance,
//     left out on both sides but where the environment is constant.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "base/paths.h"
#include "files/image.h"
#include "files/ktx.h"
#include "gl/mesh.h"
#include "gltf/gltf_renderer.h"
#include "gltf/model.h"
#include "ibl/ibl_cache.h"
#include "math/camera.h"
#include "reference/linear_sky.h"
#include "support/build_paths.h"
#include "support/gltf_scene.h"
#include "support/process.h"
#include "support/test_data.h"
#include "support/web_page.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

constexpr float kClearLinear = 0.02f;  // 07's background without IBL (common/gltf/gltf_viewer.cpp)

fs::path viewerPackage() {
    return fs::path(PBR_PATH(PBR_NODE_TOOLS_DIR)) / "node_modules" / "@khronosgroup" /
           "gltf-viewer";
}

// Why the viewer cannot run here, or nullopt.
std::optional<std::string> viewerUnavailable() {
    if (!nodeOnPath())
        return "no node on PATH: it drives the browser (tests/khronos/render_viewer.js)";
    if (!chromiumOnPath()) {
        return "no chromium-headless-shell (or chromium) on PATH (./build.sh test installs "
               "Debian's "
               "chromium-headless-shell)";
    }
    std::error_code ec;
    if (!fs::exists(viewerPackage() / "dist" / "gltf-viewer.module.js", ec)) {
        return "the Khronos glTF Sample Viewer is not installed in " + viewerPackage().string() +
               " (./build.sh test installs @khronosgroup/gltf-viewer@1.1.0 with npm)";
    }
    return std::nullopt;
}

#define PBR_NEED_VIEWER() \
    if (const auto why = viewerUnavailable()) GTEST_SKIP() << *why

// --- the test's own glTF files
// --------------------------------------------------------------------

// A texture with an orientation: four coloured quadrants on a grey cross, each 8 x 8 texels of a
// 32 x 32 image, so offset, rotation, scale and the texture coordinate set all show.
Image quadrantTexture() {
    Image image{32, 32, 4, std::vector<std::uint8_t>(32 * 32 * 4)};
    const std::uint8_t colours[4][3] = {
        {220, 40, 30}, {40, 200, 60}, {40, 70, 220}, {230, 210, 40}};
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
            const int q = (y < 16 ? 0 : 2) + (x < 16 ? 0 : 1);
            const bool cross = (x % 16) < 2 || (y % 16) < 2;
            std::uint8_t* p = &image.pixels[size_t(y * 32 + x) * 4];
            for (int c = 0; c < 3; ++c) p[c] = cross ? 128 : colours[q][c];
            // a small notch marks each quadrant's top-left corner
            if (x % 16 >= 3 && x % 16 < 7 && y % 16 >= 3 && y % 16 < 7) p[0] = p[1] = p[2] = 250;
            p[3] = 255;
        }
    }
    return image;
}

// A tangent-space normal map of smooth bumps (x and y tilted by sines).
Image bumpNormalTexture() {
    Image image{64, 64, 4, std::vector<std::uint8_t>(64 * 64 * 4)};
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            const double u = (x + 0.5) / 64, v = (y + 0.5) / 64;
            glm::dvec3 n(0.5 * std::sin(2 * M_PI * 2 * u), 0.5 * std::sin(2 * M_PI * v), 1.0);
            n = glm::normalize(n);
            std::uint8_t* p = &image.pixels[size_t(y * 64 + x) * 4];
            for (int c = 0; c < 3; ++c) p[c] = std::uint8_t(std::lround((n[c] * 0.5 + 0.5) * 255));
            p[3] = 255;
        }
    }
    return image;
}

// Solid left half, solid right half: channel values per half (RGBA).
Image halvesTexture(std::array<std::uint8_t, 4> left, std::array<std::uint8_t, 4> right) {
    Image image{16, 16, 4, std::vector<std::uint8_t>(16 * 16 * 4)};
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < 4; ++c)
                image.pixels[size_t(y * 16 + x) * 4 + c] = (x < 8 ? left : right)[c];
    return image;
}

// Alpha rising left to right (0 to 1), colour white.
Image alphaRampTexture() {
    Image image{32, 4, 4, std::vector<std::uint8_t>(32 * 4 * 4, 255)};
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 32; ++x)
            image.pixels[size_t(y * 32 + x) * 4 + 3] = std::uint8_t(x * 255 / 31);
    return image;
}

// A square from -h to h in x and y at depth z, facing +Z (TEXCOORD_0 upright seen from +Z,
// TEXCOORD_1 = TEXCOORD_0 / 2), with optional per-corner colours; returns the "attributes" JSON.
std::string squareAttributes(GltfBufferBuilder& b, float h, float z, bool normals = true,
                             const std::vector<float>& colours = {}) {
    const std::vector<float> positions = {-h, -h, z, h, -h, z, h, h, z, -h, h, z};
    std::string json = "\"POSITION\":" + std::to_string(b.floats(positions, "VEC3", true));
    if (normals) {
        json +=
            ",\"NORMAL\":" + std::to_string(b.floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3"));
    }
    json += ",\"TEXCOORD_0\":" + std::to_string(b.floats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2"));
    json +=
        ",\"TEXCOORD_1\":" + std::to_string(b.floats({0, 0.5f, 0.5f, 0.5f, 0.5f, 0, 0, 0}, "VEC2"));
    if (!colours.empty()) json += ",\"COLOR_0\":" + std::to_string(b.floats(colours, "VEC4"));
    return json;
}

// A sphere of radius r at `centre` (48 x 32 segments, smooth normals, TEXCOORD_0 = the sphere's
// uv); returns the "attributes" JSON and sets `indices` to its index accessor.
std::string sphereAttributes(GltfBufferBuilder& b, glm::vec3 centre, float r, int& indices) {
    const MeshData sphere = uvSphereTriangles(48, 32);
    std::vector<float> positions, normals, uvs;
    for (size_t i = 0; i < sphere.positions.size(); ++i) {
        const glm::vec3 p = centre + r * sphere.positions[i], n = sphere.normals[i];
        positions.insert(positions.end(), {p.x, p.y, p.z});
        normals.insert(normals.end(), {n.x, n.y, n.z});
        uvs.insert(uvs.end(), {sphere.uvs[i].x, sphere.uvs[i].y});
    }
    indices = b.indices(std::vector<std::uint16_t>(sphere.indices.begin(), sphere.indices.end()));
    return "\"POSITION\":" + std::to_string(b.floats(positions, "VEC3", true)) +
           ",\"NORMAL\":" + std::to_string(b.floats(normals, "VEC3")) +
           ",\"TEXCOORD_0\":" + std::to_string(b.floats(uvs, "VEC2"));
}

std::string primitive(const std::string& attributes, int indices, int material) {
    return "{\"attributes\":{" + attributes + "},\"indices\":" + std::to_string(indices) +
           ",\"material\":" + std::to_string(material) + "}";
}

// A light node's rotation: -Z turned onto `direction`.
std::string rotationTowards(glm::vec3 direction) {
    const glm::vec3 from(0, 0, -1), to = glm::normalize(direction);
    const glm::vec3 axis = glm::cross(from, to);
    glm::vec4 q(axis, 1.0f + glm::dot(from, to));  // x, y, z, w: half the angle from -Z to `to`
    if (q.w < 1e-6f) q = glm::vec4(0, 1, 0, 0);    // straight back: half a turn about Y
    q = glm::normalize(q);
    std::ostringstream out;
    out << "[" << q.x << "," << q.y << "," << q.z << "," << q.w << "]";
    return out.str();
}

struct Light {
    std::string json;  // the light object
    std::string node;  // "translation"/"rotation" members of its node
};
Light directional(glm::vec3 direction, float lux) {
    return {R"({"type":"directional","intensity":)" + std::to_string(lux) + "}",
            "\"rotation\":" + rotationTowards(direction)};
}
Light point(glm::vec3 at, float candela, float range = 0) {
    return {R"({"type":"point","intensity":)" + std::to_string(candela) +
                (range > 0 ? ",\"range\":" + std::to_string(range) : "") + "}",
            "\"translation\":[" + std::to_string(at.x) + "," + std::to_string(at.y) + "," +
                std::to_string(at.z) + "]"};
}
Light spot(glm::vec3 at, glm::vec3 direction, float candela, float inner, float outer) {
    return {R"({"type":"spot","intensity":)" + std::to_string(candela) +
                R"(,"spot":{"innerConeAngle":)" + std::to_string(inner) +
                ",\"outerConeAngle\":" + std::to_string(outer) + "}}",
            "\"translation\":[" + std::to_string(at.x) + "," + std::to_string(at.y) + "," +
                std::to_string(at.z) + "],\"rotation\":" + rotationTowards(direction)};
}

// One glTF file: the meshes' primitives (one mesh, one node each), materials, textures (written
// as PNG files beside it, each with a LINEAR / LINEAR_MIPMAP_LINEAR, REPEAT sampler), lights.
struct SceneFile {
    GltfBufferBuilder buffer;
    std::vector<std::string> primitives, materials;
    std::vector<Image> textures;
    std::vector<Light> lights;
    std::vector<std::string> extensions;

    fs::path write(const fs::path& dir, const std::string& name) const {
        std::string images, textureList, nodes, meshes, lightList, sceneNodes;
        for (size_t i = 0; i < textures.size(); ++i) {
            const std::string file = name + "_" + std::to_string(i) + ".png";
            writePng(dir / file, textures[i]);
            images += (i ? "," : "") + std::string("{\"uri\":\"") + file + "\"}";
            textureList += (i ? "," : "") + std::string("{\"sampler\":0,\"source\":") +
                           std::to_string(i) + "}";
        }
        int node = 0;
        for (size_t i = 0; i < primitives.size(); ++i, ++node) {
            meshes += (i ? "," : "") + std::string("{\"primitives\":[") + primitives[i] + "]}";
            nodes += (node ? "," : "") + std::string("{\"mesh\":") + std::to_string(i) + "}";
            sceneNodes += (node ? "," : "") + std::to_string(node);
        }
        for (size_t i = 0; i < lights.size(); ++i, ++node) {
            lightList += (i ? "," : "") + lights[i].json;
            nodes += ",{" + lights[i].node + R"(,"extensions":{"KHR_lights_punctual":{"light":)" +
                     std::to_string(i) + "}}}";
            sceneNodes += "," + std::to_string(node);
        }
        std::vector<std::string> used = extensions;
        if (!lights.empty()) used.push_back("KHR_lights_punctual");
        std::string usedJson;
        for (const std::string& e : used) usedJson += (usedJson.empty() ? "\"" : ",\"") + e + "\"";
        std::string json = "{\"asset\":{\"version\":\"2.0\"},\n" + buffer.json();
        if (!usedJson.empty()) json += "\"extensionsUsed\":[" + usedJson + "],\n";
        if (!textures.empty()) {
            json +=
                R"("samplers":[{"magFilter":9729,"minFilter":9987,"wrapS":10497,"wrapT":10497}],)";
            json += "\"images\":[" + images + "],\"textures\":[" + textureList + "],\n";
        }
        std::string materialList;
        for (size_t i = 0; i < materials.size(); ++i)
            materialList += (i ? ",\n" : "") + materials[i];
        json += "\"materials\":[" + materialList + "],\n\"meshes\":[" + meshes + "],\n\"nodes\":[" +
                nodes + "],\n\"scenes\":[{\"nodes\":[" + sceneNodes + "]}],\"scene\":0";
        if (!lights.empty()) {
            json += ",\n\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[" + lightList + "]}}";
        }
        return writeTextFile(dir, name + ".gltf", json + "}\n");
    }
};

// A lit, textured square seen from the front, the texture through `textureInfo` (the base
// colour's "baseColorTexture" members, e.g. a KHR_texture_transform).
fs::path texturedSquare(const fs::path& dir, const std::string& name,
                        const std::string& textureInfo) {
    SceneFile s;
    const std::string attributes = squareAttributes(s.buffer, 1.0f, 0.0f);
    const int indices = s.buffer.indices({0, 1, 2, 0, 2, 3});
    s.primitives.push_back(primitive(attributes, indices, 0));
    s.materials.push_back(R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0)" +
                          textureInfo + R"(},"metallicFactor":0,"roughnessFactor":0.7}})");
    s.textures.push_back(quadrantTexture());
    s.lights.push_back(directional({-0.3f, -0.4f, -1.0f}, 2.5f));
    s.extensions.push_back("KHR_texture_transform");
    return s.write(dir, name);
}

// One square of one material under a point light in front and a directional light.
fs::path plainSquare(const fs::path& dir, const std::string& name, const std::string& material,
                     std::vector<Image> textures = {}, std::vector<float> colours = {}) {
    SceneFile s;
    const std::string attributes = squareAttributes(s.buffer, 1.0f, 0.0f, true, colours);
    const int indices = s.buffer.indices({0, 1, 2, 0, 2, 3});
    s.primitives.push_back(primitive(attributes, indices, 0));
    s.materials.push_back(material);
    s.textures = std::move(textures);
    s.lights.push_back(point({0.4f, 0.5f, 1.2f}, 3.0f));
    s.lights.push_back(directional({-0.3f, -0.4f, -1.0f}, 1.0f));
    return s.write(dir, name);
}

// --- one case: both renderers, one comparison
// -------------------------------------------------------

struct Case {
    std::string name;
    std::string sample;  // "07_gltf_metallic_roughness" or "08_gltf_specular_glossiness"
    fs::path gltf;
    glm::vec3 eye;
    int width = 192, height = 144;
    double minPsnr;  // the gate, from measurement (see each case)
    int maxWorst;    // largest channel difference allowed, 0..255
    // Pixels more than 8 levels apart allowed (for the assets, whose worst pixel lies in a named
    // difference: a BLEND pane, a roughness-0 highlight); -1: not gated, maxWorst is.
    int maxOver8 = -1;
    // Spec-gloss: the factor (1 - max specular) we keep on the diffuse and the viewer drops,
    // applied to the viewer's linear values (a diffuse-only surface: see the case).
    float viewerDiffuseScale = 1.0f;
    // The objects fill the view: under image-based light, no picture of ours with neither light
    // is needed to tell them from the environment behind.
    bool filled = false;
};

struct Comparison {
    double psnr = 0;
    int worst = 0;
    size_t compared = 0, edges = 0, over8 = 0;
};

double srgbEncode(double linear) {
    linear = std::clamp(linear, 0.0, 1.0);
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
}

// The viewer's pow(1/2.2) bytes as exact-sRGB bytes (after an optional linear scale).
Image viewerAsSrgb(const Image& viewer, float scale) {
    Image out = viewer;
    for (size_t i = 0; i < out.pixels.size(); ++i) {
        if (out.channels == 4 && i % 4 == 3) continue;
        const double linear = std::pow(viewer.pixels[i] / 255.0, 2.2) * scale;
        out.pixels[i] = std::uint8_t(std::lround(srgbEncode(linear) * 255));
    }
    return out;
}

// `mask`: where the objects are, told from the background grey (the pictures themselves
// otherwise): a picture of ours with neither light, where the environment is drawn behind them;
// then only the objects are compared (the environment behind them is not what is tested).
Comparison compare(const Image& ours, const Image& viewer, Image& diff,
                   const Image* mask = nullptr) {
    const int w = ours.width, h = ours.height;
    const std::uint8_t bg = std::uint8_t(std::lround(srgbEncode(kClearLinear) * 255));
    auto covered = [&](const Image& im, int x, int y) {
        for (int c = 0; c < 3; ++c)
            if (std::abs(int(im.at(x, y, c)) - int(bg)) > 1) return true;
        return false;
    };
    std::vector<const Image*> outlines = {&ours, &viewer};
    if (mask) outlines = {mask};
    Comparison r;
    double squared = 0;
    diff = Image{w, h, 3, std::vector<std::uint8_t>(size_t(w) * size_t(h) * 3, 0)};
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            bool edge = false;
            for (const Image* im : outlines) {
                const bool centre = covered(*im, x, y);
                for (int dy = -1; dy <= 1 && !edge; ++dy)
                    for (int dx = -1; dx <= 1 && !edge; ++dx) {
                        const int nx = std::clamp(x + dx, 0, w - 1),
                                  ny = std::clamp(y + dy, 0, h - 1);
                        edge = covered(*im, nx, ny) != centre;
                    }
            }
            if (edge) {
                ++r.edges;
                diff.pixels[(size_t(y) * w + x) * 3 + 2] = 60;  // left out: dark blue
                continue;
            }
            if (mask && !covered(*mask, x, y)) continue;  // the environment behind
            ++r.compared;
            int pixelWorst = 0;
            for (int c = 0; c < 3; ++c) {
                const int d = std::abs(int(ours.at(x, y, c)) - int(viewer.at(x, y, c)));
                squared += double(d) * d;
                pixelWorst = std::max(pixelWorst, d);
                diff.pixels[(size_t(y) * w + x) * 3 + c] = std::uint8_t(std::min(255, d * 8));
            }
            r.worst = std::max(r.worst, pixelWorst);
            if (pixelWorst > 8) ++r.over8;
        }
    }
    const double mse = squared / (3.0 * double(std::max<size_t>(r.compared, 1)));
    r.psnr = mse == 0 ? 99.0 : 10 * std::log10(255.0 * 255.0 / mse);
    return r;
}

std::string vec(glm::vec3 v) {
    std::ostringstream out;
    out.precision(9);
    out << "[" << v.x << "," << v.y << "," << v.z << "]";
    return out.str();
}

struct Lighting {
    // A lut_sheen_E.png for the viewer to apply its sheen albedo scaling with (see
    // render_viewer.js); empty: none (the viewer then never scales).
    fs::path sheenTable = {};
    // An .hdr that lights every case alone, drawn behind it, on both sides; empty: no image-based
    // light, the file's punctual lights (or the default one).
    fs::path environment = {};
    // With the environment: both without the multiple-scattering share (ours by
    // --single-scattering, the viewer's bundle changed as render_viewer.js says).
    bool singleScattering = false;
    // The viewer's filtered cube faces, `cubeFaceSize`^2 (render_viewer.js): 16 for a constant
    // environment, which any size holds exactly.
    int cubeFaceSize = 64;
};

// Draws every case with its sample and, in one browser session, with the viewer; compares them,
// prints one line a case and checks each against its gate.
void runCases(const std::string& suite, const std::vector<Case>& cases,
              const Lighting& lighting = {}) {
    const fs::path dir = testOutputDir("khronos_" + suite);
    const bool ibl = !lighting.environment.empty();
    fs::path environment = lighting.environment;
    if (!ibl) {
        environment = dir / "environment.hdr";  // never lights anything
        writeHdr(environment, HdrImage{32, 16, std::vector<float>(32 * 16 * 3, 0.5f)});
    }

    std::string job = "{\"environment\":\"" + fs::absolute(environment).string() + "\",";
    if (!lighting.sheenTable.empty())
        job += "\"sheenTable\":\"" + fs::absolute(lighting.sheenTable).string() + "\",";
    if (ibl) job += "\"imageBasedLight\":true,";
    if (lighting.singleScattering) job += "\"singleScattering\":true,";
    if (ibl) job += "\"cubeFaceSize\":" + std::to_string(lighting.cubeFaceSize) + ",";
    job += "\"cases\":[";
    for (size_t i = 0; i < cases.size(); ++i) {
        const Case& c = cases[i];
        const Model model = loadModel(c.gltf);
        const OrbitCamera camera =
            OrbitCamera::fromPosition(model.boundsMin, model.boundsMax, c.eye);
        const std::string size = std::to_string(c.width) + "x" + std::to_string(c.height);
        std::ostringstream eye;
        eye << c.eye.x << "," << c.eye.y << "," << c.eye.z;
        auto runOurs = [&](const std::string& file, std::vector<std::string> lights) {
            std::vector<std::string> args = {c.sample,    "--headless",   "--output", file,
                                             "--size",    size,           "--msaa",   "1",
                                             "--tonemap", "none",         "--camera", eye.str(),
                                             "--model",   c.gltf.string()};
            args.insert(args.end(), lights.begin(), lights.end());
            const RunResult ours = runSample(args);
            EXPECT_EQ(ours.exitCode, 0) << c.name << ": " << ours.err;
        };
        if (ibl) {
            std::vector<std::string> flags = {"--hdr", environment.string(), "--no-punctual"};
            if (lighting.singleScattering) flags.push_back("--single-scattering");
            runOurs((dir / (c.name + "_ours.png")).string(), flags);
            if (!c.filled)
                runOurs((dir / (c.name + "_mask.png")).string(), {"--no-ibl", "--no-punctual"});
        } else {
            runOurs((dir / (c.name + "_ours.png")).string(), {"--no-ibl"});
        }
        std::string light;
        // 07's one default light, as the viewer must have it too
        if (model.lights.empty() && !ibl) {
            const PunctualLight fallback = defaultLight();
            light = ",\"defaultLight\":{\"direction\":" + vec(fallback.direction) +
                    ",\"intensity\":" + std::to_string(fallback.color.x) + "}";
        }
        job += (i ? ",\n" : "\n") + std::string("{\"name\":\"") + c.name + "\",\"gltf\":\"" +
               fs::absolute(c.gltf).string() + "\",\"eye\":" + vec(camera.position()) +
               ",\"target\":" + vec(camera.target()) +
               ",\"yfov\":" + std::to_string(glm::radians(OrbitCamera::kFovYDegrees)) +
               ",\"near\":" + std::to_string(camera.nearPlane()) +
               ",\"far\":" + std::to_string(camera.farPlane()) +
               ",\"width\":" + std::to_string(c.width) + ",\"height\":" + std::to_string(c.height) +
               ",\"output\":\"" + (dir / (c.name + "_viewer.png")).string() + "\"" +
               ",\"clear\":" + std::to_string(kClearLinear) + light + "}";
    }
    writeTextFile(dir, "job.json", job + "\n]}\n");

    const RunResult viewer = runSample({nodeOnPath()->string(), PBR_PATH(PBR_KHRONOS_RENDERER),
                                        chromiumOnPath()->string(), viewerPackage().string(),
                                        (dir / "job.json").string(), "240"});
    EXPECT_EQ(viewer.exitCode, 0) << viewer.err;

    std::printf("%-28s %8s %6s %9s %7s %6s   gate\n", "case", "PSNR dB", "worst", "compared",
                "edges", ">8");
    for (const Case& c : cases) {
        const fs::path oursFile = dir / (c.name + "_ours.png"),
                       viewerFile = dir / (c.name + "_viewer.png");
        if (!fs::exists(oursFile) || !fs::exists(viewerFile)) {
            ADD_FAILURE() << c.name << ": no picture ("
                          << (fs::exists(oursFile) ? viewerFile : oursFile) << ")";
            continue;
        }
        const Image ours = readImage(oursFile, 3);
        const Image theirs = viewerAsSrgb(readImage(viewerFile, 3), c.viewerDiffuseScale);
        writePng(dir / (c.name + "_viewer_srgb.png"), theirs);
        Image diff;
        std::optional<Image> mask;
        if (ibl && !c.filled) mask = readImage(dir / (c.name + "_mask.png"), 3);
        const Comparison r = compare(ours, theirs, diff, mask ? &*mask : nullptr);
        writePng(dir / (c.name + "_diff.png"), diff);
        std::printf("%-28s %8.2f %6d %9zu %7zu %6zu   >= %.0f dB, %s <= %d\n", c.name.c_str(),
                    r.psnr, r.worst, r.compared, r.edges, r.over8, c.minPsnr,
                    c.maxOver8 >= 0 ? ">8" : "worst", c.maxOver8 >= 0 ? c.maxOver8 : c.maxWorst);
        EXPECT_GE(r.psnr, c.minPsnr) << c.name << ": PSNR " << r.psnr << " dB (worst " << r.worst
                                     << "); pictures in " << dir;
        if (c.maxOver8 >= 0) {
            EXPECT_LE(r.over8, size_t(c.maxOver8))
                << c.name << ": " << r.over8 << " pixels more than 8 levels apart (PSNR " << r.psnr
                << " dB); pictures in " << dir;
            continue;
        }
        EXPECT_LE(r.worst, c.maxWorst) << c.name << ": worst channel difference " << r.worst
                                       << " (PSNR " << r.psnr << " dB); pictures in " << dir;
    }
    std::fflush(stdout);
}

const char* k07 = "07_gltf_metallic_roughness";
const char* k08 = "08_gltf_specular_glossiness";

// Gates, from measurement (2026-12-02, llvmpipe 15 vs SwiftShader in chromium-headless-shell 156,
// the table each test prints). The feature files measured 55.99 to 64.88 dB, worst channel 1 to 3
// levels (BLEND: 36.83 dB, worst 17, the named display-space blend); a swapped colour channel on
// these coloured squares or a dropped BRDF term (a highlight, the diffuse) moves pixels by tens
// of levels, far past 6.
constexpr double kFeaturePsnr = 50.0;
constexpr int kFeatureWorst = 6;
TEST(Khronos, FeaturesMatchTheSampleViewer) {
    PBR_NEED_VIEWER();
    const fs::path dir = testOutputDir("khronos_files");
    const glm::vec3 front(0.0f, 0.0f, 3.2f);
    std::vector<Case> cases;
    // A feature case: 07, 192 x 144, the feature gate, seen from `eye`.
    auto feature = [&](const std::string& name, const fs::path& file, glm::vec3 eye) {
        cases.push_back({name, k07, file, eye, 192, 144, kFeaturePsnr, kFeatureWorst});
    };
    // KHR_texture_transform, one property each.
    const std::pair<const char*, const char*> transforms[] = {
        {"tt_offset", R"("offset":[0.25,0.1])"},
        {"tt_rotation", R"("rotation":0.5)"},
        {"tt_scale", R"("scale":[2,1.5])"},
        {"tt_texcoord", R"("texCoord":1)"}};
    for (const auto& [name, property] : transforms) {
        feature(name,
                texturedSquare(
                    dir, name,
                    std::string(R"(,"extensions":{"KHR_texture_transform":{)") + property + "}}"),
                front);
    }
    // Fractional metallic: a factor of 0.5, and a texture border (filtering makes fractions).
    feature(
        "metallic_half",
        plainSquare(
            dir, "metallic_half",
            R"({"pbrMetallicRoughness":{"baseColorFactor":[0.9,0.5,0.2,1],"metallicFactor":0.5,"roughnessFactor":0.4}})"),
        front);
    feature(
        "metal_border",
        plainSquare(
            dir, "metal_border",
            R"({"pbrMetallicRoughness":{"baseColorFactor":[0.9,0.6,0.3,1],"metallicRoughnessTexture":{"index":0}}})",
            {halvesTexture({0, 110, 255, 255}, {0, 110, 0, 255})}),
        front);
    // A primitive without NORMAL: a low pyramid sharing its apex; flat normals per the spec.
    {
        SceneFile s;
        const int pos =
            s.buffer.floats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0, 0, 0, 0.6f}, "VEC3", true);
        const int idx = s.buffer.indices({0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4});
        s.primitives.push_back("{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
                               "},\"indices\":" + std::to_string(idx) + ",\"material\":0}");
        s.materials.push_back(
            R"({"pbrMetallicRoughness":{"baseColorFactor":[0.8,0.8,0.8,1],"metallicFactor":0,"roughnessFactor":0.6}})");
        s.lights.push_back(directional({-0.5f, -0.3f, -1.0f}, 2.5f));
        feature("no_normals", s.write(dir, "no_normals"), front);
    }
    // A normal texture and no TANGENT: both derive the frame from the texture coordinates.
    feature(
        "no_tangents",
        plainSquare(
            dir, "no_tangents",
            R"({"pbrMetallicRoughness":{"baseColorFactor":[0.7,0.7,0.7,1],"metallicFactor":0,"roughnessFactor":0.5},"normalTexture":{"index":0}})",
            {bumpNormalTexture()}),
        front);
    feature(
        "vertex_colors",
        plainSquare(
            dir, "vertex_colors",
            R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],"metallicFactor":0,"roughnessFactor":0.6}})",
            {}, {1, 0.2f, 0.1f, 1, 0.1f, 0.9f, 0.2f, 1, 0.1f, 0.2f, 1, 1, 0.9f, 0.9f, 0.1f, 1}),
        front);
    // The alpha modes: a textured square with alpha rising left to right in front of a red one.
    for (const char* mode : {"OPAQUE", "MASK", "BLEND"}) {
        SceneFile s;
        const std::string back = squareAttributes(s.buffer, 1.0f, -0.4f);
        const int idx = s.buffer.indices({0, 1, 2, 0, 2, 3});
        const std::string front2 = squareAttributes(s.buffer, 0.7f, 0.0f);
        s.primitives.push_back(primitive(back, idx, 0));
        s.primitives.push_back(primitive(front2, idx, 1));
        s.materials.push_back(
            R"({"pbrMetallicRoughness":{"baseColorFactor":[0.8,0.1,0.1,1],"metallicFactor":0,"roughnessFactor":0.7}})");
        s.materials.push_back(
            std::string(R"({"alphaMode":")") + mode +
            R"(","alphaCutoff":0.5,"pbrMetallicRoughness":{"baseColorFactor":[0.2,0.5,0.9,1],"baseColorTexture":{"index":0},"metallicFactor":0,"roughnessFactor":0.7}})");
        s.textures.push_back(alphaRampTexture());
        s.lights.push_back(directional({-0.3f, -0.4f, -1.0f}, 2.5f));
        const std::string name = std::string("alpha_") + mode;
        // BLEND: we blend in linear light, the viewer in display space; measured lower gate.
        const bool blend = std::string(mode) == "BLEND";
        cases.push_back({name, k07, s.write(dir, name), front, 192, 144,
                         blend ? 34.0 : kFeaturePsnr, blend ? 24 : kFeatureWorst});
    }
    // Double-sided, seen from behind (lit from behind); a single-sided square beside it is culled.
    {
        SceneFile s;
        const std::string a = squareAttributes(s.buffer, 0.6f, 0.0f);
        const int idx = s.buffer.indices({0, 1, 2, 0, 2, 3});
        s.primitives.push_back(primitive(a, idx, 0));
        s.materials.push_back(
            R"({"doubleSided":true,"pbrMetallicRoughness":{"baseColorFactor":[0.3,0.8,0.4,1],"baseColorTexture":{"index":0},"metallicFactor":0,"roughnessFactor":0.5}})");
        s.textures.push_back(quadrantTexture());
        s.lights.push_back(directional({0.3f, -0.4f, 1.0f}, 2.5f));
        s.lights.push_back(point({-0.3f, 0.3f, -1.0f}, 2.0f));
        cases.push_back({"double_sided_back",
                         k07,
                         s.write(dir, "double_sided_back"),
                         {0.4f, 0.3f, -3.0f},
                         192,
                         144,
                         kFeaturePsnr,
                         kFeatureWorst});
    }
    // Occlusion: with IBL off it changes nothing on either side (it applies to indirect light).
    feature(
        "occlusion",
        plainSquare(
            dir, "occlusion",
            R"({"pbrMetallicRoughness":{"baseColorFactor":[0.8,0.8,0.8,1],"metallicFactor":0,"roughnessFactor":0.5},"occlusionTexture":{"index":0,"strength":1}})",
            {halvesTexture({40, 40, 40, 255}, {255, 255, 255, 255})}),
        front);
    feature(
        "emissive",
        plainSquare(
            dir, "emissive",
            R"({"pbrMetallicRoughness":{"baseColorFactor":[0.2,0.2,0.2,1],"metallicFactor":0,"roughnessFactor":0.5},"emissiveFactor":[0.8,0.5,0.3],"emissiveTexture":{"index":0}})",
            {quadrantTexture()}),
        front);
    // A spot's cone and a point light's range on a large square, each light alone.
    auto litSquare = [&](const std::string& name, const Light& light) {
        SceneFile s;
        const std::string a = squareAttributes(s.buffer, 2.0f, 0.0f);
        const int idx = s.buffer.indices({0, 1, 2, 0, 2, 3});
        s.primitives.push_back(primitive(a, idx, 0));
        s.materials.push_back(
            R"({"pbrMetallicRoughness":{"baseColorFactor":[0.8,0.8,0.8,1],"metallicFactor":0,"roughnessFactor":0.8}})");
        s.lights.push_back(light);
        feature(name, s.write(dir, name), {0, 0, 6.0f});
    };
    litSquare("spot_cone", spot({0.3f, 0.2f, 2.0f}, {-0.15f, -0.1f, -1.0f}, 12.0f, 0.25f, 0.45f));
    litSquare("point_range", point({0.3f, -0.2f, 0.6f}, 2.0f, 1.5f));
    runCases("features", cases);
}

// An opaque square behind the square of material 0, filling the view from the front (3.2 away):
// material 1, its vertex colours a smooth pattern for a refraction to move, with `textured` the
// quadrant texture repeated 6 x 6 over it (edges for a blur to soften). `indices`: the squares'.
void addBackdrop(SceneFile& s, int indices, bool textured) {
    const std::vector<float> colours = {0.9f, 0.3f, 0.2f, 1, 0.3f, 0.8f, 0.3f, 1,
                                        0.2f, 0.4f, 0.9f, 1, 0.9f, 0.9f, 0.3f, 1};
    s.primitives.push_back(
        primitive(squareAttributes(s.buffer, 3.0f, -0.8f, true, colours), indices, 1));
    s.materials.push_back(R"({"pbrMetallicRoughness":{"baseColorFactor":[0.7,0.6,0.5,1],)" +
                          std::string(textured ? R"("baseColorTexture":{"index":0,"extensions":)"
                                                 R"({"KHR_texture_transform":{"scale":[6,6]}}},)"
                                               : "") +
                          R"("metallicFactor":0,"roughnessFactor":0.5}})");
    if (textured) {
        s.textures.push_back(quadrantTexture());
        s.extensions.push_back("KHR_texture_transform");
    }
}

// The viewer's sheen table from ours, written to dir/lut_sheen_E.png: the A channel of the baked
// sheen LUT (E with Charlie's visibility, the viewer's own D_Charlie and V_Sheen), in the
// viewer's layout (R, x = NdotV, y = sheen roughness, row 0 at y = 0), 8 bits.
fs::path sheenTable(const fs::path& dir) {
    const KtxImage lut = readKtx(iblDir() / "brdf_lut_sheen_256.ktx");
    Image table{lut.width, lut.height, 3, {}};
    for (int y = 0; y < lut.height; ++y) {
        for (int x = 0; x < lut.width; ++x) {
            const float E =
                lutTexel(lut, (x + 0.5f) / float(lut.width), (y + 0.5f) / float(lut.height))
                    .sheenAlbedo;
            const auto byte = std::uint8_t(std::lround(std::clamp(E, 0.0f, 1.0f) * 255.0f));
            table.pixels.insert(table.pixels.end(), {byte, byte, byte});
        }
    }
    writePng(dir / "lut_sheen_E.png", table);
    return dir / "lut_sheen_E.png";
}

// A case gated on PSNR and on the count of pixels more than 8 levels apart (its worst pixel lies
// in a named difference).
Case assetCase(std::string name, const char* sample, fs::path file, glm::vec3 eye, int width,
               int height, double minPsnr, int maxOver8) {
    Case c{std::move(name), sample, std::move(file), eye, width, height, minPsnr, 255};
    c.maxOver8 = maxOver8;
    return c;
}

TEST(Khronos, AssetsMatchTheSampleViewer) {
    PBR_NEED_VIEWER();
    PBR_NEED_ASSIMP_MODELS(corpus);
    std::vector<Case> cases;
    // Measured 42.64 dB, 373 pixels > 8 levels, worst 255: the glass pane (BLEND, blended in
    // display space by the viewer) and the point light's highlight on the roughness-0 mirror
    // sphere (our alpha >= 0.002 clamp; the viewer's delta lobe shows nothing).
    cases.push_back(assetCase("pbr_showcase", k07, modelDir() / "pbr_showcase.gltf",
                              {0.0f, 1.5f, 9.0f}, 320, 180, 40, 600));
    // Measured 55.27 dB, worst 11 (2 pixels > 8): gated as the feature files, on the worst pixel.
    cases.push_back({"TextureTransformTest",
                     k07,
                     corpus / "textureTransform" / "TextureTransformTest.gltf",
                     {0.0f, 0.0f, 3.0f},
                     256,
                     192,
                     50,
                     16});
    // Measured 39.31 dB, 72 pixels > 8 (worst 194): inner edges between parts (not silhouettes
    // against the background, so not masked) where the two rasterizers pick different triangles.
    cases.push_back(assetCase("2CylinderEngine", k07,
                              corpus / "2CylinderEngine-glTF-Binary" / "2CylinderEngine.glb",
                              {300.0f, 200.0f, 500.0f}, 256, 192, 37, 150));
    // Measured 44.35 dB, 31 pixels > 8 (worst 157): the cube's inner edges, as above.
    cases.push_back(assetCase("BoxTextured", k07, corpus / "BoxTextured-glTF" / "BoxTextured.gltf",
                              {1.5f, 1.2f, 2.0f}, 192, 144, 42, 60));
    runCases("assets", cases);
}

TEST(Khronos, SpecularGlossinessMatchesTheSampleViewer) {
    PBR_NEED_VIEWER();
    PBR_NEED_ASSIMP_MODELS(corpus);
    std::vector<Case> cases;
    // specularFactor 0.2 everywhere: our diffuse x (1 - 0.2), the viewer's x 1 (the named
    // spec-gloss term), corrected on the viewer's side. Measured 25.34 dB, 5850 pixels > 8 even so:
    // ours / viewer in linear light is 0.24 to 0.70 (median 0.59) on the faces, not the 0.8 the
    // named term explains. NOT understood yet (glossiness 1, so roughness 0, is one suspect); this
    // gate only pins today's state.
    Case box = assetCase("BoxTextured_specgloss", k08,
                         corpus / "BoxTextured-glTF-pbrSpecularGlossiness" / "BoxTextured.gltf",
                         {1.5f, 1.2f, 2.0f}, 192, 144, 23, 7000);
    box.viewerDiffuseScale = 0.8f;
    cases.push_back(box);
    // Measured 35.55 dB, 699 pixels > 8 (worst 238): the spec-gloss spheres (the named (1 - max
    // specular) term, not corrected here: half the spheres are metallic-roughness) and the
    // roughness-0 spheres' highlights (the named clamp).
    cases.push_back(assetCase("pbr_workflows", k08, modelDir() / "pbr_workflows.gltf",
                              {0.0f, 0.0f, 9.0f}, 320, 180, 33, 1000));
    runCases("specgloss", cases);
}

// Sample 10's layers, one extension a file, each on a square under 07's feature lights (a point
// light in front, a directional one), IBL off as everywhere here; the transmissive squares in
// front of an opaque one that fills the view. Gated as the feature files (measured 2026-12-06:
// 56.8 to 61.0 dB, worst 1; the transmissions 51.6 to 54.1 dB, worst 1 to 6), with the viewer's
// transmission mended as render_viewer.js says (transmissionFixes: with its 1 - F twice, the
// smooth pane measured 45.0 dB). The viewer scales the base under a sheen with
// the table it asks for served (render_viewer.js: our LUT's A, its layout, and one line of its
// bundle changed). Planted, a coat added instead of mixed, F0 ignoring ior, emissive strength
// applied twice, the sheen's albedo scaling dropped, the transmitted light's 1 - F applied twice,
// the volume's attenuation dropped and half the rough pane's blur each fail their case.
TEST(Khronos, AdvancedMaterialsMatchTheSampleViewer) {
    PBR_NEED_VIEWER();
    const fs::path dir = testOutputDir("khronos_layer_files");
    const char* k10 = "10_gltf_advanced_materials";
    auto material = [](const std::string& base, const std::string& extension,
                       const std::string& members, const std::string& core = "") {
        return R"({"pbrMetallicRoughness":{"baseColorFactor":)" + base +
               R"(,"metallicFactor":0,"roughnessFactor":0.6})" + core + R"(,"extensions":{")" +
               extension + R"(":{)" + members + "}}}";
    };
    struct Layer {
        std::string name, extension, material;
        glm::vec3 eye{0.0f, 0.0f, 3.2f};
        double minPsnr = kFeaturePsnr;
        int maxWorst = kFeatureWorst;
        std::string secondExtension = "";
        bool backdrop = false;  // an opaque square behind, filling the view, seen through it
        bool pointLight = true;  // else the directional light alone
        bool texturedBackdrop = false;  // the backdrop in quadrants with a cross: edges to blur
    };
    const std::string red = "[0.7,0.06,0.05,1]", dark = "[0.05,0.05,0.06,1]";
    // white glass of `roughness`, with `more` extensions
    auto glass = [](const std::string& roughness, const std::string& more) {
        return R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],"metallicFactor":0,)"
               R"("roughnessFactor":)" +
               roughness + R"(},"extensions":{"KHR_materials_transmission":)"
                           R"({"transmissionFactor":1})" +
               more + "}}";
    };
    const std::vector<Layer> layers = {
        {"clearcoat", "KHR_materials_clearcoat",
         material(red, "KHR_materials_clearcoat",
                  R"("clearcoatFactor":1,"clearcoatRoughnessFactor":0.3)")},
        {"clearcoat_half_smooth", "KHR_materials_clearcoat",
         material(red, "KHR_materials_clearcoat",
                  R"("clearcoatFactor":0.5,"clearcoatRoughnessFactor":0.05)")},
        // Seen at a grazing angle, where a sheen shows, the base's reflection scaled under it:
        // the viewer with its albedo table served (below; without it, 38.0 dB, worst 12: its
        // base left bright)
        {"sheen", "KHR_materials_sheen",
         material(dark, "KHR_materials_sheen",
                  R"("sheenColorFactor":[1,0.5,0.8],"sheenRoughnessFactor":0.5)"),
         {0.0f, -2.9f, 1.1f}},
        // the sheen alone over a base that reflects nothing (black, KHR_materials_specular 0):
        // nothing for the albedo scaling to dim
        {"sheen_lobe", "KHR_materials_sheen",
         R"({"pbrMetallicRoughness":{"baseColorFactor":[0,0,0,1],"metallicFactor":0,)"
         R"("roughnessFactor":0.6},"extensions":{"KHR_materials_sheen":{"sheenColorFactor":)"
         R"([1,0.5,0.8],"sheenRoughnessFactor":0.5},"KHR_materials_specular":)"
         R"({"specularFactor":0}}})",
         {0.0f, -2.9f, 1.1f}, kFeaturePsnr, kFeatureWorst, "KHR_materials_specular"},
        {"specular", "KHR_materials_specular",
         material("[0.3,0.3,0.3,1]", "KHR_materials_specular",
                  R"("specularFactor":0.5,"specularColorFactor":[1,0.5,0.2])")},
        {"ior", "KHR_materials_ior", material(dark, "KHR_materials_ior", R"("ior":2.2)")},
        {"emissive_strength", "KHR_materials_emissive_strength",
         material(dark, "KHR_materials_emissive_strength", R"("emissiveStrength":4)",
                  R"(,"emissiveFactor":[0.2,0.1,0.05])")},
        // white glass in front of a lit opaque square: thin-walled and smooth (the backdrop
        // itself, less what the glass reflects), rough at ior 1.5 (its blur, from the backdrop's
        // mips), and a volume (the ray refracted through 0.5, attenuated to amber)
        {"transmission", "KHR_materials_transmission", glass("0.05", ""), {0.0f, 0.0f, 3.2f},
         kFeaturePsnr, kFeatureWorst, "", true},
        // (its backdrop a pattern, whose edges the blur of the backdrop's mips softens: measured
        // 51.6 dB, worst 6, at the edges the glass blurs; at half the blur, 39.2 dB, worst 30)
        {"transmission_rough", "KHR_materials_transmission", glass("0.4", ""), {0.0f, 0.0f, 3.2f},
         kFeaturePsnr, 8, "", true, true, true},
        // (under the directional light alone: the viewer 1.1.0 takes a point light's intensity
        // for the reflection at the point where the refracted ray leaves, 39 dB, worst 62)
        {"volume", "KHR_materials_transmission",
         glass("0.1", R"(,"KHR_materials_volume":{"thicknessFactor":0.5,)"
                      R"("attenuationDistance":0.4,"attenuationColor":[0.9,0.5,0.2]})"),
         {0.0f, 0.0f, 3.2f}, kFeaturePsnr, kFeatureWorst, "KHR_materials_volume", true, false},
    };
    std::vector<Case> cases;
    for (const Layer& layer : layers) {
        SceneFile s;
        const std::string attributes = squareAttributes(s.buffer, 1.0f, 0.0f);
        const int indices = s.buffer.indices({0, 1, 2, 0, 2, 3});
        s.primitives.push_back(primitive(attributes, indices, 0));
        s.materials.push_back(layer.material);
        if (layer.backdrop) addBackdrop(s, indices, layer.texturedBackdrop);
        if (layer.pointLight) s.lights.push_back(point({0.4f, 0.5f, 1.2f}, 3.0f));
        s.lights.push_back(directional({-0.3f, -0.4f, -1.0f}, layer.pointLight ? 1.0f : 2.5f));
        s.extensions.push_back(layer.extension);
        if (!layer.secondExtension.empty()) s.extensions.push_back(layer.secondExtension);
        cases.push_back({layer.name, k10, s.write(dir, layer.name), layer.eye, 192, 144,
                         layer.minPsnr, layer.maxWorst});
    }
    runCases("layers", cases, {.sheenTable = sheenTable(dir)});
}

// Under image-based light alone, three spheres a case, the environment drawn behind them (the
// spheres alone compared; their outlines from a picture of ours with neither light). The viewer
// filters each environment with its own shaders (at the sizes render_viewer.js says), and its
// split sum is served without its roughness-dependent Fresnel (render_viewer.js says why:
// unmended, the dielectric spheres measured 38.8 dB, worst 24, at their rims).
//   - The reference tests' linear sky (tests/reference/linear_sky.h: linear in the direction,
//     along another axis in each channel): what the maps hold in each direction and roughness,
//     and the split sum's table. Single scattering on both sides: the two light the
//     multiple-scattering share differently (the viewer by the prefiltered map, we by the
//     irradiance, as Fdez-Aguera does), which only an environment alike in every direction does
//     not tell apart.
//   - Such an environment, a constant colour: every map holds that colour, so what is compared is
//     the split sum's table and the multiple-scattering share, on both sides.
// Measured 2026-12-07: 53.8 to 55.1 dB, worst 1 or 2, but for the rough metals (50.7 dB, worst
// 3: the viewer's filtering at 64^2 faces, which converges towards ours with the face size, see
// render_viewer.js) and the sheen (47.0 dB, 20 pixels past 8 at the rims of the smoothest one:
// the viewer prefilters by importance sampling, most of whose samples fall below the horizon for
// a narrow sheen lobe; with its own 64 samples a texel instead of the 1024 served, 43.3 dB); the
// glass in front of an opaque square (the linear sky lighting both, and reflected by the glass)
// 50.3 to 53.2 dB, worst 1 to 4, the rough pane over a pattern gated as without the light.
// This test found 07's image-based light using the texts' BRDF table, whose Schlick-GGX
// masking-shadowing is not the glTF BRDF's (BrdfLutChannels::GltfScaleBias): the metal spheres
// then measured 34.9 dB, worst 20. Planted, each fails its case: that table again; the
// multiple-scattering share dropped (18.0 dB); the irradiance read along the reflection (29.7 dB);
// the prefiltered level at roughness^2 (40.6 dB); the clear coat added over the base instead of
// mixed (36.7 dB); F0 ignoring ior (25.3 dB); the sheen's albedo scaling dropped (33.9 dB); the
// light through the glass weighed by 1 - E twice (46.0 to 47.3 dB).
TEST(Khronos, ImageBasedLightMatchesTheSampleViewer) {
    PBR_NEED_VIEWER();
    const fs::path dir = testOutputDir("khronos_ibl_files");
    const fs::path sky = writeLinearSky(dir);
    // Three spheres in a row, materials 0, 1, 2 from left to right.
    auto spheres = [&](const std::string& name, const std::vector<std::string>& materials,
                       const std::vector<std::string>& extensions = {}) {
        SceneFile s;
        for (int i = 0; i < 3; ++i) {
            int indices = 0;
            const std::string attributes =
                sphereAttributes(s.buffer, {1.15f * float(i - 1), 0.0f, 0.0f}, 0.5f, indices);
            s.primitives.push_back(primitive(attributes, indices, i));
            s.materials.push_back(materials[size_t(i)]);
        }
        s.extensions = extensions;
        return s.write(dir, name);
    };
    auto core = [](const std::string& base, float metallic, float roughness) {
        return R"({"pbrMetallicRoughness":{"baseColorFactor":)" + base + R"(,"metallicFactor":)" +
               std::to_string(metallic) + R"(,"roughnessFactor":)" + std::to_string(roughness) +
               "}}";
    };
    const std::string red = "[0.8,0.2,0.1,1]", gold = "[1,0.78,0.34,1]";
    const glm::vec3 eye{0.0f, 0.0f, 2.9f};
    std::vector<Case> cases;
    auto add = [&](const std::string& name, const char* sample,
                   const std::vector<std::string>& materials,
                   const std::vector<std::string>& extensions = {}) {
        cases.push_back({name, sample, spheres(name, materials, extensions), eye, 256, 128,
                         kFeaturePsnr, kFeatureWorst});
        return &cases.back();
    };
    add("dielectric", k07, {core(red, 0, 0.1f), core(red, 0, 0.5f), core(red, 0, 1)});
    add("metal", k07, {core(gold, 1, 0.1f), core(gold, 1, 0.5f), core(gold, 1, 1)})->minPsnr = 48;
    add("metallic", k07, {core(gold, 0.3f, 0.3f), core(gold, 0.6f, 0.3f), core(red, 0.5f, 0.7f)});
    // sample 10's layers: a material of 07's with an extension's members
    auto layered = [](const std::string& base, float roughness, const std::string& extensions) {
        return R"({"pbrMetallicRoughness":{"baseColorFactor":)" + base +
               R"(,"metallicFactor":0,"roughnessFactor":)" + std::to_string(roughness) +
               R"(},"extensions":{)" + extensions + "}}";
    };
    const char* k10 = "10_gltf_advanced_materials";
    auto coat = [](const std::string& factor, const std::string& roughness) {
        return R"("KHR_materials_clearcoat":{"clearcoatFactor":)" + factor +
               R"(,"clearcoatRoughnessFactor":)" + roughness + "}";
    };
    add("clearcoat", k10,
        {layered(red, 0.6f, coat("1", "0.05")), layered(red, 0.6f, coat("0.5", "0.1")),
         layered(gold, 0.3f, coat("1", "0.2"))},
        {"KHR_materials_clearcoat"});
    const std::string tinted =
        R"("KHR_materials_specular":{"specularFactor":0.5,"specularColorFactor":[1,0.5,0.2]})";
    add("specular_ior", k10,
        {layered("[0.3,0.3,0.3,1]", 0.3f, tinted),
         layered("[0.05,0.05,0.06,1]", 0.2f, R"("KHR_materials_ior":{"ior":2.2})"),
         layered(red, 0.5f,
                 R"("KHR_materials_ior":{"ior":1.2},)"
                 R"("KHR_materials_specular":{"specularFactor":0.8})")},
        {"KHR_materials_specular", "KHR_materials_ior"});
    auto sheenOf = [](const std::string& colour, const std::string& roughness) {
        return R"("KHR_materials_sheen":{"sheenColorFactor":)" + colour +
               R"(,"sheenRoughnessFactor":)" + roughness + "}";
    };
    const std::string dark = "[0.05,0.05,0.06,1]", pink = "[1,0.5,0.8]";
    Case* sheen =
        add("sheen", k10,
            {layered(dark, 0.6f, sheenOf(pink, "0.3")), layered(dark, 0.6f, sheenOf(pink, "0.7")),
             layered(red, 0.4f, sheenOf("[0.3,0.6,1]", "0.5"))},
            {"KHR_materials_sheen"});
    sheen->minPsnr = 45;
    sheen->maxOver8 = 40;
    // white glass in front of an opaque square that fills the view (as in
    // AdvancedMaterialsMatchTheSampleViewer), smooth, rough over a pattern, and an amber volume
    auto glass = [&](const std::string& name, float roughness, const std::string& more,
                     bool textured) {
        SceneFile s;
        const int indices = s.buffer.indices({0, 1, 2, 0, 2, 3});
        s.primitives.push_back(primitive(squareAttributes(s.buffer, 1.0f, 0.0f), indices, 0));
        s.materials.push_back(
            layered("[1,1,1,1]", roughness,
                    R"("KHR_materials_transmission":{"transmissionFactor":1})" + more));
        addBackdrop(s, indices, textured);
        s.extensions.push_back("KHR_materials_transmission");
        if (!more.empty()) s.extensions.push_back("KHR_materials_volume");
        cases.push_back({name,
                         k10,
                         s.write(dir, name),
                         {0.0f, 0.0f, 3.2f},
                         192,
                         144,
                         kFeaturePsnr,
                         kFeatureWorst});
        cases.back().filled = true;
        return &cases.back();
    };
    glass("transmission", 0.05f, "", false);
    // (the pattern's edges blurred by the glass, as without the image-based light: gated as there)
    Case* rough = glass("transmission_rough", 0.4f, "", true);
    rough->minPsnr = 48;
    rough->maxWorst = 8;
    glass("volume", 0.1f,
          R"(,"KHR_materials_volume":{"thicknessFactor":0.5,"attenuationDistance":0.4,)"
          R"("attenuationColor":[0.9,0.5,0.2]})",
          false);
    runCases("ibl", cases,
             {.sheenTable = sheenTable(dir), .environment = sky, .singleScattering = true});

    cases.clear();
    const fs::path constant = dir / "constant.hdr";
    HdrImage uniform{64, 32, {}};
    for (int i = 0; i < 64 * 32; ++i)
        uniform.pixels.insert(uniform.pixels.end(), {0.7f, 0.55f, 0.4f});
    writeHdr(constant, uniform);
    add("metal_multiple", k07, {core(gold, 1, 0.4f), core(gold, 1, 0.7f), core(gold, 1, 1)});
    add("dielectric_multiple", k07,
        {core(red, 0, 0.4f), core(red, 0, 1), core("[0.9,0.9,0.9,1]", 0.5f, 0.8f)});
    runCases("ibl_constant", cases, {.environment = constant, .cubeFaceSize = 16});
}

}  // namespace
}  // namespace pbr::test
