// The term views (--view NAME) of the grid samples against the CPU, each by its definition in
// the sample's README. The inputs and the direct light's terms (01, 04, 05) come from the CPU
// mirror of the BRDF (cpu::cookTorrance); the image-based light's (04, 05) from an environment
// whose convolutions have closed forms, so that the irradiance, the prefiltered radiance and the
// LUT each have a value derived apart from the code that computes them. Which term, which
// lights, which channel and which encoding each view shows is this test's reading of the README.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "app/views.h"
#include "files/image.h"
#include "math/brdf.h"
#include "reference/grid_scene.h"
#include "reference/linear_sky.h"
#include "reference/view_terms.h"
#include "support/golden.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

// What a grid sample draws with: its point lights, its image-based light (none in 01; the
// irradiance alone in 04, the ambient light's diffuse part; the split sum in 05, in the text's
// form or the exact one) and whether that is on (--no-ibl).
struct GridLighting {
    std::span<const cpu::PointLight> lights = kGridLights;
    enum class Ibl { None, Irradiance, SplitSum } ibl = Ibl::None;
    bool iblOn = true;
    bool exactSplitSum = false;
    double gain = 1.0;  // --gain: x / (1 + x) of gain x, for the views shown so
};

// A view of a grid sample at surface point `s`, each by its definition in the samples' READMEs:
// the inputs as they are (the normal as 0.5 + 0.5 N); a light-dependent term summed over the
// lights above the horizon (NdotL > 0) and shown as x / (1 + x); the direct light alone through
// the picture's Reinhard and gamma; the image-based light's reads and the ambient light's two
// parts (occlusion included, zero with --no-ibl) as x / (1 + x), the LUT's scale and bias as
// they are (red, green), the ambient light alone and the picture ("final", 04 and 05) through
// Reinhard and gamma. The terms come from the CPU mirror (cpu::cookTorrance,
// cpu::splitSumAmbient); which term, which lights, which channel and which encoding each view
// shows is this test's reading.
glm::dvec3 gridView(const std::string& view, const cpu::SurfacePoint& s, const glm::vec3& camera,
                    const GridLighting& lighting, const LinearSkyReads& skyReads) {
    const glm::vec3 N = s.normal, V = glm::normalize(camera - s.position);
    if (const auto input = inputView(view, s)) return *input;
    auto compress = [](const glm::dvec3& x) { return x / (1.0 + x); };
    glm::dvec3 sum(0.0), direct(0.0);
    for (const cpu::PointLight& light : lighting.lights) {
        const glm::vec3 L = glm::normalize(light.position - s.position);
        const float distance = glm::length(light.position - s.position);
        direct += glm::dvec3(cpu::directLight(N, V, L, light.color / (distance * distance),
                                              s.albedo, s.metallic, s.roughness));
        if (glm::dot(N, L) <= 0.0f) continue;
        const cpu::CookTorrance t = cpu::cookTorrance(N, V, L, s.albedo, s.metallic, s.roughness);
        addTermView(view, t, s.albedo, sum);
    }
    if (view == "direct") return glm::dvec3(cpu::reinhardGamma(glm::vec3(direct)));
    if (lighting.ibl == GridLighting::Ibl::None) {
        // LearnOpenGL's stand-in for the environment: 0.03 x albedo x ao, alone
        if (view == "ambient") return glm::dvec3(cpu::reinhardGamma(0.03f * s.albedo * s.ao));
        return compress(sum);
    }

    const SkyReads reads = skyReads.at(glm::dvec3(N), glm::dvec3(V), s.roughness,
                                       lighting.ibl == GridLighting::Ibl::SplitSum);
    if (view == "ks" || view == "kd" || view == "f-scale-bias") {
        // the ambient light's weights, as they are: the text's, kS = F = fresnelSchlickRoughness
        // (F0 + (max(1 - roughness, F0) - F0) (1 - NdotV)^5), kD = (1 - kS)(1 - metallic) and
        // F scale + bias; the exact split sum's, E = F0 scale + bias for both kS and the factor,
        // kD = (1 - metallic)(1 - (0.04 scale + bias))
        const glm::dvec3 F0 = glm::mix(glm::dvec3(0.04), glm::dvec3(s.albedo), double(s.metallic));
        const double NdotV = std::max(glm::dot(glm::dvec3(N), glm::dvec3(V)), 0.0);
        const double scale = reads.lut.x, bias = reads.lut.y;
        glm::dvec3 ks, kd, factor;
        if (lighting.exactSplitSum) {
            ks = factor = F0 * scale + bias;
            kd = glm::dvec3((1.0 - s.metallic) * (1.0 - (0.04 * scale + bias)));
        } else {
            ks = F0 +
                 (glm::max(glm::dvec3(1.0 - s.roughness), F0) - F0) * std::pow(1.0 - NdotV, 5.0);
            kd = (1.0 - ks) * (1.0 - s.metallic);
            factor = ks * scale + bias;
        }
        return view == "ks" ? ks : view == "kd" ? kd : factor;
    }
    if (view == "irradiance") return compress(reads.irradiance);
    if (view == "prefiltered") return compress(reads.prefiltered);
    if (view == "lut") return {reads.lut, 0.0};
    cpu::SplitSumAmbient ambient =
        cpu::splitSumAmbient(std::max(glm::dot(N, V), 0.0f), s.albedo, s.metallic, s.roughness,
                             glm::vec3(reads.irradiance), glm::vec3(reads.prefiltered),
                             glm::vec2(reads.lut), lighting.exactSplitSum);
    if (lighting.ibl == GridLighting::Ibl::Irradiance) ambient.specular = glm::vec3(0.0f);
    const float shown = lighting.iblOn ? s.ao : 0.0f;
    const glm::dvec3 diffuse(ambient.diffuse * shown), specular(ambient.specular * shown);
    if (view == "ambient-diffuse") return compress(diffuse);
    if (view == "ambient-specular") return compress(specular);
    if (view == "ambient") return glm::dvec3(cpu::reinhardGamma(glm::vec3(diffuse + specular)));
    if (view == "final")
        return glm::dvec3(cpu::reinhardGamma(glm::vec3(diffuse + specular + direct)));
    return compress(sum);
}

