// Sample 07 against the glTF specification's arithmetic done on the CPU (pbr::cpu,
// common/math/brdf): the Appendix B BRDF under KHR_lights_punctual lights, with image-based light
// off and no tone mapping, so a pixel is encode_sRGB(the sum over the lights). Scenes are written
// by the tests in JSON (tests/support/gltf_scene.h) or are the project's showcase; every ray is
// cast against the very triangles the GPU draws (tests/support/mesh_hit.h).
//
// Exactness: no MSAA; pixels within 1 % of a triangle edge are left out; so are pixels where the
// CPU's own answer moves by more than 1/255 when the normal turns by 0.002 radians (the peak of
// a mirror-like highlight, where float and double part ways), so what is compared is the
// shading, not rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <span>

#include "reference/linear_sky.h"
#include "support/gltf_scene.h"
#include "support/golden.h"
#include "support/mesh_hit.h"

#include "base/paths.h"
#include "files/image.h"
#include "gl/mesh.h"
#include "gltf/model.h"
#include "math/brdf.h"
#include "math/gltf_extensions.h"
#include "math/camera.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

constexpr int kSize = 400;  // square renders: --size 400x400

// 07's flags for `model`, image-based light off (or, `ibl`, the file's punctual lights), no tone
// mapping, no MSAA, from `eye` (looking at the model's centre); `extra` added.
std::vector<std::string> args07(const fs::path& model, const glm::vec3& eye,
                                const std::vector<std::string>& extra, bool ibl) {
    std::vector<std::string> args = {
        "--model",
        model.string(),
        ibl ? "--no-punctual" : "--no-ibl",
        "--tonemap",
        "none",
        "--msaa",
        "0",
        "--size",
        std::to_string(kSize) + "x" + std::to_string(kSize),
        "--camera",
        std::to_string(eye.x) + "," + std::to_string(eye.y) + "," + std::to_string(eye.z)};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
}

// 07 (or 08) on `model` so (args07), headless.
Image render07(const fs::path& dir, const fs::path& model, const glm::vec3& eye,
               std::vector<std::string> extra = {},
               const std::string& sample = "07_gltf_metallic_roughness", bool ibl = false) {
    const SampleRender render = renderSample(sample, dir / (model.stem().string() + ".png"),
                                             args07(model, eye, extra, ibl));
    EXPECT_EQ(render.run.exitCode, 0) << render.run.err;
    EXPECT_EQ(render.run.err.find("GL error"), std::string::npos) << render.run.err;
    return readImage(render.image, 3);
}

// The pixel centre's ray of the orbit camera 07 uses for `eye`.
struct Rays {
    glm::dmat4 toWorld;
    Rays(const Model& model, const glm::vec3& eye) {
        const OrbitCamera camera = OrbitCamera::fromPosition(model.boundsMin, model.boundsMax, eye);
        toWorld = glm::inverse(glm::dmat4(camera.projectionMatrix(1.0f)) *
                               glm::dmat4(camera.viewMatrix()));
    }
    std::pair<glm::dvec3, glm::dvec3> at(int px, int py) const {
        return pixelRay(toWorld, kSize, kSize, px, py);
    }
};

