#include "gltf/gltf_renderer.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "base/error.h"
#include "gl/framebuffer.h"

namespace pbr {

namespace {

enum Unit { kBaseColor = 0, kMetallicRoughness = 1, kNormal = 2, kOcclusion = 3, kEmissive = 4 };

// The samplers of each layer, in the order their units follow the IBL maps'.
struct LayerSampler {
    const char* layer;
    const char* sampler;
};
constexpr LayerSampler kLayerSamplers[] = {
    {"CLEARCOAT", "clearcoatTexture"},    {"CLEARCOAT", "clearcoatRoughnessTexture"},
    {"CLEARCOAT", "clearcoatNormalTexture"}, {"SHEEN", "sheenColorTexture"},
    {"SHEEN", "sheenRoughnessTexture"},   {"SHEEN", "sheenLUT"},
    {"SHEEN", "sheenMap"},                {"SPECULAR", "khrSpecularTexture"},
    {"SPECULAR", "khrSpecularColorTexture"}, {"TRANSMISSION", "transmissionTexture"},
    {"TRANSMISSION", "thicknessTexture"}, {"TRANSMISSION", "transmissionBackdrop"},
    {"TRANSMISSION", "transmissionLUT"}};

bool has(const std::vector<std::string>& layers, const std::string& layer) {
    return std::find(layers.begin(), layers.end(), layer) != layers.end();
}

// The unit of `sampler` in a program of `layers` (-1: not in it).
int layerUnit(const std::vector<std::string>& layers, const std::string& sampler) {
    int unit = GltfRenderer::kFirstLayerUnit;
    for (const LayerSampler& entry : kLayerSamplers) {
        if (!has(layers, entry.layer)) continue;
        if (sampler == entry.sampler) return unit;
        ++unit;
    }
    return -1;
}

}  // namespace

// The transmission backdrop: a float colour texture with its mip chain (the blur a rough surface
// reads), and a depth buffer, kBackdropSize square.
struct GltfRenderer::Backdrop {
    GlFramebuffer framebuffer;
    GlTexture color;
    GlRenderbuffer depth;
    Backdrop() {
        const int size = kBackdropSize;
        glBindTexture(GL_TEXTURE_2D, color.id());
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, size, size, 0, GL_RGBA, GL_FLOAT, nullptr);
        glGenerateMipmap(GL_TEXTURE_2D);  // the chain's storage (its texels come with each frame)
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glBindTexture(GL_TEXTURE_2D, 0);
        glBindRenderbuffer(GL_RENDERBUFFER, depth.id());
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size, size);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.id());
        requireCompleteFramebuffer("transmission backdrop");
    }
};

std::vector<std::string> materialLayers(const Material& m) {
    std::vector<std::string> layers;
    if (m.clearcoat.factor > 0.0f) layers.push_back("CLEARCOAT");
    if (std::max({m.sheen.colorFactor.r, m.sheen.colorFactor.g, m.sheen.colorFactor.b}) > 0.0f)
        layers.push_back("SHEEN");
    if (m.khrSpecular.texture.present() || m.khrSpecular.colorTexture.present())
        layers.push_back("SPECULAR");
    if (m.transmission.factor > 0.0f) layers.push_back("TRANSMISSION");
    const bool factors = m.ior != 1.5f || m.khrSpecular.factor != 1.0f ||
                         m.khrSpecular.colorFactor != glm::vec3(1.0f) || m.emissiveStrength != 1.0f;
    if (!layers.empty() || factors) layers.insert(layers.begin(), "GLTF_EXTENSIONS");
    return layers;
}

Material withLayerFactors(const Material& material, const LayerFactors& f) {
    Material m = material;
    const std::vector<std::string> layers = materialLayers(material);
    if (has(layers, "CLEARCOAT")) {
        m.clearcoat.factor = f.clearcoat.value_or(m.clearcoat.factor);
        m.clearcoat.roughnessFactor = f.clearcoatRoughness.value_or(m.clearcoat.roughnessFactor);
    }
    if (has(layers, "SHEEN")) {
        m.sheen.colorFactor = f.sheenColor.value_or(m.sheen.colorFactor);
        m.sheen.roughnessFactor = f.sheenRoughness.value_or(m.sheen.roughnessFactor);
    }
    if (has(layers, "TRANSMISSION")) {
        m.transmission.factor = f.transmission.value_or(m.transmission.factor);
        m.volume.thicknessFactor = f.thickness.value_or(m.volume.thicknessFactor);
        m.volume.attenuationColor = f.attenuationColor.value_or(m.volume.attenuationColor);
        m.volume.attenuationDistance =
            f.attenuationDistance.value_or(m.volume.attenuationDistance);
    }
    {  // defined for every material (its default: no extension)
        m.ior = f.ior.value_or(m.ior);
        m.khrSpecular.factor = f.specular.value_or(m.khrSpecular.factor);
        m.khrSpecular.colorFactor = f.specularColor.value_or(m.khrSpecular.colorFactor);
        m.emissiveStrength = f.emissiveStrength.value_or(m.emissiveStrength);
    }
    return m;
}

