#pragma once
// Draws a GpuModel with the glTF shading path (shaders/include/gltf_material.glsl and
// punctual_lights.glsl): each primitive's material into the shader's uniforms, its textures with
// their samplers on units 0-4, and the order and state glTF asks for: opaque and masked
// primitives first, then the blended ones back to front without depth writes; back faces culled
// unless the material is double-sided; the winding flipped under a mirroring node transform.
// Shared by the glTF samples (07, 08); the IBL maps (units 5-7) and the camera are the sample's.
#include <span>

#include <glm/glm.hpp>

#include "gl/shader.h"
#include "gl/texture.h"
#include "gltf/model.h"
#include "math/punctual_light.h"

namespace pbr {

class GltfRenderer {
public:
    static constexpr int kMaxLights = 8;  // MAX_PUNCTUAL_LIGHTS of punctual_lights.glsl
    // The split-sum maps' units (pbr::useIblMaps(shader, ..., kFirstIblUnit)): set even when no
    // maps are bound, so no two sampler types ever share a unit.
    static constexpr int kFirstIblUnit = 5;

    explicit GltfRenderer(Shader& shader);

    // Uploads up to kMaxLights lights; returns how many were left out.
    int setLights(std::span<const PunctualLight> lights);
    // Draws every primitive of `model`, placed by `world` x its node transform.
    void draw(const GpuModel& model, const glm::mat4& world, const glm::mat4& view);

private:
    void setMaterial(const GpuModel& model, const Material& material);
    void drawPrimitive(const GpuModel::Primitive& primitive, const glm::mat4& world);

    Shader& shader_;
    Texture2D white_;
};

// One light for files that bring none: a white directional light of `lux`, from above the
// viewer's right shoulder (down and away from a camera looking along -Z).
PunctualLight defaultLight(float lux = 3.0f);

}  // namespace pbr
