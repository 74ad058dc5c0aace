// Sample 09 against the CPU: each light type alone (--only), on the plain material
// (--untextured: floor albedo 0.8 grey, metallic 0, roughness 0.9, ao 1, normal +Y), every floor
// pixel the spheres do not hide, shaded by pbr::cpu::shadeLightTypes (common/math/brdf.cpp, written
// apart from light_types.glsl) and the engine's Reinhard + gamma. Pixels are counted on both
// sides of every edge: inside, in the band of and outside the spot's cone; inside and outside
// each ambient volume (pixels whose neighbours fall on the other side are left out: the edge
// itself is a step). The point light's three attenuation terms are checked each alone.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "reference/view_terms.h"
#include "support/golden.h"
#include "support/mesh_hit.h"
#include "support/process.h"

#include "../../samples/09_light_types/scene.h"
#include "files/image.h"
#include "gl/mesh.h"
#include "math/brdf.h"
#include "math/camera.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

constexpr int kSceneWidth = 320, kSceneHeight = 180;
const glm::vec3 kEye(0.0f, 5.5f, 12.0f);
constexpr float kYaw = -90.0f, kPitch = -22.0f;

struct FloorPixel {
    int x, y;
    glm::vec3 point;
};

// The floor point each pixel centre sees, unless a sphere is in the way (or nearly: rays that
// pass within 2 cm of one are left out, for the silhouettes' antialiasing-free steps).
std::optional<glm::vec3> floorPoint(const glm::dmat4& toWorld, double px, double py) {
    const auto [origin, direction] = pixelRay(toWorld, kSceneWidth, kSceneHeight, int(px), int(py));
    if (direction.y >= 0.0) return std::nullopt;
    const double t = -origin.y / direction.y;
    const glm::dvec3 hit = origin + t * direction;
    if (std::abs(hit.x) > light_types::kFloorHalfX - 0.05 ||
        std::abs(hit.z) > light_types::kFloorHalfZ - 0.05)
        return std::nullopt;
    for (int i = 0; i < 5; ++i) {
        const glm::dvec3 c(light_types::sphereCentre(i));
        const double along = glm::dot(c - origin, direction);
        const double miss = glm::length(c - origin - along * direction);
        if (along > 0.0 && along < t && miss < light_types::kSphereRadius + 0.02)
            return std::nullopt;
    }
    return glm::vec3(hit);
}

struct TypeCheck {
    int compared = 0, worst = 0;
    std::vector<int> byClass;  // pixels compared in each class of the edge test
};

// Renders `only` (with `extra` flags) and compares every usable floor pixel. `classify` sorts a
// floor point into classes (-1: none); pixels whose 4-neighbours land in another class are left
// out when `stepEdges` (a discontinuous edge).
TypeCheck checkType(const std::string& only, const std::vector<std::string>& extra,
                    pbr::Attenuation attenuation, int classes,
                    const std::function<int(const glm::vec3&)>& classify, bool stepEdges) {
    const fs::path dir = testOutputDir("reference_09_" + only);
    std::vector<std::string> args = {
        "--only",
        only,
        "--untextured",
        "--msaa",
        "0",
        "--size",
        std::to_string(kSceneWidth) + "x" + std::to_string(kSceneHeight),
        "--camera",
        "0,5.5,12,-90,-22"};
    args.insert(args.end(), extra.begin(), extra.end());
    const SampleRender render =
        renderSample("09_light_types", dir / (only + std::to_string(extra.size()) + ".png"), args);
    EXPECT_EQ(render.run.exitCode, 0) << render.run.err;
    const Image image = readImage(render.image, 3);

    std::vector<PackedLight> lights;
    for (const PackedLight& light : light_types::sceneLights(attenuation)) {
        if (kLightTypeNames[int(light.type())] == only) lights.push_back(light);
    }
    EXPECT_EQ(lights.size(), 1u);

    const FlyCamera camera(kEye, kYaw, kPitch);
    const glm::dmat4 toWorld = glm::inverse(glm::dmat4(
        camera.projectionMatrix(float(kSceneWidth) / float(kSceneHeight)) * camera.viewMatrix()));
    TypeCheck check;
    check.byClass.assign(size_t(classes), 0);
    for (int py = 0; py < kSceneHeight; ++py) {
        for (int px = 0; px < kSceneWidth; ++px) {
            const auto point = floorPoint(toWorld, px, py);
            if (!point) continue;
            const int cls = classify ? classify(*point) : 0;
            if (cls < 0) continue;
            if (stepEdges) {
                bool edge = false;
                for (const auto& [dx, dy] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}}) {
                    const auto n = floorPoint(toWorld, px + dx, py + dy);
                    if (!n || classify(*n) != cls) edge = true;
                }
                if (edge) continue;
            }
            const cpu::SurfacePoint surface{*point, {0.0f, 1.0f, 0.0f}, glm::vec3(0.8f), 0.0f, 0.9f,
                                            1.0f};
            const glm::vec3 expected =
                cpu::reinhardGamma(cpu::shadeLightTypes(surface, kEye, lights)) * 255.0f;
            for (int c = 0; c < 3; ++c) {
                const int want = int(std::lround(std::clamp(expected[c], 0.0f, 255.0f)));
                const int diff = std::abs(int(image.at(px, py, c)) - want);
                check.worst = std::max(check.worst, diff);
                EXPECT_LE(diff, 2) << only << " pixel (" << px << ", " << py << ") channel " << c
                                   << ": rendered " << int(image.at(px, py, c)) << ", CPU " << want;
            }
            ++check.compared;
            ++check.byClass[size_t(cls)];
        }
    }
    return check;
}