int textureUnitsNeeded(const std::vector<std::string>& layers) {
    int units = GltfRenderer::kFirstLayerUnit;
    for (const LayerSampler& entry : kLayerSamplers) units += has(layers, entry.layer) ? 1 : 0;
    return units;
}

void requireTextureUnits(const std::vector<std::string>& layers, int available,
                         const std::string& material) {
    const int needed = textureUnitsNeeded(layers);
    if (needed > available) {
        throw Error("material '" + material + "': its layers need " + std::to_string(needed) +
                    " texture units, where this GL has " + std::to_string(available));
    }
}

GltfRenderer::GltfRenderer(ProgramFor programFor, bool extensions)
    : programFor_(std::move(programFor)),
      extensions_(extensions),
      white_(Image{1, 1, 4, {255, 255, 255, 255}}, ColorSpace::Linear) {
    glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &maxTextureUnits_);
}

void GltfRenderer::setLayerMaps(const Texture2D* layersLut, const TextureCube* sheenMap) {
    layersLut_ = layersLut;
    sheenMap_ = sheenMap;
}

void GltfRenderer::setUnits(Shader& program, const std::vector<std::string>& layers) const {
    program.set("baseColorTexture", int(kBaseColor));
    program.set("metallicRoughnessTexture", int(kMetallicRoughness));
    program.set("specularGlossinessTexture", int(kMetallicRoughness));  // one workflow a material
    program.set("normalTexture", int(kNormal));
    program.set("occlusionTexture", int(kOcclusion));
    program.set("emissiveTexture", int(kEmissive));
    program.set("irradianceMap", kFirstIblUnit);
    program.set("prefilterMap", kFirstIblUnit + 1);
    program.set("brdfLUT", kFirstIblUnit + 2);
    program.set("environmentMap", kFirstIblUnit + 3);
    for (const LayerSampler& entry : kLayerSamplers) {
        if (has(layers, entry.layer)) program.set(entry.sampler, layerUnit(layers, entry.sampler));
    }
}

int GltfRenderer::setLights(Shader& program, std::span<const PunctualLight> lights) {
    const int count = std::min(int(lights.size()), kMaxLights);
    program.set("punctualLightCount", count);
    for (int i = 0; i < count; ++i) {
        const PunctualLight& light = lights[size_t(i)];
        const std::string at = "punctualLights[" + std::to_string(i) + "].";
        program.set(at + "type", int(light.type));
        program.set(at + "color", light.color);
        program.set(at + "position", light.position);
        program.set(at + "direction", light.direction);
        program.set(at + "range", light.range);
        program.set(at + "innerConeCos", std::cos(light.innerConeAngle));
        program.set(at + "outerConeCos", std::cos(light.outerConeAngle));
    }
    return int(lights.size()) - count;
}

Shader& GltfRenderer::programFor(const Material& material, const std::vector<std::string>& layers,
                                 const SetFrame& setFrame) {
    Shader& program = programFor_(layers);
    program.use();
    if (std::find(prepared_.begin(), prepared_.end(), &program) == prepared_.end()) {
        requireTextureUnits(layers, maxTextureUnits_, material.name);
        setUnits(program, layers);
        setFrame(program);
        if (backdropPass_) program.set("toneMapper", kLinearRadiance);
        prepared_.push_back(&program);
    }
    if (has(layers, "SHEEN")) {
        if (!layersLut_) throw Error("a sheen drawn without the layers' LUT");
        layersLut_->bind(layerUnit(layers, "sheenLUT"));
        if (sheenMap_) {  // read only with image-based light
            sheenMap_->bind(layerUnit(layers, "sheenMap"));
            program.set("sheenMaxLod", float(sheenMap_->levels() - 1));
        }
    }
    if (has(layers, "TRANSMISSION")) {
        if (!layersLut_) throw Error("a transmission drawn without the layers' LUT");
        layersLut_->bind(layerUnit(layers, "transmissionLUT"));
    }
    return program;
}