// The CPU's sRGB bytes for a surface, or nullopt where they are ill-conditioned (see the top) or
// where `shade` gives none (a point a test leaves out).
using Shade = std::function<std::optional<glm::vec3>(const glm::vec3& normal)>;
std::optional<glm::ivec3> expectedBytes(const Shade& shade, const glm::vec3& normal) {
    auto bytes = [&](const glm::vec3& n) {
        const std::optional<glm::vec3> c = shade(glm::normalize(n));
        if (!c) return glm::ivec3(-1000);
        return glm::ivec3(int(std::lround(linearToSrgb(c->r) * 255.0)),
                          int(std::lround(linearToSrgb(c->g) * 255.0)),
                          int(std::lround(linearToSrgb(c->b) * 255.0)));
    };
    if (!shade(normal)) return std::nullopt;
    const glm::ivec3 centre = bytes(normal);
    const glm::vec3 a = glm::normalize(
        glm::cross(normal, std::abs(normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
    const glm::vec3 b = glm::cross(normal, a);
    for (const glm::vec3& turn : {a, -a, b, -b}) {
        const glm::ivec3 moved = bytes(normal + 0.002f * turn);
        if (glm::any(glm::greaterThan(glm::abs(moved - centre), glm::ivec3(1))))
            return std::nullopt;
    }
    return centre;
}

// Sorts a point of the square by its distance from the centre into the ring whose outer radius
// it is first below; past the last, `beyond`.
std::function<std::string(const glm::vec3&)> rings(
    std::vector<std::pair<double, std::string>> bounds, std::string beyond) {
    return [bounds = std::move(bounds), beyond = std::move(beyond)](const glm::vec3& p) {
        const double r = std::hypot(p.x, p.y);
        for (const auto& [radius, name] : bounds) {
            if (r < radius) return name;
        }
        return beyond;
    };
}

// A grey dielectric square (2 x 2 m at z = 0, facing +Z) under the lights of `lightsJson`
// (KHR_lights_punctual's "lights") on nodes `nodesJson` (node 0 is the square).
fs::path writeLitSquare(const fs::path& dir, const std::string& name, const std::string& lightsJson,
                        const std::string& lightNodesJson, int lightNodeCount) {
    std::string sceneNodes = "0";
    for (int i = 1; i <= lightNodeCount; ++i) {
        sceneNodes += ',';  // not "," + std::to_string(i): GCC 12 warns falsely (-Wrestrict)
        sceneNodes += std::to_string(i);
    }
    return writeTextFile(dir, name,
                         R"({"asset":{"version":"2.0"},
"extensionsUsed":["KHR_lights_punctual"],
)" + squareBuffersJson(2.0f) +
                             R"(
"materials":[{"name":"grey","pbrMetallicRoughness":{"baseColorFactor":[0.8,0.8,0.8,1],
  "metallicFactor":0,"roughnessFactor":0.7}}],
"meshes":[{"primitives":[)" + squarePrimitiveJson(0) +
                             R"(]}],
"extensions":{"KHR_lights_punctual":{"lights":[)" +
                             lightsJson + R"(]}},
"nodes":[{"mesh":0},)" + lightNodesJson +
                             R"(],
"scenes":[{"nodes":[)" + sceneNodes +
                             R"(]}],"scene":0})");
}

// Compares every well-conditioned pixel of the square with the CPU; `classify` sorts each hit
// point into a named class (e.g. "inside the cone") and the test demands `minimum` of each.
void expectSquareMatchesCpu(const fs::path& file, const std::map<std::string, int>& minimum,
                            const std::function<std::string(const glm::vec3&)>& classify) {
    const Model model = loadModel(file);
    const glm::vec3 eye(0.0f, 0.0f, 3.0f);
    const Image image = render07(file.parent_path(), file, eye);
    const Rays rays(model, eye);
    const ModelRayCaster caster(model, glm::dmat4(1.0));
    const Material& material = model.materials.at(0);
    std::map<std::string, int> counts;
    int worst = 0;
    for (int py = 0; py < kSize; py += 2) {
        for (int px = 0; px < kSize; px += 2) {
            const auto [origin, direction] = rays.at(px, py);
            const auto hit = caster.hit(origin, direction);
            if (!hit || hit->minBarycentric < 0.01) continue;
            const glm::vec3 position(hit->position);
            const Shade shade = [&](const glm::vec3& normal) {
                const cpu::GltfSurface surface = cpu::metallicRoughnessSurface(
                    position, normal, glm::vec3(material.baseColorFactor), 0.0f, 0.7f);
                return cpu::shadePunctualLights(surface, eye, model.lights);
            };
            const auto expected = expectedBytes(shade, glm::vec3(hit->normal));
            if (!expected) continue;
            for (int c = 0; c < 3; ++c) {
                const int diff = std::abs(int(image.at(px, py, c)) - (*expected)[c]);
                worst = std::max(worst, diff);
                EXPECT_LE(diff, 2)
                    << file.filename() << " pixel (" << px << ", " << py << ") at " << position.x
                    << ", " << position.y << " (" << classify(position) << "): rendered "
                    << int(image.at(px, py, c)) << ", CPU " << (*expected)[c];
            }
            ++counts[classify(position)];
        }
    }
    for (const auto& [name, least] : minimum) {
        std::printf("%s: %d pixels %s\n", file.filename().c_str(), counts[name], name.c_str());
        EXPECT_GE(counts[name], least) << name;
    }
    std::printf("%s: worst channel difference %d/255\n", file.filename().c_str(), worst);
}

TEST(Reference, Gltf07PointLightRangeWindow) {
    const fs::path dir = testOutputDir("reference_07_range");
    // a point light 0.5 m in front of the square's centre, range 1.5: its light ends where
    // d = 1.5, a circle of radius sqrt(1.5^2 - 0.5^2) = 1.414 on the square
    const fs::path file = writeLitSquare(
        dir, "range.gltf", R"({"type":"point","intensity":3,"range":1.5})",
        R"({"translation":[0,0,0.5],"extensions":{"KHR_lights_punctual":{"light":0}}})", 1);
    const double edge = std::sqrt(1.5 * 1.5 - 0.5 * 0.5);
    expectSquareMatchesCpu(file,
                           {{"well inside", 500},
                            {"just inside the range", 40},
                            {"just outside the range", 40},
                            {"outside", 500}},
                           rings({{edge - 0.1, "well inside"},
                                  {edge, "just inside the range"},
                                  {edge + 0.1, "just outside the range"}},
                                 "outside"));
}

TEST(Reference, Gltf07SpotLightCones) {
    const fs::path dir = testOutputDir("reference_07_spot");
    // a spot 1.5 m in front of the square, shining down -Z onto it: inner cone 0.35 rad, outer
    // 0.6 rad, so full light within r = 1.5 tan 0.35, none beyond 1.5 tan 0.6, t^2 between
    const fs::path file = writeLitSquare(
        dir, "spot.gltf",
        R"({"type":"spot","intensity":8,"spot":{"innerConeAngle":0.35,"outerConeAngle":0.6}})",
        R"({"translation":[0,0,1.5],"extensions":{"KHR_lights_punctual":{"light":0}}})", 1);
    const double inner = 1.5 * std::tan(0.35), outer = 1.5 * std::tan(0.6);
    expectSquareMatchesCpu(file,
                           {{"inside the inner cone", 400},
                            {"just inside the inner cone", 30},
                            {"in the soft band", 300},
                            {"just outside the outer cone", 30},
                            {"outside", 500}},
                           rings({{inner - 0.05, "inside the inner cone"},
                                  {inner, "just inside the inner cone"},
                                  {outer, "in the soft band"},
                                  {outer + 0.05, "just outside the outer cone"}},
                                 "outside"));
}

TEST(Reference, Gltf07DirectionalAndPointTogether) {
    const fs::path dir = testOutputDir("reference_07_two");
    // no range (plain inverse square) and a slanted directional light, placed by rotated nodes
    const fs::path file = writeLitSquare(
        dir, "two.gltf",
        R"({"type":"point","color":[1,0.6,0.3],"intensity":1.5},
           {"type":"directional","color":[0.3,0.5,1],"intensity":0.8})",
        R"({"translation":[0.7,-0.4,0.8],"extensions":{"KHR_lights_punctual":{"light":0}}},
           {"rotation":[0.2588190,0,0,0.9659258],"extensions":{"KHR_lights_punctual":{"light":1}}})",
        2);
    expectSquareMatchesCpu(file, {{"lit", 5000}}, rings({}, "lit"));
}

// MASK keeps a fragment exactly when its alpha is at or above the cutoff: a 16 x 16 texture
// whose texel i has alpha i / 255 (i = 0..255), nearest-filtered, under an unlit white material
// with alphaCutoff 0.25: texels 64 and up (64 / 255 = 0.251) show, 63 (0.247) and below do not.
TEST(Reference, Gltf07MaskKeepsTexelsAtOrAboveTheCutoff) {
    const fs::path dir = testOutputDir("reference_07_mask");
    Image alphas{16, 16, 4, {}};
    for (int i = 0; i < 256; ++i)
        alphas.pixels.insert(alphas.pixels.end(), {255, 255, 255, std::uint8_t(i)});
    writePng(dir / "alphas.png", alphas);
    const fs::path file = writeTextFile(dir, "mask.gltf", R"({"asset":{"version":"2.0"},
"extensionsUsed":["KHR_materials_unlit"],
)" + squareBuffersJson(1.0f) + R"(
"images":[{"uri":"alphas.png"}],
"samplers":[{"magFilter":9728,"minFilter":9728}],
"textures":[{"source":0,"sampler":0}],
"materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}},"alphaMode":"MASK",
  "alphaCutoff":0.25,"extensions":{"KHR_materials_unlit":{}}}],
"meshes":[{"primitives":[)" + squarePrimitiveJson(0) + R"(]}],
"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})");
    const Model model = loadModel(file);
    const glm::vec3 eye(0.0f, 0.0f, 2.6f);
    const Image image = render07(dir, file, eye);
    const Rays rays(model, eye);
    const ModelRayCaster caster(model, glm::dmat4(1.0));
    int kept = 0, dropped = 0;
    for (int py = 0; py < kSize; ++py) {
        for (int px = 0; px < kSize; ++px) {
            const auto [origin, direction] = rays.at(px, py);
            const auto hit = caster.hit(origin, direction);
            if (!hit) continue;
            const glm::dvec2 texel = hit->uv0 * 16.0;
            const glm::dvec2 within = texel - glm::floor(texel);
            // well inside one texel (a pixel is about 1/16 of one)
            if (glm::any(glm::lessThan(within, glm::dvec2(0.2))) ||
                glm::any(glm::greaterThan(within, glm::dvec2(0.8))))
                continue;
            const int i = std::clamp(int(texel.y), 0, 15) * 16 + std::clamp(int(texel.x), 0, 15);
            const bool shows = image.at(px, py, 0) == 255 && image.at(px, py, 1) == 255;
            EXPECT_EQ(shows, i >= 64) << "texel " << i << " (alpha " << i << "/255) at pixel ("
                                      << px << ", " << py << ")";
            (i >= 64 ? kept : dropped) += 1;
        }
    }
    std::printf("mask: %d pixels kept, %d dropped\n", kept, dropped);
    EXPECT_GT(kept, 5000);
    EXPECT_GT(dropped, 1500);
}

// Where compareSpheres looks from: 4 in front of the model's centre, a little above.
glm::vec3 spheresEye(const Model& model) {
    return 0.5f * (model.boundsMin + model.boundsMax) + glm::vec3(0.0f, 0.2f, 4.0f);
}

// `views` of `file` as compareSpheres renders it (`extra` added), in one run (renderViews): the
// pictures to hand it, by view.
std::map<std::string, Image> renderSpheresViews(const fs::path& dir, const std::string& sample,
                                                const fs::path& file,
                                                const std::vector<std::string>& views,
                                                const std::vector<std::string>& extra = {},
                                                bool ibl = false,
                                                std::optional<glm::vec3> eyeAt = std::nullopt) {
    const glm::vec3 eye = eyeAt.value_or(spheresEye(loadModel(file)));
    const ViewRenders renders = renderViews(sample, views, args07(file, eye, extra, ibl), dir);
    EXPECT_EQ(renders.run.exitCode, 0) << renders.run.err;
    EXPECT_EQ(renders.run.err.find("GL error"), std::string::npos) << renders.run.err;
    std::map<std::string, Image> images;
    for (const auto& [view, path] : renders.images) images[view] = readImage(path, 3);
    EXPECT_EQ(images.size(), views.size()) << renders.run.out;
    return images;
}

// Spheres of one of the project's assets against the CPU: every other pixel whose ray meets a
// sphere named "<prefix>..." (and not near a triangle's edge), shaded by the CPU from the
// surface `surfaceOf` gives (nothing: left out) under the file's own lights.
struct SphereCheck {
    std::map<std::string, int> compared;  // pixels, by material
    int total = 0, worst = 0;
};
using SurfaceOf = std::function<std::optional<cpu::GltfSurface>(
    const Model&, const Material&, const glm::vec3& position, const glm::vec3& normal)>;
// The linear value a pixel holds before the sRGB encoding, for a surface seen from `eye` under
// `lights` (nullopt: not compared): by default the picture's, the sum over the lights.
using ShadeSurface = std::function<std::optional<glm::vec3>(
    const cpu::GltfSurface&, const glm::vec3& eye, std::span<const PunctualLight> lights)>;
std::optional<glm::vec3> shadeUnderLights(const cpu::GltfSurface& surface, const glm::vec3& eye,
                                          std::span<const PunctualLight> lights) {
    return cpu::shadePunctualLights(surface, eye, lights);
}
SphereCheck compareSpheres(const fs::path& dir, const std::string& sample, const fs::path& file,
                           const std::string& prefix, const SurfaceOf& surfaceOf,
                           const std::vector<std::string>& extra = {},
                           const ShadeSurface& shadeSurface = shadeUnderLights, bool ibl = false,
                           const Image* rendered = nullptr,
                           std::optional<glm::vec3> eyeAt = std::nullopt) {
    const Model model = loadModel(file);
    const glm::vec3 eye = eyeAt.value_or(spheresEye(model));
    const Image image = rendered ? *rendered : render07(dir, file, eye, extra, sample, ibl);
    const Rays rays(model, eye);
    const ModelRayCaster caster(model, glm::dmat4(1.0));
    SphereCheck check;
    for (int py = 0; py < kSize; ++py) {
        for (int px = py % 2; px < kSize; px += 2) {  // every other pixel, in a checkerboard
            const auto [origin, direction] = rays.at(px, py);
            const auto hit = caster.hit(origin, direction);
            if (!hit || hit->minBarycentric < 0.01) continue;
            const Material& material =
                model.materials[size_t(model.primitives[size_t(hit->primitive)].material)];
            if (!material.name.starts_with(prefix)) continue;
            const glm::vec3 position(hit->position);
            if (!surfaceOf(model, material, position, glm::vec3(hit->normal))) continue;
            const Shade shade = [&](const glm::vec3& normal) {
                return shadeSurface(*surfaceOf(model, material, position, normal), eye,
                                    model.lights);
            };
            const auto expected = expectedBytes(shade, glm::vec3(hit->normal));
            if (!expected) continue;
            for (int c = 0; c < 3; ++c) {
                const int diff = std::abs(int(image.at(px, py, c)) - (*expected)[c]);
                check.worst = std::max(check.worst, diff);
                EXPECT_LE(diff, 2)
                    << material.name << " pixel (" << px << ", " << py << "): rendered "
                    << int(image.at(px, py, c)) << ", CPU " << (*expected)[c];
            }
            ++check.compared[material.name];
            ++check.total;
        }
    }
    return check;
}

// The 07 showcase's ten spheres, each with its own solid metallic-roughness texture (read here
// on the CPU: G roughness, B metallic). `materialOf` gives a sphere's metallic and roughness,
// or false to leave the sphere out.
SphereCheck compareShowcaseSpheres(
    const std::string& name,
    const std::function<bool(const Material&, const Image& mr, float& metallic, float& roughness)>&
        materialOf,
    const std::vector<std::string>& extra = {}, const ShadeSurface& shadeSurface = shadeUnderLights,
    bool ibl = false, const Image* rendered = nullptr) {
    std::map<std::string, Image> textures;  // each material's, read once (not at every pixel)
    return compareSpheres(
        testOutputDir("reference_07_spheres_" + name), "07_gltf_metallic_roughness",
        modelDir() / "pbr_showcase.gltf", "sphere_",
        [&](const Model& model, const Material& material, const glm::vec3& position,
            const glm::vec3& normal) -> std::optional<cpu::GltfSurface> {
            auto found = textures.find(material.name);
            if (found == textures.end()) {
                found = textures
                            .emplace(material.name,
                                     loadTextureImage(model, material.metallicRoughnessTexture, 3))
                            .first;
            }
            const Image& mr = found->second;
            float metallic = 0.0f, roughness = 0.0f;
            if (!materialOf(material, mr, metallic, roughness)) return std::nullopt;
            return cpu::metallicRoughnessSurface(
                position, normal, glm::vec3(material.baseColorFactor), metallic, roughness);
        },
        extra, shadeSurface, ibl, rendered);
}

// A solid metallic-roughness texture's values: its first texel; glTF: roughness = factor x G,
// metallic = factor x B.
bool solidTexture(const Material& m, const Image& mr, float& metallic, float& roughness) {
    roughness = m.roughnessFactor * float(mr.at(0, 0, 1)) / 255.0f;
    metallic = m.metallicFactor * float(mr.at(0, 0, 2)) / 255.0f;
    return true;
}

TEST(Reference, Gltf07ShowcaseSpheresMatchTheCpu) {
    const SphereCheck check = compareShowcaseSpheres("all", solidTexture);
    std::printf("showcase spheres: %d pixels compared, worst channel difference %d/255\n",
                check.total, check.worst);
    EXPECT_GT(check.total, 3000);
    EXPECT_EQ(check.compared.size(), 10u);
}

// The channel test: the texture with only G set is a fully rough dielectric, the one with only B
// a mirror-smooth metal (values from the specification, not from the texture reader).
TEST(Reference, Gltf07MetallicRoughnessChannels) {
    const SphereCheck check = compareShowcaseSpheres(
        "channels", [](const Material& m, const Image& mr, float& metallic, float& roughness) {
            if (m.name == "sphere_metal_0") {  // texel (0, 0, 255): only B
                EXPECT_EQ(mr.at(0, 0, 0) + mr.at(0, 0, 1), 0);
                metallic = 1.0f;
                roughness = 0.0f;
                return true;
            }
            if (m.name == "sphere_dielectric_4") {  // texel (0, 255, 0): only G
                EXPECT_EQ(mr.at(0, 0, 0) + mr.at(0, 0, 2), 0);
                metallic = 0.0f;
                roughness = 1.0f;
                return true;
            }
            return false;
        });
    for (const char* name : {"sphere_metal_0", "sphere_dielectric_4"}) {
        std::printf("%s: %d pixels compared\n", name, check.compared.at(name));
        EXPECT_GT(check.compared.at(name), 150) << name;
    }
}

// The linear value that the sRGB encoding takes to v: what a view shows as it is is written so.
glm::vec3 encodedAs(const glm::dvec3& v) {
    return {float(srgbToLinear(std::clamp(v.r, 0.0, 1.0))),
            float(srgbToLinear(std::clamp(v.g, 0.0, 1.0))),
            float(srgbToLinear(std::clamp(v.b, 0.0, 1.0)))};
}

// A view of the glTF samples at `s` by its definition in 07's README: the inputs as they are
// (the normal as 0.5 + 0.5 N; f0 = mix(F0, base colour, metallic)); a punctual light's term
// summed over the lights that reach the point (NdotL > 0, radiance above 0), as x / (1 + x); the
// direct light alone through the tone mapper (none here: clamped to [0, 1]). The terms are
// cpu::gltfBrdf's; G = Vis x 4 NdotL NdotV.
glm::vec3 gltfPunctualView(const std::string& view, const cpu::GltfSurface& s, const glm::vec3& eye,
                           std::span<const PunctualLight> lights) {
    const glm::vec3 N = s.normal, V = glm::normalize(eye - s.position);
    if (view == "base-color") return encodedAs(glm::dvec3(s.metalColor));
    if (view == "normal") return encodedAs(0.5 + 0.5 * glm::dvec3(N));
    if (view == "metallic") return encodedAs(glm::dvec3(s.metallic));
    if (view == "roughness") return encodedAs(glm::dvec3(s.roughness));
    if (view == "occlusion") return encodedAs(glm::dvec3(1.0));  // no occlusion texture
    if (view == "emissive") return encodedAs(glm::dvec3(0.0));   // no emission
    if (view == "f0") return encodedAs(glm::dvec3(glm::mix(s.F0, s.metalColor, s.metallic)));
    glm::dvec3 sum(0.0);
    glm::vec3 direct(0.0f);
    for (const PunctualLight& light : lights) {
        glm::vec3 L;
        const glm::vec3 radiance = cpu::punctualRadiance(light, s.position, L);
        direct += cpu::gltfDirectLight(N, V, L, radiance, s);
        if (glm::dot(N, L) <= 0.0f || radiance == glm::vec3(0.0f)) continue;
        const cpu::GltfBrdf b = cpu::gltfBrdf(N, V, L, s);
        if (view == "d") sum += glm::dvec3(b.D);
        if (view == "g") sum += glm::dvec3(b.Vis * 4.0f * b.NdotL * b.NdotV);
        if (view == "visibility") sum += glm::dvec3(b.Vis);
        if (view == "f") sum += glm::dvec3(b.F);
        if (view == "specular") sum += glm::dvec3(b.specular);
        if (view == "diffuse") sum += glm::dvec3(b.diffuse);
        if (view == "ndotl") sum += glm::dvec3(b.NdotL);
    }
    if (view == "direct") return glm::clamp(direct, 0.0f, 1.0f);
    return encodedAs(sum / (1.0 + sum));
}

// gltfPunctualView as compareSpheres shades with it.
ShadeSurface punctualViewShade(const std::string& view) {
    return [view](const cpu::GltfSurface& s, const glm::vec3& eye,
                  std::span<const PunctualLight> lights) -> std::optional<glm::vec3> {
        return gltfPunctualView(view, s, eye, lights);
    };
}

// Prints a view's comparison and checks it saw enough pixels on every one of `spheres` spheres.
void expectViewCompared(const std::string& label, const SphereCheck& check, int minPixels,
                        size_t spheres) {
    std::printf("%s: %d pixels compared, worst channel difference %d/255\n", label.c_str(),
                check.total, check.worst);
    EXPECT_GT(check.total, minPixels) << label;
    EXPECT_EQ(check.compared.size(), spheres) << label;
}

// 07's term views of the inputs and of the punctual lights on the showcase's ten spheres (image-
// based light off, no tone mapping), every other pixel against the CPU, within 2/255.
TEST(Reference, Gltf07TermViewsMatchTheCpu) {
    const std::vector<std::string> views = {
        "base-color", "normal",     "metallic", "roughness", "occlusion", "emissive", "f0",    "d",
        "g",          "visibility", "f",        "specular",  "diffuse",   "ndotl",    "direct"};
    std::map<std::string, Image> images =
        renderSpheresViews(testOutputDir("reference_07_spheres_views"),
                           "07_gltf_metallic_roughness", modelDir() / "pbr_showcase.gltf", views);
    for (const std::string& view : views) {
        SCOPED_TRACE("--view " + view);
        ASSERT_TRUE(images.count(view));
        const SphereCheck check =
            compareShowcaseSpheres("view_" + view, solidTexture, {"--view", view},
                                   punctualViewShade(view), false, &images[view]);
        expectViewCompared("--view " + view, check, 1500, 10);
    }
}

// Sample 10's views of its layers on its showcase (image-based light off, the file's sun), one
// pixel in four of each of its 35 spheres against the CPU (by the definitions in 10's
// README, from common/math/gltf_extensions.cpp; the sheen's albedo E by quadrature, not from the
// baked table the shader reads, at NdotV from 0.1, short of the table's steep grazing end, which
// its own test checks), within 2/255: F0 from ior and the specular layer, the coat's share and
// normal, the sheen's light, what the base keeps under the sheen, the transmission's share, what
// the volume leaves. A material without the layer shows none of it.
TEST(Reference, Gltf10LayerViewsMatchTheCpu) {
    const fs::path file = modelDir() / "advanced_materials.gltf";
    const glm::vec3 eye(0.0f, 1.4f, 9.3f);  // the sample's own start: every row in the frame
    const std::vector<std::string> views = {"f0",           "clearcoat",    "clearcoat-normal",
                                            "sheen",        "sheen-scaling", "transmission",
                                            "volume-attenuation"};
    std::map<std::string, Image> images =
        renderSpheresViews(testOutputDir("reference_10_layer_views"), "10_gltf_advanced_materials",
                           file, views, {}, false, eye);
    const Model model = loadModel(file);
    // one pixel in four (every other of every other row) on a sphere, not near a triangle's edge,
    // cast once for every view
    struct Hit {
        int px, py;
        const Material* material;
        glm::vec3 position, normal;
    };
    std::vector<Hit> hits;
    const Rays rays(model, eye);
    const ModelRayCaster caster(model, glm::dmat4(1.0));
    for (int py = 0; py < kSize; py += 2) {
        for (int px = py % 4 / 2; px < kSize; px += 2) {
            const auto [origin, direction] = rays.at(px, py);
            const auto hit = caster.hit(origin, direction);
            if (!hit || hit->minBarycentric < 0.01) continue;
            const Material& material =
                model.materials[size_t(model.primitives[size_t(hit->primitive)].material)];
            if (material.name == "backdrop") continue;
            hits.push_back({px, py, &material, glm::vec3(hit->position), glm::vec3(hit->normal)});
        }
    }
    // E(NdotV, sheen roughness) at NdotV in steps of 1/50, by quadrature, and linearly between
    std::map<std::pair<int, int>, double> albedo;
    auto albedoAt = [&](float NdotV, float roughness) {
        const int r = int(std::lround(roughness * 1000.0f));
        auto at = [&](int step) {
            const std::pair<int, int> key{step, r};
            if (!albedo.count(key)) albedo[key] = cpu::sheenAlbedoQuadrature(step / 50.0, r / 1000.0);
            return albedo[key];
        };
        const int below = std::min(int(NdotV * 50.0f), 49);
        const double t = NdotV * 50.0 - below;
        return (1.0 - t) * at(below) + t * at(below + 1);
    };
    // the view at a point of material m with normal N, by 10's README
    auto viewOf = [&](const std::string& view, const Material& m, const glm::vec3& position,
                      const glm::vec3& N) -> std::optional<glm::vec3> {
        const glm::vec3 V = glm::normalize(eye - position);
        const glm::vec3 base(m.baseColorFactor);
        if (view == "f0") {  // from ior and KHR_materials_specular, then the metal's
            const cpu::DielectricFresnel f =
                cpu::dielectricFresnel(m.ior, m.khrSpecular.colorFactor, m.khrSpecular.factor);
            return encodedAs(glm::dvec3(glm::mix(f.F0, base, m.metallicFactor)));
        }
        if (view == "clearcoat") {
            return encodedAs(glm::dvec3(
                m.clearcoat.factor * cpu::clearcoatFresnel(cpu::iorToF0(m.ior), glm::dot(N, V))));
        }
        if (view == "clearcoat-normal") return encodedAs(0.5 + 0.5 * glm::dvec3(N));
        if (view == "transmission") return encodedAs(glm::dvec3(m.transmission.factor));
        if (view == "volume-attenuation") {
            // the refracted ray crosses the whole thickness (the nodes are unscaled)
            if (m.transmission.factor == 0.0f || !std::isfinite(m.volume.attenuationDistance))
                return encodedAs(glm::dvec3(1.0));
            return encodedAs(glm::pow(glm::dvec3(m.volume.attenuationColor),
                                      glm::dvec3(m.volume.thicknessFactor /
                                                 m.volume.attenuationDistance)));
        }
        if (view == "sheen-scaling") {
            const float NdotV = std::clamp(glm::dot(N, V), 0.0f, 1.0f);
            if (cpu::max3(m.sheen.colorFactor) == 0.0f) return encodedAs(glm::dvec3(1.0));
            if (NdotV < 0.1f) return std::nullopt;
            return encodedAs(glm::dvec3(1.0 - cpu::max3(m.sheen.colorFactor) *
                                                  albedoAt(NdotV, m.sheen.roughnessFactor)));
        }
        glm::dvec3 sheen(0.0);  // "sheen"
        for (const PunctualLight& light : model.lights) {
            glm::vec3 L;
            const glm::vec3 radiance = cpu::punctualRadiance(light, position, L);
            sheen += glm::dvec3(
                cpu::sheenDirect(N, V, L, m.sheen.colorFactor, m.sheen.roughnessFactor) * radiance);
        }
        return encodedAs(sheen / (1.0 + sheen));
    };
    for (const std::string& view : views) {
        SCOPED_TRACE("--view " + view);
        ASSERT_TRUE(images.count(view));
        const Image& image = images[view];
        SphereCheck check;
        for (const Hit& hit : hits) {
            const auto expected = expectedBytes(
                [&](const glm::vec3& n) { return viewOf(view, *hit.material, hit.position, n); },
                hit.normal);
            if (!expected) continue;
            for (int c = 0; c < 3; ++c) {
                const int diff = std::abs(int(image.at(hit.px, hit.py, c)) - (*expected)[c]);
                check.worst = std::max(check.worst, diff);
                EXPECT_LE(diff, 2) << hit.material->name << " pixel (" << hit.px << ", " << hit.py
                                   << "): rendered " << int(image.at(hit.px, hit.py, c))
                                   << ", CPU " << (*expected)[c];
            }
            ++check.compared[hit.material->name];
            ++check.total;
        }
        expectViewCompared("--view " + view, check, 8000, 35);
    }
}

// KHR_materials_transmission's limit (issue 46): a white ball that transmits everything, of index
// of refraction 1 (no refraction, F0 0) and roughness 0, thin-walled or with a volume but no
// attenuation, passes the backdrop behind it unchanged. One scene twice, 10 drawing it: a sphere
// in front of a square whose texture is a smooth gradient (a 2 x 2 image, linear filtering), lit
// from the camera's side; the second time the sphere's material masks every fragment away (the
// same bounds, so the same camera). Where the view meets the sphere head-on (NdotV > 0.8, where
// Schlick's grazing reflection is below 4e-4) both pictures agree within 1/255; at its rim
// (NdotV < 0.3) the reflection the glass still has there shows (a ball that is not drawn would
// pass the first check).
TEST(Reference, Gltf10AnIor1BallPassesTheBackdropUnchanged) {
    const fs::path dir = testOutputDir("reference_10_ior1_ball");
    const MeshData sphere = uvSphereTriangles(64, 32);
    GltfMeshArrays ball{sphere.positions, sphere.normals, sphere.uvs, sphere.tangents,
                        sphere.indices};
    GltfMeshArrays square;
    for (const glm::vec2 corner : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1),
                                   glm::vec2(-1, 1)}) {
        square.positions.push_back(glm::vec3(3.0f * corner, -2.0f));
        square.normals.push_back(glm::vec3(0.0f, 0.0f, 1.0f));
        square.uvs.push_back(glm::vec2(0.5f + 0.5f * corner.x, 0.5f - 0.5f * corner.y));
        square.tangents.push_back(glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    }
    square.indices = {0, 1, 2, 0, 2, 3};
    const std::string png = encodePng(Image{2, 2, 3, {230, 40, 30, 40, 200, 60, 40, 70, 220,
                                                       230, 210, 40}});
    const std::string image =
        "data:image/png;base64," + base64(std::vector<std::uint8_t>(png.begin(), png.end()));
    auto scene = [&](const std::string& name, const std::string& ballMaterial) {
        return writeTextFile(
            dir, name + ".gltf",
            R"({"asset":{"version":"2.0"},"extensionsUsed":["KHR_materials_transmission",)"
            R"("KHR_materials_ior","KHR_materials_volume","KHR_lights_punctual"],)" +
                meshBuffersJson({ball, square}) + R"("meshes":[{"primitives":[)" +
                meshPrimitiveJson(0, 0) + "]},{\"primitives\":[" + meshPrimitiveJson(1, 1) +
                R"(]}],"materials":[)" + ballMaterial +
                R"(,{"pbrMetallicRoughness":{"baseColorTexture":{"index":0},"metallicFactor":0,)"
                R"("roughnessFactor":1}}],"textures":[{"source":0,"sampler":0}],)"
                R"("samplers":[{"magFilter":9729,"minFilter":9729}],"images":[{"uri":")" +
                image +
                R"("}],"nodes":[{"mesh":0},{"mesh":1},{"extensions":{"KHR_lights_punctual":)"
                R"({"light":0}}}],"scenes":[{"nodes":[0,1,2]}],"scene":0,"extensions":)"
                R"({"KHR_lights_punctual":{"lights":[{"type":"directional","intensity":2}]}}})");
    };
    const glm::vec3 eye(0.0f, 0.0f, 5.0f);
    const Image without = render07(
        dir,
        scene("without",
              R"({"alphaMode":"MASK","alphaCutoff":0.5,"pbrMetallicRoughness":)"
              R"({"baseColorFactor":[1,1,1,0]}})"),
        eye, {}, "10_gltf_advanced_materials");
    for (const std::string volume : {"", R"(,"KHR_materials_volume":{"thicknessFactor":1.5})"}) {
        const std::string name = volume.empty() ? "thin" : "volume";
        SCOPED_TRACE(name);
        const fs::path file = scene(
            name, R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],"metallicFactor":0,)"
                  R"("roughnessFactor":0},"extensions":{"KHR_materials_transmission":)"
                  R"({"transmissionFactor":1},"KHR_materials_ior":{"ior":1})" +
                      volume + "}}");
        const Image with = render07(dir, file, eye, {}, "10_gltf_advanced_materials");
        const Rays rays(loadModel(file), eye);
        int head = 0, worst = 0, rim = 0, rimShows = 0;
        for (int py = 0; py < kSize; ++py) {
            for (int px = 0; px < kSize; ++px) {
                // the ray against the unit sphere at the origin
                const auto [origin, direction] = rays.at(px, py);
                const double b = glm::dot(origin, direction);
                const double c = glm::dot(origin, origin) - 1.0;
                if (b * b - c <= 0.0) continue;
                const glm::dvec3 at = origin + (-b - std::sqrt(b * b - c)) * direction;
                const double NdotV = -glm::dot(glm::normalize(at), direction);
                int diff = 0;
                for (int ch = 0; ch < 3; ++ch)
                    diff = std::max(diff, std::abs(int(with.at(px, py, ch)) - without.at(px, py, ch)));
                if (NdotV > 0.8) {
                    ++head;
                    worst = std::max(worst, diff);
                    EXPECT_LE(diff, 1) << "pixel (" << px << ", " << py << "), NdotV " << NdotV;
                } else if (NdotV < 0.3) {
                    ++rim;
                    rimShows += diff > 4 ? 1 : 0;
                }
            }
        }
        std::printf("%s: %d pixels head-on, worst channel difference %d/255; %d of %d rim pixels "
                    "show the glass\n",
                    name.c_str(), head, worst, rimShows, rim);
        EXPECT_GT(head, 5000);
        EXPECT_GT(rimShows, rim / 4);
    }
}