void report(const std::string& what, const TypeCheck& check) {
    std::printf("%s: %d floor pixels, worst %d/255; by class:", what.c_str(), check.compared,
                check.worst);
    for (int n : check.byClass) std::printf(" %d", n);
    std::printf("\n");
}

TEST(Reference, LightTypes09PointAndDirectional) {
    for (const char* only : {"point", "directional"}) {
        const TypeCheck check =
            checkType(only, {}, light_types::kPointAttenuation, 1, nullptr, false);
        report(only, check);
        EXPECT_GT(check.compared, 5000) << only;
    }
}

// The cone: inside the cut-off, in the soft band, outside the outer angle.
TEST(Reference, LightTypes09SpotCone) {
    const PackedLight spot = light_types::sceneLights(light_types::kPointAttenuation)[2];
    ASSERT_EQ(spot.type(), LightType::Spot);
    const float inner = std::cos(glm::radians(spot.cutoff()));
    const float outer = std::cos(glm::radians(spot.outerCutoff()));
    const TypeCheck check = checkType(
        "spot", {}, light_types::kPointAttenuation, 3,
        [&](const glm::vec3& p) {
            const float theta = glm::dot(glm::normalize(spot.position() - p), -spot.forward());
            return theta > inner + 1e-3f   ? 0
                   : theta > outer + 1e-3f ? 1
                   : theta < outer - 1e-3f ? 2
                                           : -1;
        },
        false);
    report("spot (inside, band, outside)", check);
    for (int cls = 0; cls < 3; ++cls) EXPECT_GT(check.byClass[size_t(cls)], 300) << cls;
}

// The ambient volumes: a step at the box's faces and the sphere's surface.
TEST(Reference, LightTypes09AmbientVolumes) {
    const auto lights = light_types::sceneLights(light_types::kPointAttenuation);
    for (const int index : {3, 4}) {
        const PackedLight volume = lights[size_t(index)];
        const std::string only = index == 3 ? "ambient-box" : "ambient-sphere";
        const TypeCheck check = checkType(
            only, {}, light_types::kPointAttenuation, 2,
            [&](const glm::vec3& p) { return cpu::insideAmbientVolume(volume, p) ? 0 : 1; }, true);
        report(only + " (inside, outside)", check);
        EXPECT_GT(check.byClass[0], 300) << only;
        EXPECT_GT(check.byClass[1], 300) << only;
    }
}

// 1 / (c + l d + q d^2) with each term alone: constant (no falloff), linear (1/d), quadratic
// (1/d^2), through --attenuation.
TEST(Reference, LightTypes09AttenuationTermsEachAlone) {
    for (const auto& [flag, terms] : {std::pair{"1,0,0", Attenuation{1, 0, 0}},
                                      {"0,1,0", Attenuation{0, 1, 0}},
                                      {"0,0,1", Attenuation{0, 0, 1}}}) {
        const TypeCheck check =
            checkType("point", {"--attenuation", flag}, terms, 1, nullptr, false);
        report(std::string("point, attenuation ") + flag, check);
        EXPECT_GT(check.compared, 5000) << flag;
    }
}