void GltfRenderer::setMaterial(Shader& program, const GpuModel& model, const Material& m,
                               const std::vector<std::string>& layers) {
    auto slot = [&](const char* name, const TextureRef& ref, ColorSpace colorSpace, int unit) {
        largestUnit_ = std::max(largestUnit_, unit);
        const bool own = model.bindTexture(ref, colorSpace, unit, white_);
        program.set(std::string(name) + "UvSet", own ? ref.uvSet : 0);
        program.set(std::string(name) + "UvTransform", own ? ref.transform : glm::mat3(1.0f));
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
    program.set("hasNormalTexture",
                slot("normal", m.normalTexture, ColorSpace::Linear, kNormal) ? 1 : 0);
    slot("occlusion", m.occlusionTexture, ColorSpace::Linear, kOcclusion);
    slot("emissive", m.emissiveTexture, ColorSpace::Srgb, kEmissive);
    program.set("baseColorFactor", m.baseColorFactor);
    program.set("metallicFactor", m.metallicFactor);
    program.set("roughnessFactor", m.roughnessFactor);
    program.set("specularGlossiness", m.specularGlossiness ? 1 : 0);
    program.set("specularFactor", m.specularFactor);
    program.set("glossinessFactor", m.glossinessFactor);
    program.set("normalScale", m.normalScale);
    program.set("occlusionStrength", m.occlusionStrength);
    program.set("emissiveFactor", m.emissiveFactor);
    program.set("alphaMode", int(m.alphaMode));
    program.set("alphaCutoff", m.alphaCutoff);
    program.set("unlit", m.unlit ? 1 : 0);
    if (layers.empty()) return;
    program.set("ior", m.ior);
    program.set("khrSpecularFactor", m.khrSpecular.factor);
    program.set("khrSpecularColorFactor", m.khrSpecular.colorFactor);
    program.set("emissiveStrength", m.emissiveStrength);
    if (has(layers, "CLEARCOAT")) {
        program.set("clearcoatFactor", m.clearcoat.factor);
        program.set("clearcoatRoughnessFactor", m.clearcoat.roughnessFactor);
        program.set("clearcoatNormalScale", m.clearcoat.normalScale);
        slot("clearcoat", m.clearcoat.texture, ColorSpace::Linear,
             layerUnit(layers, "clearcoatTexture"));
        slot("clearcoatRoughness", m.clearcoat.roughnessTexture, ColorSpace::Linear,
             layerUnit(layers, "clearcoatRoughnessTexture"));
        program.set("hasClearcoatNormalTexture",
                    slot("clearcoatNormal", m.clearcoat.normalTexture, ColorSpace::Linear,
                         layerUnit(layers, "clearcoatNormalTexture"))
                        ? 1
                        : 0);
    }
    if (has(layers, "SHEEN")) {
        program.set("sheenColorFactor", m.sheen.colorFactor);
        program.set("sheenRoughnessFactor", m.sheen.roughnessFactor);
        slot("sheenColor", m.sheen.colorTexture, ColorSpace::Srgb,
             layerUnit(layers, "sheenColorTexture"));
        slot("sheenRoughness", m.sheen.roughnessTexture, ColorSpace::Linear,
             layerUnit(layers, "sheenRoughnessTexture"));
        largestUnit_ = std::max(largestUnit_, layerUnit(layers, "sheenMap"));
    }
    if (has(layers, "TRANSMISSION")) {
        program.set("transmissionFactor", m.transmission.factor);
        program.set("thicknessFactor", m.volume.thicknessFactor);
        program.set("attenuationColor", m.volume.attenuationColor);
        // the extension's infinity (no attenuation) as 0 in the shader
        program.set("attenuationDistance", std::isfinite(m.volume.attenuationDistance)
                                               ? m.volume.attenuationDistance
                                               : 0.0f);
        slot("transmission", m.transmission.texture, ColorSpace::Linear,
             layerUnit(layers, "transmissionTexture"));
        slot("thickness", m.volume.thicknessTexture, ColorSpace::Linear,
             layerUnit(layers, "thicknessTexture"));
        const int unit = layerUnit(layers, "transmissionBackdrop");
        largestUnit_ = std::max(largestUnit_, unit);
        // drawn before any transmissive primitive (draw), by a pass that leaves them out, and
        // unbound after the frame: never read while it is the target
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        glBindTexture(GL_TEXTURE_2D, backdrop_ ? backdrop_->color.id() : 0);
        glBindSampler(GLuint(unit), 0);  // its own filtering, not a glTF sampler's
        backdropUnit_ = unit;
    }
    if (has(layers, "SPECULAR")) {
        slot("khrSpecular", m.khrSpecular.texture, ColorSpace::Linear,
             layerUnit(layers, "khrSpecularTexture"));
        slot("khrSpecularColor", m.khrSpecular.colorTexture, ColorSpace::Srgb,
             layerUnit(layers, "khrSpecularColorTexture"));
    }
}

void GltfRenderer::drawPrimitive(Shader& program, const GpuModel::Primitive& primitive,
                                 const glm::mat4& world) {
    const glm::mat4 transform = world * primitive.transform;
    if (primitive.material.doubleSided) {
        glDisable(GL_CULL_FACE);
    } else {
        glEnable(GL_CULL_FACE);
    }
    // glTF: a node transform with a negative determinant turns the winding around.
    glFrontFace(glm::determinant(glm::mat3(transform)) < 0.0f ? GL_CW : GL_CCW);
    program.setModel(transform);
    primitive.mesh.draw();
}

void GltfRenderer::drawWithMaterial(const GpuModel& model, const GpuModel::Primitive& primitive,
                                    const glm::mat4& world, const SetFrame& setFrame) {
    // (a copy only where the factors may change it: the core material is drawn as it is)
    std::optional<Material> applied;
    if (extensions_) applied = withLayerFactors(primitive.material, layerFactors_);
    const Material& material = applied ? *applied : primitive.material;
    const std::vector<std::string> layers =
        extensions_ ? materialLayers(material) : std::vector<std::string>();
    Shader& program = programFor(material, layers, setFrame);
    setMaterial(program, model, material, layers);
    drawPrimitive(program, primitive, world);
}

bool GltfRenderer::transmissive(const Material& material) const {
    // (a transmission given live applies to the materials with one: withLayerFactors)
    return extensions_ && material.transmission.factor > 0.0f &&
           layerFactors_.transmission.value_or(1.0f) > 0.0f;
}

void GltfRenderer::drawPass(const GpuModel& model, const glm::mat4& world, const glm::mat4& view,
                            const SetFrame& setFrame, bool backdrop) {
    prepared_.clear();
    std::vector<const GpuModel::Primitive*> throughs, blended;
    for (const GpuModel::Primitive& primitive : model.primitives()) {
        if (transmissive(primitive.material)) {
            if (!backdrop) throughs.push_back(&primitive);
            continue;
        }
        if (primitive.material.alphaMode == AlphaMode::Blend) {
            blended.push_back(&primitive);
            continue;
        }
        drawWithMaterial(model, primitive, world, setFrame);
    }
    // Transmissive and blended primitives, each group the farthest first (by the centre of their
    // bounds, in view space): a transmissive one over what its backdrop holds, a blended one
    // without writing depth so none hides another.
    auto depth = [&](const GpuModel::Primitive* p) {
        return (view * world * p->transform * glm::vec4(p->centre, 1.0f)).z;
    };
    auto farthestFirst = [&](std::vector<const GpuModel::Primitive*>& primitives) {
        std::stable_sort(primitives.begin(), primitives.end(),
                         [&](auto* a, auto* b) { return depth(a) < depth(b); });
    };
    farthestFirst(throughs);
    for (const GpuModel::Primitive* primitive : throughs) {
        drawWithMaterial(model, *primitive, world, setFrame);
    }
    farthestFirst(blended);
    if (!blended.empty()) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
        for (const GpuModel::Primitive* primitive : blended) {
            drawWithMaterial(model, *primitive, world, setFrame);
        }
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }
}