// An unlit material (KHR_materials_unlit) takes no light: its inputs show as any material's, and
// every term of the lighting is 0 (black) there. 03's showcase, all four objects unlit, through
// 07: wherever the base colour view shows an object, the D and direct views are black; and the
// program uses its `unlit` uniform in every view (no note that it is inactive).
TEST(Reference, Gltf07UnlitMaterialsHaveNoLightingTerms) {
    const fs::path dir = testOutputDir("reference_07_unlit_views");
    std::map<std::string, Image> views;
    for (const std::string view : {"base-color", "d", "direct"}) {
        const SampleRender render =
            renderSample("07_gltf_metallic_roughness", dir / (view + ".png"),
                         {"--model", (modelDir() / "unlit_showcase.gltf").string(), "--msaa", "0",
                          "--size", "320x180", "--view", view});
        ASSERT_EQ(render.run.exitCode, 0) << render.run.err;
        EXPECT_EQ(render.run.err.find("no active uniform"), std::string::npos) << render.run.err;
        views[view] = readImage(render.image, 3);
    }
    for (const std::string view : {"d", "direct"}) {
        int objects = 0, black = 0;
        const Image& terms = views[view];
        for (size_t p = 0; p < terms.pixels.size(); p += 3) {
            bool object = false, dark = true;
            for (size_t c = 0; c < 3; ++c) {
                object = object || views["base-color"].pixels[p + c] != terms.pixels[p + c];
                dark = dark && terms.pixels[p + c] == 0;
            }
            objects += object;
            black += object && dark;
        }
        std::printf("--view %s: %d of %d object pixels black\n", view.c_str(), black, objects);
        EXPECT_GT(objects, 2000) << view;
        EXPECT_EQ(black, objects) << view;
    }
}