// ---- 09's term views, on the floor and the spheres ----

constexpr int kViewWidth = 640, kViewHeight = 360;

// What each pixel centre of the plain scene (--untextured) sees: the floor or a sphere (the very
// triangles of the 64 x 32 mesh the GPU draws, normals interpolated at the hit), as the surface
// point the CPU shades; object 0 the floor, 1-5 the spheres left to right, -1 nothing.
struct ScenePixel {
    int object = -1;
    cpu::SurfacePoint surface;
};

std::vector<ScenePixel> plainScene() {
    const FlyCamera camera(kEye, kYaw, kPitch);
    const glm::dmat4 toWorld = glm::inverse(glm::dmat4(
        camera.projectionMatrix(float(kViewWidth) / float(kViewHeight)) * camera.viewMatrix()));
    const MeshData sphere = uvSphere(64, 32);
    const std::vector<light_types::Object> objects = light_types::objects();
    std::vector<ScenePixel> pixels(size_t(kViewWidth) * kViewHeight);
    for (int py = 0; py < kViewHeight; ++py) {
        for (int px = 0; px < kViewWidth; ++px) {
            const auto [origin, direction] = pixelRay(toWorld, kViewWidth, kViewHeight, px, py);
            ScenePixel& pixel = pixels[size_t(py) * kViewWidth + size_t(px)];
            double nearest = 1e30;
            if (direction.y < 0.0) {
                const double t = -origin.y / direction.y;
                const glm::dvec3 p = origin + t * direction;
                if (std::abs(p.x) < light_types::kFloorHalfX &&
                    std::abs(p.z) < light_types::kFloorHalfZ) {
                    nearest = t;
                    pixel.object = 0;
                    pixel.surface = {glm::vec3(p),
                                     {0.0f, 1.0f, 0.0f},
                                     glm::vec3(0.8f),
                                     objects[0].plainMetallic,
                                     objects[0].plainRoughness,
                                     1.0f};
                }
            }
            for (int i = 0; i < 5; ++i) {
                const glm::dvec3 c(light_types::sphereCentre(i));
                const double along = glm::dot(c - origin, direction);
                if (glm::length(c - origin - along * direction) > light_types::kSphereRadius + 0.01)
                    continue;  // not even near the sphere
                const auto hit = hitUvSphere(
                    sphere, 64, 32, glm::dmat4(objects[size_t(i + 1)].model), origin, direction);
                if (!hit || hit->distance >= nearest) continue;
                nearest = hit->distance;
                pixel.object = i + 1;
                const light_types::Object& object = objects[size_t(i + 1)];
                pixel.surface = {glm::vec3(hit->position), glm::vec3(hit->normal),
                                 glm::vec3(object.tint),   object.plainMetallic,
                                 object.plainRoughness,    1.0f};
            }
        }
    }
    return pixels;
}

