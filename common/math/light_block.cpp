#include "math/light_block.h"


namespace pbr {

namespace {
PackedLight make(LightType type, const glm::vec3& position, const glm::vec3& forward,
                 const glm::vec3& color, float intensity, glm::vec3 terms, float cutoff = 0.0f,
                 float outer = 0.0f) {
    PackedLight light;
    light.positionConstant = glm::vec4(position, terms.x);
    light.forwardLinear = glm::vec4(forward, terms.y);
    light.colorQuadratic = glm::vec4(color, terms.z);
    light.typeCutoffOuterIntensity = glm::vec4(float(int(type)), cutoff, outer, intensity);
    return light;
}
}  // namespace

PackedLight pointLight(const glm::vec3& position, const glm::vec3& color, float intensity,
                       Attenuation a) {
    return make(LightType::Point, position, glm::vec3(0.0f), color, intensity,
                {a.constant, a.linear, a.quadratic});
}

PackedLight directionalLight(const glm::vec3& forward, const glm::vec3& color, float intensity) {
    return make(LightType::Directional, glm::vec3(0.0f), glm::normalize(forward), color, intensity,
                glm::vec3(0.0f));
}

PackedLight spotLight(const glm::vec3& position, const glm::vec3& forward, const glm::vec3& color,
                      float intensity, float cutoffDegrees, float outerDegrees, Attenuation a) {
    return make(LightType::Spot, position, glm::normalize(forward), color, intensity,
                {a.constant, a.linear, a.quadratic}, cutoffDegrees, outerDegrees);
}

PackedLight ambientBoxLight(const glm::vec3& centre, const glm::vec3& halfSize,
                            const glm::vec3& color, float intensity) {
    return make(LightType::AmbientBox, centre, glm::vec3(0.0f), color, intensity, halfSize);
}

PackedLight ambientSphereLight(const glm::vec3& centre, float radius, const glm::vec3& color,
                               float intensity) {
    return make(LightType::AmbientSphere, centre, glm::vec3(0.0f), color, intensity,
                {radius, 0.0f, 0.0f});
}

}  // namespace pbr