// One punctual light alone (--light K): the showcase's second light by itself, in the summed views
// and the picture, against the CPU given that light alone.
TEST(Reference, Gltf07OneLightAlone) {
    std::map<std::string, Image> images = renderSpheresViews(
        testOutputDir("reference_07_spheres_light_2"), "07_gltf_metallic_roughness",
        modelDir() / "pbr_showcase.gltf", {"specular", "direct"}, {"--light", "2"});
    for (const std::string view : {"specular", "direct"}) {
        SCOPED_TRACE("--view " + view);
        ASSERT_TRUE(images.count(view));
        const SphereCheck check = compareShowcaseSpheres(
            "light_2_" + view, solidTexture, {"--light", "2", "--view", view},
            [&](const cpu::GltfSurface& s, const glm::vec3& eye,
                std::span<const PunctualLight> lights) -> std::optional<glm::vec3> {
                if (lights.size() < 2) return std::nullopt;
                return gltfPunctualView(view, s, eye, lights.subspan(1, 1));
            },
            false, &images[view]);
        expectViewCompared("--light 2 --view " + view, check, 1500, 10);
    }
}

// 07's image-based light's views on the showcase's spheres in the linear sky (tests/reference/
// linear_sky.h: the irradiance and the prefiltered levels in closed form, the glTF BRDF's LUT by
// quadrature), punctual lights off, no tone mapping: the reads as x / (1 + x) (the LUT's scale
// and bias as they are), the parts of cpu::gltfAmbient (multiple scattering on) as x / (1 + x),
// the ambient light alone and the picture itself clamped to [0, 1].
TEST(Reference, Gltf07IblTermViewsMatchTheCpu) {
    const fs::path dir = testOutputDir("reference_07_ibl_views");
    const std::string hdr = writeLinearSky(dir).string();
    const LinearSkyReads skyReads(true);
    auto compress = [](const glm::dvec3& x) { return x / (1.0 + x); };
    const std::vector<std::string> views = {"irradiance",      "prefiltered",        "lut",
                                            "ambient-diffuse", "ambient-specular",   "ambient",
                                            "final",           "multiple-scattering"};
    std::map<std::string, Image> images =
        renderSpheresViews(dir, "07_gltf_metallic_roughness", modelDir() / "pbr_showcase.gltf",
                           views, {"--hdr", hdr}, true);
    for (const std::string& view : views) {
        SCOPED_TRACE("--view " + view);
        ASSERT_TRUE(images.count(view));
        const SphereCheck check = compareShowcaseSpheres(
            "ibl_view_" + view, solidTexture, {"--hdr", hdr, "--view", view},
            [&](const cpu::GltfSurface& s, const glm::vec3& eye,
                std::span<const PunctualLight>) -> std::optional<glm::vec3> {
                const glm::dvec3 N(s.normal), V(glm::normalize(eye - s.position));
                // away from the rims, as in 05's test: there the mirror's environment is read at
                // a mip level the screen's derivatives choose, which blurs the sky's slope
                if (glm::dot(N, V) < 0.5) return std::nullopt;
                const SkyReads reads = skyReads.at(N, V, s.roughness, true);
                if (view == "irradiance") return encodedAs(compress(reads.irradiance));
                if (view == "prefiltered") return encodedAs(compress(reads.prefiltered));
                if (view == "lut") return encodedAs({reads.lut, 0.0});
                if (view == "multiple-scattering") {
                    // Fdez-Aguera's share, from the LUT's scale and bias: a white lobe loses
                    // 1 - (scale + bias); after further bounces, each tinted by the mean Fresnel
                    // F0 + (1 - F0) / 21, E_ms = lost F_avg E_ss / (1 - F_avg lost), lit by the
                    // irradiance; the dielectric's lobe and the metal's mixed by metallic
                    const double scale = reads.lut.x, bias = reads.lut.y,
                                 lost = 1.0 - (scale + bias);
                    const auto share = [&](const glm::dvec3& F0) {
                        const glm::dvec3 single = F0 * scale + bias;
                        const glm::dvec3 average = F0 + (1.0 - F0) / 21.0;
                        return lost * average * single / (1.0 - average * lost) * reads.irradiance;
                    };
                    return encodedAs(
                        compress(glm::mix(share(glm::dvec3(s.F0)), share(glm::dvec3(s.metalColor)),
                                          double(s.metallic))));
                }
                const cpu::GltfAmbient a =
                    cpu::gltfAmbient(s, glm::vec3(reads.irradiance), glm::vec3(reads.prefiltered),
                                     glm::vec2(reads.lut), true);
                if (view == "ambient-diffuse")
                    return encodedAs(compress(glm::dvec3((1.0f - s.metallic) * a.diffuse)));
                if (view == "ambient-specular")
                    return encodedAs(
                        compress(glm::dvec3(glm::mix(a.dielectricSpecular, a.metal, s.metallic))));
                return glm::clamp(glm::mix(a.diffuse + a.dielectricSpecular, a.metal, s.metallic),
                                  0.0f, 1.0f);  // ambient, and the picture: nothing else lights it
            },
            true, &images[view]);
        expectViewCompared("--view " + view, check, 1500, 10);
    }
}

