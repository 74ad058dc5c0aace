#pragma once
// A KHR_lights_punctual light (glTF 2.0), placed in world space: plain data, shared by the model
// loader, the samples that upload lights and the CPU reference in common/math/brdf.
#include <string>

#include <glm/glm.hpp>

namespace pbr {

struct PunctualLight {
    enum class Type { Directional = 0, Point = 1, Spot = 2 };
    Type type = Type::Point;
    std::string name;
    // Linear colour times intensity, in the specification's units: candela (lm/sr) for point and
    // spot lights, lux (lm/m^2) for directional ones; no conversion.
    glm::vec3 color{1.0f};
    glm::vec3 position{0.0f};              // world space (point, spot)
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // world space, unit: where the light shines
    float range = 0.0f;                    // 0: unlimited (plain inverse square)
    float innerConeAngle = 0.0f;           // radians, spot only
    float outerConeAngle = 0.7853982f;     // radians (the specification's default pi / 4)
};

}  // namespace pbr