// The surface at a hit on sphere (row, col), or nullopt where it must not be compared.
using SurfaceAt = std::function<std::optional<cpu::SurfacePoint>(const Hit&, int row, int col)>;
std::optional<cpu::SurfacePoint> constantMaterial(const Hit& hit, int row, int col) {
    return gridSurface(hit.position, hit.normal, row, col);
}

// Renders `views` of a grid sample (640 x 360, no MSAA; `args` added; one run, renderViews) and
// compares each with gridView on the spheres, where NdotV >= 0.5.
void compareViews(const std::string& sample, const std::vector<std::string>& views,
                  const std::vector<std::string>& args, const GridLighting& lighting, double gridZ,
                  const fs::path& dir, const SurfaceAt& surfaceAt = constantMaterial) {
    LinearSkyReads skyReads;
    const GridFrame frame{.width = 640, .height = 360, .gridZ = gridZ};
    std::vector<std::string> all = {"--msaa", "0", "--size", "640x360"};
    all.insert(all.end(), args.begin(), args.end());
    const ViewRenders renders = renderViews(sample, views, all, dir);
    ASSERT_EQ(renders.run.exitCode, 0) << renders.run.err;
    for (const std::string& view : views) {
        SCOPED_TRACE(sample + " --view " + view);
        ASSERT_TRUE(renders.images.count(view)) << "no picture\n" << renders.run.out;
        const Image image = readImage(renders.images.at(view), 3);
        ASSERT_EQ(image.width, frame.width);
        const Comparison result = compareGrid(
            image, [&](double x, double y, int row, int col) -> std::optional<glm::dvec3> {
                const auto hit = hitSphere(x, y, row, col, frame);
                if (!hit || hit->ndotv < 0.5) return std::nullopt;
                const auto surface = surfaceAt(*hit, row, col);
                if (!surface) return std::nullopt;
                glm::dvec3 shown =
                    gridView(view, *surface, glm::vec3(gridCamera(gridZ)), lighting, skyReads);
                if (lighting.gain != 1.0 && viewScale(viewNamed(view)) == ViewScale::Compressed) {
                    // y = x / (1 + x) gives x = y / (1 - y); the gain makes it g x / (1 + g x)
                    const glm::dvec3 x = shown / (1.0 - shown);
                    shown = lighting.gain * x / (1.0 + lighting.gain * x);
                }
                return 255.0 * shown;
            });
        std::printf("%s --view %s: compared %d pixels (skipped %d); worst channel diff %.0f/255\n",
                    sample.c_str(), view.c_str(), result.checked, result.skipped, result.worst);
        EXPECT_GE(result.checked, 49 * 20);
    }
}