// Occlusion and emission, which the showcase's spheres lack, on a square of known values: an
// occlusion texture of R 128 (G 20, B 240: the wrong channels) at strength 0.8, so 1 - 0.8 +
// 0.8 x 128/255; an emissive factor (0.9, 0.5, 0.2); a base colour (0.3, 0.6, 0.9). Each view
// shows its value as it is, at every pixel of the square, within 2/255.
TEST(Reference, Gltf07OcclusionAndEmissiveViews) {
    const fs::path dir = testOutputDir("reference_07_square_views");
    Image occlusion{2, 2, 3, {}};
    for (int i = 0; i < 4 * 3; ++i)
        occlusion.pixels.push_back(std::uint8_t(i % 3 == 0 ? 128 : i % 3 == 1 ? 20 : 240));
    writePng(dir / "occlusion.png", occlusion);
    const fs::path file = writeTextFile(dir, "square.gltf", R"({"asset":{"version":"2.0"},
)" + squareBuffersJson(1.0f) + R"(
"images":[{"uri":"occlusion.png"}],
"textures":[{"source":0}],
"materials":[{"pbrMetallicRoughness":{"baseColorFactor":[0.3,0.6,0.9,1],"metallicFactor":0},
  "occlusionTexture":{"index":0,"strength":0.8},"emissiveFactor":[0.9,0.5,0.2]}],
"meshes":[{"primitives":[)" + squarePrimitiveJson(0) + R"(]}],
"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})");
    const Model model = loadModel(file);
    const glm::vec3 eye(0.0f, 0.0f, 2.6f);
    const Rays rays(model, eye);
    const ModelRayCaster caster(model, glm::dmat4(1.0));
    const double strength = 0.8, texel = 128.0 / 255.0;
    for (const auto& [view, value] :
         {std::pair{std::string("occlusion"), glm::dvec3(1.0 - strength + strength * texel)},
          {"emissive", {0.9, 0.5, 0.2}},
          {"base-color", {0.3, 0.6, 0.9}}}) {
        fs::create_directories(dir / view);
        const Image image = render07(dir / view, file, eye, {"--view", view});
        int compared = 0, worst = 0;
        for (int py = 0; py < kSize; py += 2) {
            for (int px = 0; px < kSize; px += 2) {
                const auto [origin, direction] = rays.at(px, py);
                const auto hit = caster.hit(origin, direction);
                if (!hit || hit->minBarycentric < 0.01) continue;
                for (int c = 0; c < 3; ++c) {
                    const int diff =
                        std::abs(int(image.at(px, py, c)) - int(std::lround(255.0 * value[c])));
                    worst = std::max(worst, diff);
                    EXPECT_LE(diff, 2) << view << " pixel (" << px << ", " << py << ") channel "
                                       << c << ": rendered " << int(image.at(px, py, c));
                }
                ++compared;
            }
        }
        std::printf("--view %s: %d pixels of the square, worst channel difference %d/255\n",
                    view.c_str(), compared, worst);
        EXPECT_GT(compared, 3000) << view;
    }
}

