#pragma once
// Sample 09's scene in numbers: where the spheres stand and the five lights, shared by the sample
// and its reference test (tests/reference/light_types_test.cpp), which shades the same scene on
// the CPU.
#include <vector>

#include <glm/glm.hpp>

#include "light_block.h"

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
        // a warm point light in front of the left sphere (by default the terms of LearnOpenGL's
        // table for a 7 m range: a pool of light a few metres wide)
        pbr::pointLight({-5.0f, 1.8f, 1.8f}, {1.0f, 0.8f, 0.6f}, 10.0f, pointAttenuation),
        // a dim bluish directional light, from above and behind the camera's left
        pbr::directionalLight({0.3f, -1.0f, -0.4f}, {0.6f, 0.7f, 1.0f}, 0.6f),
        // a spot straight down onto the floor in front of the middle sphere: a cone of 18 degrees
        // and a soft band of 6 more
        pbr::spotLight({0.0f, 6.0f, 2.5f}, {0.0f, -1.0f, 0.0f}, {1.0f, 1.0f, 1.0f}, 40.0f, 18.0f,
                       6.0f, {1.0f, 0.045f, 0.0075f}),
        // a greenish ambient box around the right sphere and its patch of floor
        pbr::ambientBoxLight({5.0f, 1.0f, 0.5f}, {1.6f, 1.5f, 2.0f}, {0.25f, 0.6f, 0.3f}, 2.0f),
        // an orange ambient sphere around the second sphere
        pbr::ambientSphereLight({-2.5f, 0.8f, 0.8f}, 1.7f, {0.8f, 0.45f, 0.15f}, 2.0f),
    };
}

}  // namespace light_types