const std::vector<std::string> kInputAndDirectViews = {
    "albedo", "normal", "metallic", "roughness", "ao",    "f0",    "d",
    "g",      "f",      "specular", "diffuse",   "ndotl", "direct"};

TEST(Reference, Lighting01TermViewsMatchTheCpu) {
    std::vector<std::string> views = kInputAndDirectViews;
    views.push_back("ambient");
    compareViews("01_lighting", views, {}, {}, 0.0, testOutputDir("reference_01_views"));
    // a gain for the dark terms (--gain 8: x / (1 + x) of 8 x); the inputs keep theirs
    compareViews("01_lighting", {"specular", "diffuse", "ndotl", "albedo"}, {"--gain", "8"},
                 {.gain = 8.0}, 0.0, testOutputDir("reference_01_views_gain"));
    // one light alone (--light K): the third, up and to the left of the grid's right half
    compareViews("01_lighting", {"d", "f", "specular", "ndotl", "direct"}, {"--light", "3"},
                 {.lights = std::span(kGridLights).subspan(2, 1)}, 0.0,
                 testOutputDir("reference_01_views_light_3"));
}

// 02 in a material of random texels, drawn with nearest filtering so that the CPU reads the
// texel the GPU reads (randomTexels): every input as the maps give it (the normal after the normal
// map), every term of its one light.
TEST(Reference, Textured02TermViewsMatchTheCpu) {
    const fs::path dir = testOutputDir("reference_02_views");
    const TexelMaterial material = randomTexels();
    const fs::path set = writeTexelMaterial(material, dir / "random_texels");
    std::vector<std::string> views = kInputAndDirectViews;
    views.push_back("ambient");  // with the maps' ao
    compareViews("02_lighting_textured", views,
                 {"--filter", "nearest", "--material-dir", set.string(), "--camera",
                  "0,0,23"},  // the whole grid (02 starts closer)
                 {.lights = std::span(&kTexturedGridLight, 1)}, 0.0, dir,
                 [&](const Hit& hit, int, int) { return texelSurface(material, hit); });
}

// 04 and 05 in the linear sky. Every view of each, then the parts of the light each alone: the
// image-based light without the point lights (--lights 0: the picture is the ambient light),
// the point lights without it (--no-ibl), and 05's exact split sum, whose diffuse is what the
// dielectric's lobe leaves.
TEST(Reference, Irradiance04TermViewsMatchTheCpu) {
    const fs::path dir = testOutputDir("reference_04_views");
    const std::string hdr = writeLinearSky(dir).string();
    std::vector<std::string> views = kInputAndDirectViews;
    views.insert(views.end(), {"irradiance", "ambient-diffuse", "ambient", "final", "ks", "kd"});
    const GridLighting lighting{.ibl = GridLighting::Ibl::Irradiance};
    compareViews("04_ibl_irradiance", views, {"--hdr", hdr}, lighting, -2.0, dir);

    compareViews("04_ibl_irradiance", {"final"}, {"--hdr", hdr, "--lights", "0"},
                 {.lights = {}, .ibl = GridLighting::Ibl::Irradiance}, -2.0, dir / "no_lights");
    compareViews("04_ibl_irradiance", {"d", "direct"}, {"--hdr", hdr, "--light", "1"},
                 {.lights = std::span(kGridLights).first(1), .ibl = GridLighting::Ibl::Irradiance},
                 -2.0, dir / "light_1");
    compareViews("04_ibl_irradiance", {"final", "ambient"}, {"--hdr", hdr, "--no-ibl"},
                 {.ibl = GridLighting::Ibl::Irradiance, .iblOn = false}, -2.0, dir / "no_ibl");
}

