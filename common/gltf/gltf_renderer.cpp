#include "gltf/gltf_renderer.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace pbr {

namespace {

enum Unit { kBaseColor = 0, kMetallicRoughness = 1, kNormal = 2, kOcclusion = 3, kEmissive = 4 };
constexpr int kUnits = 5;

}  // namespace

GltfRenderer::GltfRenderer(Shader& shader)
    : shader_(shader), white_(Image{1, 1, 4, {255, 255, 255, 255}}, ColorSpace::Linear) {
    shader_.set("baseColorTexture", int(kBaseColor));
    shader_.set("metallicRoughnessTexture", int(kMetallicRoughness));
    shader_.set("specularGlossinessTexture", int(kMetallicRoughness));  // one workflow a material
    shader_.set("normalTexture", int(kNormal));
    shader_.set("occlusionTexture", int(kOcclusion));
    shader_.set("emissiveTexture", int(kEmissive));
    shader_.set("irradianceMap", kFirstIblUnit);
    shader_.set("prefilterMap", kFirstIblUnit + 1);
    shader_.set("brdfLUT", kFirstIblUnit + 2);
    shader_.set("environmentMap", kFirstIblUnit + 3);
    setLights({});
}

int GltfRenderer::setLights(std::span<const PunctualLight> lights) {
    const int count = std::min(int(lights.size()), kMaxLights);
    shader_.set("punctualLightCount", count);
    for (int i = 0; i < count; ++i) {
        const PunctualLight& light = lights[size_t(i)];
        const std::string at = "punctualLights[" + std::to_string(i) + "].";
        shader_.set(at + "type", int(light.type));
        shader_.set(at + "color", light.color);
        shader_.set(at + "position", light.position);
        shader_.set(at + "direction", light.direction);
        shader_.set(at + "range", light.range);
        shader_.set(at + "innerConeCos", std::cos(light.innerConeAngle));
        shader_.set(at + "outerConeCos", std::cos(light.outerConeAngle));
    }
    return int(lights.size()) - count;
}

void GltfRenderer::setMaterial(const GpuModel& model, const Material& m) {
    auto slot = [&](const char* name, const TextureRef& ref, ColorSpace colorSpace, int unit) {
        const bool own = model.bindTexture(ref, colorSpace, unit, white_);
        shader_.set(std::string(name) + "UvSet", own ? ref.uvSet : 0);
        shader_.set(std::string(name) + "UvTransform", own ? ref.transform : glm::mat3(1.0f));
        return own;
    };
    slot("baseColor", m.baseColorTexture, ColorSpace::Srgb, kBaseColor);
    // unit 1: the workflow's second texture
    if (m.specularGlossiness) {
        slot("specularGlossiness", m.specularGlossinessTexture, ColorSpace::Srgb,
             kMetallicRoughness);
    } else {
        slot("metallicRoughness", m.metallicRoughnessTexture, ColorSpace::Linear,
             kMetallicRoughness);
    }
    shader_.set("hasNormalTexture",
                slot("normal", m.normalTexture, ColorSpace::Linear, kNormal) ? 1 : 0);
    slot("occlusion", m.occlusionTexture, ColorSpace::Linear, kOcclusion);
    slot("emissive", m.emissiveTexture, ColorSpace::Srgb, kEmissive);
    shader_.set("baseColorFactor", m.baseColorFactor);
    shader_.set("metallicFactor", m.metallicFactor);
    shader_.set("roughnessFactor", m.roughnessFactor);
    shader_.set("specularGlossiness", m.specularGlossiness ? 1 : 0);
    shader_.set("specularFactor", m.specularFactor);
    shader_.set("glossinessFactor", m.glossinessFactor);
    shader_.set("normalScale", m.normalScale);
    shader_.set("occlusionStrength", m.occlusionStrength);
    shader_.set("emissiveFactor", m.emissiveFactor);
    shader_.set("alphaMode", int(m.alphaMode));
    shader_.set("alphaCutoff", m.alphaCutoff);
    shader_.set("unlit", m.unlit ? 1 : 0);
}

void GltfRenderer::drawPrimitive(const GpuModel::Primitive& primitive, const glm::mat4& world) {
    const glm::mat4 transform = world * primitive.transform;
    if (primitive.material.doubleSided) {
        glDisable(GL_CULL_FACE);
    } else {
        glEnable(GL_CULL_FACE);
    }
    // glTF: a node transform with a negative determinant turns the winding around.
    glFrontFace(glm::determinant(glm::mat3(transform)) < 0.0f ? GL_CW : GL_CCW);
    shader_.setModel(transform);
    primitive.mesh.draw();
}

void GltfRenderer::draw(const GpuModel& model, const glm::mat4& world, const glm::mat4& view) {
    shader_.use();
    std::vector<const GpuModel::Primitive*> blended;
    for (const GpuModel::Primitive& primitive : model.primitives()) {
        if (primitive.material.alphaMode == AlphaMode::Blend) {
            blended.push_back(&primitive);
            continue;
        }
        setMaterial(model, primitive.material);
        drawPrimitive(primitive, world);
    }
    // Blended primitives last, the farthest first (by the centre of their bounds, in view
    // space), over what is drawn, without writing depth so none hides another.
    auto depth = [&](const GpuModel::Primitive* p) {
        return (view * world * p->transform * glm::vec4(p->centre, 1.0f)).z;
    };
    std::stable_sort(blended.begin(), blended.end(),
                     [&](auto* a, auto* b) { return depth(a) < depth(b); });
    if (!blended.empty()) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
        for (const GpuModel::Primitive* primitive : blended) {
            setMaterial(model, primitive->material);
            drawPrimitive(*primitive, world);
        }
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    GpuModel::unbindSamplers(kUnits);
}

PunctualLight defaultLight(float lux) {
    PunctualLight light;
    light.type = PunctualLight::Type::Directional;
    light.name = "default light";
    light.color = glm::vec3(lux);
    light.direction = glm::normalize(glm::vec3(-0.4f, -0.7f, -0.6f));
    return light;
}

}  // namespace pbr
