#pragma once
// The Overload engine's lights (its standard PBR shader; sample 09): five kinds of light, each
// packed into one mat4, all of them in one buffer the shader loops over. The engine uses a
// shader storage buffer; GL 3.3 has none, so here the lights go into a std140 uniform block,
// `LightBlock` in shaders/include/light_types.glsl, mirrored field by field by the structs below
// (a GL test checks the offsets against what GL reports for the block). Pure data, no GL:
// common/gl/light_buffer.h owns the GL buffer.
//
// One light, four vec4 columns (the engine's mat4; GLSL struct Light):
//   positionConstant  xyz position (box, sphere: the centre)  w constant attenuation term
//                                                                (box: half-size x; sphere: radius)
//   forwardLinear     xyz forward (where a directional or       w linear term (box: half-size y)
//                     spot light points)
//   colorQuadratic    rgb colour (linear)                       w quadratic term (box: half-size z)
//   typeCutoffOuterIntensity  x type (0 point, 1 directional, 2 spot, 3 ambient box,
//                     4 ambient sphere), y cut-off angle (degrees), z outer angle (degrees, added
//                     to the cut-off), w intensity
#include <cstddef>
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

namespace pbr {

enum class LightType { Point = 0, Directional = 1, Spot = 2, AmbientBox = 3, AmbientSphere = 4 };
// The types' names, in LightType's order, as sample 09's --only takes them.
inline constexpr const char* kLightTypeNames[5] = {"point", "directional", "spot", "ambient-box",
                                                   "ambient-sphere"};

struct PackedLight {
    glm::vec4 positionConstant{0.0f};
    glm::vec4 forwardLinear{0.0f};
    glm::vec4 colorQuadratic{0.0f};
    glm::vec4 typeCutoffOuterIntensity{0.0f};

    bool operator==(const PackedLight&) const = default;
    LightType type() const { return LightType(int(typeCutoffOuterIntensity.x)); }
    glm::vec3 position() const { return glm::vec3(positionConstant); }
    glm::vec3 forward() const { return glm::vec3(forwardLinear); }
    glm::vec3 color() const { return glm::vec3(colorQuadratic); }
    float intensity() const { return typeCutoffOuterIntensity.w; }
    // attenuation terms (point, spot)
    float constant() const { return positionConstant.w; }
    float linear() const { return forwardLinear.w; }
    float quadratic() const { return colorQuadratic.w; }
    // spot angles, degrees
    float cutoff() const { return typeCutoffOuterIntensity.y; }
    float outerCutoff() const { return typeCutoffOuterIntensity.y + typeCutoffOuterIntensity.z; }
    // ambient volumes
    glm::vec3 halfSize() const {
        return {positionConstant.w, forwardLinear.w, colorQuadratic.w};
    }
    float radius() const { return positionConstant.w; }
};
static_assert(sizeof(PackedLight) == 64, "one mat4, as std140 lays it out");

struct Attenuation {
    float constant = 1.0f, linear = 0.0f, quadratic = 0.0f;
};

PackedLight pointLight(const glm::vec3& position, const glm::vec3& color, float intensity,
                       Attenuation attenuation);
PackedLight directionalLight(const glm::vec3& forward, const glm::vec3& color, float intensity);
PackedLight spotLight(const glm::vec3& position, const glm::vec3& forward, const glm::vec3& color,
                      float intensity, float cutoffDegrees, float outerDegrees,
                      Attenuation attenuation);
PackedLight ambientBoxLight(const glm::vec3& centre, const glm::vec3& halfSize,
                            const glm::vec3& color, float intensity);
PackedLight ambientSphereLight(const glm::vec3& centre, float radius, const glm::vec3& color,
                               float intensity);

// The whole std140 block: the count (padded to 16 bytes), then the lights. 255 lights fill the
// 16 KiB every GL 3.3 implementation must allow a uniform block (GL_MAX_UNIFORM_BLOCK_SIZE).
struct LightBlock {
    static constexpr int kMaxLights = 255;  // MAX_LIGHTS of light_types.glsl
    std::int32_t lightCount = 0;
    std::int32_t padding[3] = {0, 0, 0};
    PackedLight lights[kMaxLights];
};
static_assert(offsetof(LightBlock, lights) == 16);
static_assert(sizeof(LightBlock) <= 16384);

}  // namespace pbr
