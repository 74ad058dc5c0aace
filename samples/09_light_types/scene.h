#pragma once
// Sample 09's scene in numbers: the floor and the spheres (where they stand, which material set,
// the engine's material inputs), the five lights and the moving lights of the stress test. Plain
// data, no GL: shared by the sample and its reference test (tests/reference/light_types_test.cpp),
// which shades the same scene on the CPU.
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "app/options.h"
#include "app/views.h"
#include "math/light_block.h"

namespace light_types {

// The floor: y = 0, x -8..8, z -5..5. Five spheres of radius 0.8 resting on it, 2.5 m apart.
inline constexpr float kFloorHalfX = 8.0f, kFloorHalfZ = 5.0f;
inline constexpr float kSphereRadius = 0.8f;
inline glm::vec3 sphereCentre(int i) {
    return {-5.0f + 2.5f * float(i), kSphereRadius, 0.0f};
}
// The point light's terms unless --attenuation says otherwise.
inline constexpr pbr::Attenuation kPointAttenuation{1.0f, 0.7f, 1.8f};

// One light of each kind, placed so the picture shows what each does.
inline std::vector<pbr::PackedLight> sceneLights(pbr::Attenuation pointAttenuation) {
    return {
        // a warm point light 1.2 m above the floor in front of the left sphere, bright enough
        // (30) that its pool shows (by default the terms of LearnOpenGL's table for a 7 m range:
        // a pool a few metres wide)
        pbr::pointLight({-5.0f, 1.2f, 1.8f}, {1.0f, 0.8f, 0.6f}, 30.0f, pointAttenuation),
        // a dim bluish directional light, from above and behind the camera's left
        pbr::directionalLight({0.3f, -1.0f, -0.4f}, {0.6f, 0.7f, 1.0f}, 0.6f),
        // a spot straight down onto the floor in front of the middle sphere: a cone of 18 degrees
        // and a soft band of 6 more
        pbr::spotLight({0.0f, 6.0f, 2.5f}, {0.0f, -1.0f, 0.0f}, {1.0f, 1.0f, 1.0f}, 40.0f, 18.0f,
                       6.0f, {1.0f, 0.045f, 0.0075f}),
        // a greenish ambient box around the right sphere's lower part and its patch of floor,
        // 1.25 m high: the sphere's top (1.6 m) stands out of it
        pbr::ambientBoxLight({5.0f, 0.5f, 0.5f}, {1.6f, 0.75f, 2.0f}, {0.25f, 0.6f, 0.3f}, 2.0f),
        // an orange ambient sphere around the second sphere
        pbr::ambientSphereLight({-2.5f, 0.8f, 0.8f}, 1.7f, {0.8f, 0.45f, 0.15f}, 2.0f),
    };
}

// One object of the scene: where it is, which material set, the engine's material inputs.
struct Object {
    const char* materialSet;
    glm::mat4 model;
    glm::vec2 tiling{1.0f}, offset{0.0f};
    glm::vec4 tint{1.0f};
    float metallic = 1.0f, roughness = 1.0f;  // factors on the maps
    bool floor = false;
    // The tests' plain material (--untextured): white maps, so that the factors are the values.
    // The floor a rough dielectric; the spheres' metallic 0, 1/4, ... 1 from left to right.
    float plainMetallic = 0.0f, plainRoughness = 0.4f;
};

// The floor (object 0), then the five spheres from left to right.
inline std::vector<Object> objects() {
    std::vector<Object> objects;
    // the floor: 16 x 10 m at y = 0, the wall set tiled 8 x 5 and shifted by a quarter tile
    Object floor{"wall",
                 glm::scale(glm::rotate(glm::mat4(1.0f), -std::numbers::pi_v<float> / 2, {1, 0, 0}),
                            {8.0f, 5.0f, 1.0f})};
    floor.tiling = {8.0f, 5.0f};
    floor.offset = {0.25f, 0.0f};
    floor.floor = true;
    floor.plainRoughness = 0.9f;
    objects.push_back(floor);
    // five spheres in a row, 2.5 m apart, resting on the floor
    const char* sets[5] = {"rusted_iron", "gold", "grass", "plastic", "wall"};
    for (int i = 0; i < 5; ++i) {
        Object sphere{sets[i], glm::scale(glm::translate(glm::mat4(1.0f), sphereCentre(i)),
                                          glm::vec3(kSphereRadius))};
        sphere.plainMetallic = float(i) / 4.0f;
        objects.push_back(sphere);
    }
    objects[3].tiling = {2.0f, 1.0f};              // grass: twice around
    objects[4].tint = {0.45f, 0.65f, 1.0f, 1.0f};  // plastic, tinted blue
    objects[5].offset = {0.5f, 0.0f};              // wall: the pattern turned half way round
    return objects;
}

// N moving point lights for the stress test: on a circle over the scene, turning with `time`,
// colours round the hue wheel; the same short range as the scene's point light (terms 1, 0.7,
// 1.8), so each makes its own small pool of light.
inline std::vector<pbr::PackedLight> movingLights(int count, float time) {
    std::vector<pbr::PackedLight> lights;
    for (int i = 0; i < count; ++i) {
        const float t = float(i) / float(count);
        const float angle = 2.0f * std::numbers::pi_v<float> * t + 0.5f * time;
        const glm::vec3 position(6.5f * std::cos(angle), 0.6f + 0.4f * std::sin(3.0f * angle),
                                 3.5f * std::sin(angle));
        const glm::vec3 hue = glm::clamp(
            glm::abs(glm::mod(6.0f * t + glm::vec3(0.0f, 4.0f, 2.0f), 6.0f) - 3.0f) - 1.0f, 0.0f,
            1.0f);
        lights.push_back(pbr::pointLight(position, hue, 3.0f, {1.0f, 0.7f, 1.8f}));
    }
    return lights;
}

// The sample's own flags: --only, --point-lights, --attenuation and --view are read every frame
// (live in the panel).
inline std::vector<pbr::FlagSpec> flags() {
    std::vector<std::string> onlyChoices = {"all"};
    onlyChoices.insert(onlyChoices.end(), std::begin(pbr::kLightTypeNames),
                       std::end(pbr::kLightTypeNames));
    return {
        pbr::FlagSpec::choice("--only", onlyChoices, "draw with one kind of light (default all)")
            .asLive(),
        pbr::FlagSpec::integer("--point-lights", "N",
                               "add N moving point lights (their places depend only on "
                               "--time), for the cost of many lights",
                               0, pbr::LightBlock::kMaxLights - 5, 0)
            .asLive(),
        pbr::FlagSpec::numbers("--attenuation", "C,L,Q",
                               "the point light's constant, linear and quadratic terms, "
                               "each >= 0, not all 0",
                               // light_types::kPointAttenuation, which the reference
                               // tests light the scene with
                               3, 0.0, 1e6, {1.0, 0.7, 1.8})
            .refusing([](const std::string& value) {
                // (three numbers >= 0 by now: the kind's own check comes first)
                double sum = 0.0;
                for (size_t at = 0; at != std::string::npos;) {
                    sum += std::strtod(value.c_str() + at, nullptr);
                    at = value.find(',', at);
                    if (at != std::string::npos) ++at;
                }
                return sum > 0.0 ? std::string() : std::string("all three terms are 0");
            })
            .asLive(),
        pbr::FlagSpec::toggle("--untextured",
                              "a plain material instead of the maps: the tint as albedo, "
                              "a rough dielectric floor, spheres of roughness 0.4 and "
                              "metallic 0 to 1 from left to right (the tests' surface)"),
        pbr::viewFlag(pbr::kLightTypeViews).asLive(),
        pbr::viewGainFlag()};
}

}  // namespace light_types