// 08's spheres in the specular-glossiness workflow (factors only) against the CPU: the
// extension's conversion (F0 = specular, roughness = 1 - glossiness, c_diff = diffuse x
// (1 - max(specular))) through 07's BRDF.
TEST(Reference, Gltf08SpecularGlossinessSpheresMatchTheCpu) {
    const SphereCheck check = compareSpheres(
        testOutputDir("reference_08_spheres"), "08_gltf_specular_glossiness",
        modelDir() / "pbr_workflows_sg.gltf", "sg_",
        [](const Model&, const Material& m, const glm::vec3& position,
           const glm::vec3& normal) -> std::optional<cpu::GltfSurface> {
            EXPECT_TRUE(m.specularGlossiness) << m.name;
            if (m.baseColorTexture.present() || m.specularGlossinessTexture.present())
                return std::nullopt;  // the textured ones: the halves test below
            return cpu::specularGlossinessSurface(position, normal, glm::vec3(m.baseColorFactor),
                                                  m.specularFactor, m.glossinessFactor);
        });
    std::printf("08 spheres: %d pixels compared, worst channel difference %d/255\n", check.total,
                check.worst);
    EXPECT_GT(check.total, 3000);
    EXPECT_EQ(check.compared.size(), 8u);
}

// 08's term views on its factor-only specular-glossiness spheres: the inputs after the
// extension's conversion (base colour = the diffuse factor; f0 = the specular; roughness =
// 1 - glossiness; metallic 0) and the sun's terms through 07's BRDF, against the CPU.
TEST(Reference, Gltf08TermViewsMatchTheCpu) {
    const std::vector<std::string> views = {"base-color", "metallic", "roughness", "f0",
                                            "d",          "specular", "diffuse",   "direct"};
    const fs::path file = modelDir() / "pbr_workflows_sg.gltf";
    std::map<std::string, Image> images = renderSpheresViews(
        testOutputDir("reference_08_views"), "08_gltf_specular_glossiness", file, views);
    for (const std::string& view : views) {
        SCOPED_TRACE("--view " + view);
        ASSERT_TRUE(images.count(view));
        const SphereCheck check = compareSpheres(
            testOutputDir("reference_08_views_" + view), "08_gltf_specular_glossiness",
            modelDir() / "pbr_workflows_sg.gltf", "sg_",
            [](const Model&, const Material& m, const glm::vec3& position,
               const glm::vec3& normal) -> std::optional<cpu::GltfSurface> {
                if (m.baseColorTexture.present() || m.specularGlossinessTexture.present())
                    return std::nullopt;
                cpu::GltfSurface surface =
                    cpu::specularGlossinessSurface(position, normal, glm::vec3(m.baseColorFactor),
                                                   m.specularFactor, m.glossinessFactor);
                surface.metalColor = glm::vec3(m.baseColorFactor);  // what base-color shows
                return surface;
            },
            {"--view", view}, punctualViewShade(view), false, &images[view]);
        expectViewCompared("08 --view " + view, check, 3000, 8);
    }
}