void GltfRenderer::drawBackdrop(const GpuModel& model, const glm::mat4& world,
                                const glm::mat4& view, const SetFrame& setFrame,
                                const std::function<void()>& background) {
    GLint framebuffer = 0, viewport[4] = {};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    glGetIntegerv(GL_VIEWPORT, viewport);
    if (!backdrop_) backdrop_ = std::make_shared<Backdrop>();
    glBindFramebuffer(GL_FRAMEBUFFER, backdrop_->framebuffer.id());
    glViewport(0, 0, kBackdropSize, kBackdropSize);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);  // the frame's clear colour, linear
    if (background) background();
    backdropPass_ = true;
    drawPass(model, world, view, setFrame, true);
    backdropPass_ = false;
    glBindTexture(GL_TEXTURE_2D, backdrop_->color.id());
    glGenerateMipmap(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(framebuffer));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
}

void GltfRenderer::draw(const GpuModel& model, const glm::mat4& world, const glm::mat4& view,
                        const SetFrame& setFrame, const std::function<void()>& background) {
    largestUnit_ = kEmissive;
    const auto& primitives = model.primitives();
    if (std::any_of(primitives.begin(), primitives.end(),
                    [&](const GpuModel::Primitive& p) { return transmissive(p.material); })) {
        drawBackdrop(model, world, view, setFrame, background);
    }
    drawPass(model, world, view, setFrame, false);
    if (backdropUnit_ >= 0) {
        glActiveTexture(GLenum(GL_TEXTURE0 + backdropUnit_));
        glBindTexture(GL_TEXTURE_2D, 0);
        backdropUnit_ = -1;
    }
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    GpuModel::unbindSamplers(largestUnit_ + 1);
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