// A view of the plain scene at `s` by its definition in 09's README: the inputs as they are (the
// normal as 0.5 + 0.5 N); a direct light's term summed over the lights that reach the point
// (above its horizon, inside a spot's cone) as x / (1 + x); the direct light alone, the ambient
// volumes' light alone and the picture through Reinhard and gamma.
glm::dvec3 lightTypesView(const std::string& view, const cpu::SurfacePoint& s,
                          std::span<const PackedLight> lights) {
    const glm::vec3 N = s.normal, V = glm::normalize(kEye - s.position);
    if (const auto input = inputView(view, s)) return *input;
    if (view == "final")
        return glm::dvec3(cpu::reinhardGamma(cpu::shadeLightTypes(s, kEye, lights)));
    glm::dvec3 sum(0.0);
    glm::vec3 direct(0.0f), ambient(0.0f);
    double attenuation = 0.0, cone = 0.0;
    for (const PackedLight& light : lights) {
        glm::vec3 L;
        const glm::vec3 radiance = cpu::lightTypeRadiance(light, s.position, L);
        const glm::dvec3 toLight = glm::dvec3(light.position()) - glm::dvec3(s.position);
        const double d = glm::length(toLight);
        if (light.type() == LightType::Point || light.type() == LightType::Spot) {
            // the text's 1 / (constant + linear d + quadratic d^2), in double here
            attenuation +=
                1.0 / (light.constant() + light.linear() * d + light.quadratic() * d * d);
        }
        if (light.type() == LightType::Spot) {
            // 1 inside the cut-off, 0 beyond cut-off + outer, linear in the cosine between
            const double inner = std::cos(glm::radians(double(light.cutoff())));
            const double outer =
                std::cos(glm::radians(double(light.outerCutoff())));  // cut-off + outer
            const double theta =
                glm::dot(toLight / d, -glm::normalize(glm::dvec3(light.forward())));
            cone += std::clamp((theta - outer) / (inner - outer), 0.0, 1.0);
        }
        if (cpu::isAmbientVolume(light)) {
            ambient += radiance;
            continue;
        }
        direct += cpu::directLight(N, V, L, radiance, s.albedo, s.metallic, s.roughness);
        if (radiance == glm::vec3(0.0f) || glm::dot(N, L) <= 0.0f) continue;
        const cpu::CookTorrance t = cpu::cookTorrance(N, V, L, s.albedo, s.metallic, s.roughness);
        addTermView(view, t, s.albedo, sum);
    }
    if (view == "direct") return glm::dvec3(cpu::reinhardGamma(direct));
    if (view == "ambient") return glm::dvec3(cpu::reinhardGamma(ambient * s.albedo * s.ao));
    if (view == "attenuation") return glm::dvec3(attenuation / (1.0 + attenuation));
    if (view == "cone") return glm::dvec3(cone);
    return sum / (1.0 + sum);
}

// Every view of 09's plain scene, every pixel whose four neighbours see the same object and whose
// prediction the neighbours' does not change by more than 8/255 (off the silhouettes, the ambient
// volumes' steps and the pin-point highlights), within 2/255. Among them the right sphere's top,
// above the ambient box (1.25 m), and the spheres' metallic, 0 to 1 from left to right: the box's
// height and the metallic factor, which the tests above, on the floor alone, could not see.
TEST(Reference, LightTypes09TermViewsMatchTheCpu) {
    const fs::path dir = testOutputDir("reference_09_views");
    const std::vector<ScenePixel> scene = plainScene();
    const std::vector<PackedLight> lights =
        light_types::sceneLights(light_types::kPointAttenuation);
    auto at = [&](int px, int py) -> const ScenePixel& {
        return scene[size_t(py) * kViewWidth + size_t(px)];
    };
    const std::vector<std::string> views = {
        "albedo", "normal",  "metallic", "roughness",   "ao",      "f0",
        "d",      "g",       "f",        "specular",    "diffuse", "ndotl",
        "direct", "ambient", "final",    "attenuation", "cone"};
    const ViewRenders renders =
        renderViews("09_light_types", views,
                    {"--untextured", "--msaa", "0", "--size",
                     std::to_string(kViewWidth) + "x" + std::to_string(kViewHeight), "--camera",
                     "0,5.5,12,-90,-22"},
                    dir);
    ASSERT_EQ(renders.run.exitCode, 0) << renders.run.err;
    for (const std::string& view : views) {
        SCOPED_TRACE("--view " + view);
        ASSERT_TRUE(renders.images.count(view)) << renders.run.out;
        const Image image = readImage(renders.images.at(view), 3);
        ASSERT_EQ(image.width, kViewWidth);
        int compared = 0, onSpheres = 0, aboveTheBox = 0, failed = 0, worst = 0;
        for (int py = 1; py + 1 < kViewHeight; ++py) {
            for (int px = 1; px + 1 < kViewWidth; ++px) {
                const ScenePixel& pixel = at(px, py);
                if (pixel.object < 0) continue;
                const glm::dvec3 expected = 255.0 * lightTypesView(view, pixel.surface, lights);
                bool steady = true;
                for (const auto& [dx, dy] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}}) {
                    const ScenePixel& n = at(px + dx, py + dy);
                    if (n.object != pixel.object ||
                        glm::length(255.0 * lightTypesView(view, n.surface, lights) - expected) >
                            8.0)
                        steady = false;
                }
                if (!steady) continue;
                for (int c = 0; c < 3; ++c) {
                    const int diff =
                        std::abs(int(image.at(px, py, c)) - int(std::lround(expected[c])));
                    worst = std::max(worst, diff);
                    if (diff > 2 && ++failed <= 5) {
                        ADD_FAILURE() << "object " << pixel.object << " pixel (" << px << ", " << py
                                      << ") channel " << c << ": rendered "
                                      << int(image.at(px, py, c)) << ", CPU " << expected[c];
                    }
                }
                ++compared;
                if (pixel.object > 0) ++onSpheres;
                if (pixel.object == 5 && pixel.surface.position.y > 1.3f) ++aboveTheBox;
            }
        }
        EXPECT_EQ(failed, 0) << "channels off by more than 2/255";
        std::printf(
            "--view %s: compared %d pixels (%d on the spheres, %d of the right sphere "
            "above the ambient box); worst channel diff %d/255\n",
            view.c_str(), compared, onSpheres, aboveTheBox, worst);
        EXPECT_GT(compared, 50000);
        EXPECT_GT(onSpheres, 5000);
        if (view == "ambient") {
            EXPECT_GT(aboveTheBox, 100);
        }
    }
}