// Where both workflows can say the same material, they draw the same: 08's two halves, each in
// a file of its own at the same place, under the same camera, agree within 1/255 at every pixel,
// with all the light (IBL and the file's sun) and with the sun alone (where the dark background
// leaves only the spheres unlike the corner: they must cover a good part of the picture).
TEST(Reference, Gltf08BothWorkflowsDrawTheSameMaterials) {
    const fs::path dir = testOutputDir("reference_08_halves");
    for (const bool ibl : {true, false}) {
        std::vector<Image> images;
        for (const char* half : {"pbr_workflows_mr", "pbr_workflows_sg"}) {
            std::vector<std::string> args = {"--model",
                                             (modelDir() / (std::string(half) + ".gltf")).string(),
                                             "--size", "640x360"};
            if (!ibl) args.push_back("--no-ibl");
            const SampleRender render =
                renderSample("08_gltf_specular_glossiness",
                             dir / (std::string(half) + (ibl ? "" : "_no_ibl") + ".png"), args);
            ASSERT_EQ(render.run.exitCode, 0) << render.run.err;
            images.push_back(readImage(render.image, 3));
        }
        const Image& mr = images[0];
        const Image& sg = images[1];
        ASSERT_EQ(mr.pixels.size(), sg.pixels.size());
        int worst = 0;
        size_t off = 0;
        for (size_t i = 0; i < mr.pixels.size(); ++i) {
            const int diff = std::abs(int(mr.pixels[i]) - int(sg.pixels[i]));
            worst = std::max(worst, diff);
            off += diff > 1 ? 1 : 0;
        }
        const double covered = double(pixelsUnlikeCorner(mr)) / double(mr.width * mr.height);
        std::printf("08 halves%s: worst channel difference %d/255; %.1f %% unlike the corner\n",
                    ibl ? "" : " (sun only)", worst, 100.0 * covered);
        EXPECT_LE(worst, 1) << off << " channel values differ by more than 1";
        if (!ibl) {
            EXPECT_GT(covered, 0.05);
        }
    }
}

}  // namespace
}  // namespace pbr::test