TEST(Reference, SplitSum05TermViewsMatchTheCpu) {
    const fs::path dir = testOutputDir("reference_05_views");
    const std::string hdr = writeLinearSky(dir).string();
    std::vector<std::string> views = kInputAndDirectViews;
    views.insert(views.end(), {"irradiance", "prefiltered", "lut", "ambient-diffuse",
                               "ambient-specular", "ambient", "final", "ks", "kd", "f-scale-bias"});
    const GridLighting lighting{.ibl = GridLighting::Ibl::SplitSum};
    compareViews("05_ibl_specular", views, {"--hdr", hdr}, lighting, -2.0, dir);

    compareViews("05_ibl_specular",
                 {"ambient-diffuse", "ambient-specular", "final", "ks", "kd", "f-scale-bias"},
                 {"--hdr", hdr, "--split-sum", "exact"},
                 {.ibl = GridLighting::Ibl::SplitSum, .exactSplitSum = true}, -2.0, dir / "exact");
    compareViews("05_ibl_specular", {"final"}, {"--hdr", hdr, "--lights", "0"},
                 {.lights = {}, .ibl = GridLighting::Ibl::SplitSum}, -2.0, dir / "no_lights");
    compareViews("05_ibl_specular", {"final", "ambient"}, {"--hdr", hdr, "--no-ibl"},
                 {.ibl = GridLighting::Ibl::SplitSum, .iblOn = false}, -2.0, dir / "no_ibl");
}

// 05 --textured: the irradiance view is the irradiance at the shading normal, the normal map's
// (the view reads the irradiance map, not the prefiltered one). The normals come from the same
// run's normal view (0.5 + 0.5 N, 8 bits: at most 0.4 % off), the irradiance from the linear
// sky's closed form; compared on the five spheres away from their rims. (Planted, an irradiance
// view reading the prefiltered map passed every test.)
TEST(Reference, SplitSum05TexturedIrradianceViewIsAtTheMappedNormal) {
    const fs::path dir = testOutputDir("reference_05_textured_irradiance");
    const std::string hdr = writeLinearSky(dir).string();
    const LinearSkyReads skyReads;
    const int width = 320, height = 180;
    std::map<std::string, Image> views;
    const ViewRenders renders =
        renderViews("05_ibl_specular", {"normal", "irradiance"},
                    {"--textured", "--hdr", hdr, "--msaa", "0", "--size", "320x180"}, dir);
    ASSERT_EQ(renders.run.exitCode, 0) << renders.run.err;
    for (const auto& [view, image] : renders.images) views[view] = readImage(image, 3);
    ASSERT_EQ(views.size(), 2u) << renders.run.out;
    // the row of five at z = -2, 2.5 apart, seen from (0, 0, 8) down -Z through 45 degrees
    const glm::dvec3 eye(0.0, 0.0, 8.0);
    const double tanHalf = std::tan(std::numbers::pi / 8.0);
    int compared = 0, worst = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const glm::dvec3 d = glm::normalize(
                glm::dvec3((2.0 * (x + 0.5) / width - 1.0) * tanHalf * width / height,
                           (1.0 - 2.0 * (y + 0.5) / height) * tanHalf, -1.0));
            bool onSphere = false;
            for (int col = 0; col < 5 && !onSphere; ++col) {
                const glm::dvec3 centre((col - 2) * 2.5, 0.0, -2.0), oc = eye - centre;
                const double b = glm::dot(oc, d), disc = b * b - (glm::dot(oc, oc) - 1.0);
                if (disc <= 0.0) continue;
                const glm::dvec3 n = glm::normalize(eye + (-b - std::sqrt(disc)) * d - centre);
                onSphere = glm::dot(n, -d) >= 0.5;  // away from the rim
            }
            if (!onSphere) continue;
            const size_t at = (size_t(y) * width + size_t(x)) * 3;
            glm::dvec3 n;
            for (int c = 0; c < 3; ++c)
                n[c] = 2.0 * views["normal"].pixels[at + size_t(c)] / 255.0 - 1.0;
            const glm::dvec3 irradiance = skyReads.at(glm::normalize(n), -d, 0.5f, true).irradiance;
            for (int c = 0; c < 3; ++c) {
                const double expected = 255.0 * irradiance[c] / (1.0 + irradiance[c]);
                worst = std::max(
                    worst, int(std::lround(
                               std::abs(views["irradiance"].pixels[at + size_t(c)] - expected))));
            }
            ++compared;
        }
    }
    std::printf("05 --textured --view irradiance: %d pixels, worst channel difference %d/255\n",
                compared, worst);
    EXPECT_GT(compared, 3000);
    EXPECT_LE(worst, 3);
}

}  // namespace
}  // namespace pbr::test