// 09 in its material sets, whose ao maps lie below 1: the ambient view is the ambient volumes'
// light times the albedo times the ao there, through Reinhard and gamma. The albedo and the ao
// come from the same run's views of them (8 bits each), the light from the CPU at the pixel's
// point (the plain scene's geometry, the same); compared where the four neighbours see the same
// object and the same ambient light. (Planted, an ambient view that left out the ao passed every
// test: the plain scene's ao is 1.)
TEST(Reference, LightTypes09AmbientViewTakesTheMapsAo) {
    const fs::path dir = testOutputDir("reference_09_textured_ambient");
    const std::vector<ScenePixel> scene = plainScene();
    const std::vector<PackedLight> lights =
        light_types::sceneLights(light_types::kPointAttenuation);
    std::map<std::string, Image> views;
    const ViewRenders renders = renderViews(
        "09_light_types", {"albedo", "ao", "ambient"},
        {"--msaa", "0", "--size", std::to_string(kViewWidth) + "x" + std::to_string(kViewHeight),
         "--camera", "0,5.5,12,-90,-22"},
        dir);
    ASSERT_EQ(renders.run.exitCode, 0) << renders.run.err;
    for (const auto& [view, path] : renders.images) views[view] = readImage(path, 3);
    ASSERT_EQ(views.size(), 3u) << renders.run.out;
    const auto ambientAt = [&](const glm::vec3& position) {
        glm::vec3 ambient(0.0f), L;
        for (const PackedLight& light : lights) {
            if (cpu::isAmbientVolume(light)) ambient += cpu::lightTypeRadiance(light, position, L);
        }
        return ambient;
    };
    int compared = 0, shaded = 0, worst = 0;
    for (int py = 1; py + 1 < kViewHeight; ++py) {
        for (int px = 1; px + 1 < kViewWidth; ++px) {
            const ScenePixel& pixel = scene[size_t(py) * kViewWidth + size_t(px)];
            if (pixel.object < 0) continue;
            const glm::vec3 ambient = ambientAt(pixel.surface.position);
            bool steady = true;
            for (const auto& [dx, dy] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}}) {
                const ScenePixel& n = scene[size_t(py + dy) * kViewWidth + size_t(px + dx)];
                steady = steady && n.object == pixel.object &&
                         glm::length(ambientAt(n.surface.position) - ambient) < 1e-3f;
            }
            if (!steady) continue;
            glm::vec3 albedo;
            for (int c = 0; c < 3; ++c) albedo[c] = views["albedo"].at(px, py, c) / 255.0f;
            const float ao = views["ao"].at(px, py, 0) / 255.0f;
            const glm::vec3 expected = 255.0f * cpu::reinhardGamma(ambient * albedo * ao);
            for (int c = 0; c < 3; ++c) {
                worst = std::max(worst, std::abs(int(views["ambient"].at(px, py, c)) -
                                                 int(std::lround(expected[c]))));
            }
            ++compared;
            if (ao < 0.9f && ambient != glm::vec3(0.0f)) ++shaded;
        }
    }
    std::printf(
        "09 --view ambient in the material sets: %d pixels (%d lit with ao below 0.9); "
        "worst channel difference %d/255\n",
        compared, shaded, worst);
    EXPECT_GT(compared, 50000);
    EXPECT_GT(shaded, 1000);
    EXPECT_LE(worst, 3);
}

}  // namespace
}  // namespace pbr::test
