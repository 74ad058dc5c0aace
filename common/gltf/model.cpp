#include "gltf/model.h"

#include <algorithm>
#include <cmath>

#include "base/error.h"
#include "base/paths.h"

namespace pbr {

namespace fs = std::filesystem;

std::optional<std::string> defaultMaterialNote(const Model& model) {
    if (model.primitivesWithoutMaterial == 0) return std::nullopt;
    return "note: " + displayPath(model.file) + ": " +
           std::to_string(model.primitivesWithoutMaterial) +
           " primitive(s) name no material; drawn in glTF's default material (base colour "
           "white, metallic 1, roughness 1)";
}

glm::mat3 textureTransform(const glm::vec2& offset, float rotation, const glm::vec2& scale) {
    const float c = std::cos(rotation), s = std::sin(rotation);
    const glm::mat3 translation(1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, offset.x, offset.y, 1.0f);
    // u' = c u + s v, v' = -s u + c v, as the extension's example, its TextureTransformTest model,
    // three.js, Babylon.js and Khronos' sample viewer turn it. (The GLSL listing in the
    // extension's README has the transpose, a known erratum: KhronosGroup/glTF issue 1563.)
    const glm::mat3 rotate(c, -s, 0.0f, s, c, 0.0f, 0.0f, 0.0f, 1.0f);
    const glm::mat3 scaling(scale.x, 0.0f, 0.0f, 0.0f, scale.y, 0.0f, 0.0f, 0.0f, 1.0f);
    return translation * rotate * scaling;
}

std::vector<std::string> extensionsNotDrawn(const Model& model,
                                            const std::vector<std::string>& drawn, bool required) {
    std::vector<std::string> out;
    for (const std::string& name : required ? model.extensionsRequired : model.extensionsUsed) {
        const bool isRequired =
            std::find(model.extensionsRequired.begin(), model.extensionsRequired.end(), name) !=
            model.extensionsRequired.end();
        if (!required && isRequired) continue;  // listed with the required ones
        if (std::find(drawn.begin(), drawn.end(), name) == drawn.end()) out.push_back(name);
    }
    return out;
}

std::string extensionAndItsMaterials(const Model& model, const std::string& extension) {
    std::vector<std::string> names;
    for (const Material& material : model.materials) {
        if (std::find(material.extensions.begin(), material.extensions.end(), extension) !=
            material.extensions.end())
            names.push_back("'" + printable(material.name) + "'");
    }
    if (names.empty()) return extension;
    std::string text = extension + (names.size() == 1 ? " (material " : " (materials ");
    for (size_t i = 0; i < names.size() && i < 3; ++i) text += (i ? ", " : "") + names[i];
    if (names.size() > 3) text += " and " + std::to_string(names.size() - 3) + " more";
    return text + ")";
}

Image loadTextureImage(const Model& model, const TextureRef& ref, int wantChannels) {
    if (!ref.present()) throw Error(displayPath(model.file) + ": no such texture");
    if (ref.embedded < 0) return readImage(ref.file, wantChannels);
    const EmbeddedImage& embedded = model.embeddedImages.at(size_t(ref.embedded));
    const std::string what = displayPath(model.file) + ": embedded image '" + embedded.name + "'";
    if (embedded.width > 0) {
        Image image{embedded.width, embedded.height, 4, embedded.bytes};
        if (wantChannels == 0 || wantChannels == 4) return image;
        Image out{image.width, image.height, wantChannels, {}};
        for (size_t i = 0; i < image.pixels.size(); i += 4) {
            for (int c = 0; c < wantChannels; ++c)
                out.pixels.push_back(image.pixels[i + size_t(c)]);
        }
        return out;
    }
    return decodeImage(embedded.bytes, what, wantChannels);
}

GpuModel::GpuModel(const Model& model) {
    auto upload = [&](const TextureRef& ref, ColorSpace colorSpace) {
        if (!ref.present()) return;
        // One texture per image and colour space, one sampler per glTF sampler: two textures
        // sharing an image may still sample it differently (NEAREST and LINEAR, say).
        if (!textures_.count({ref, colorSpace})) {
            Image image;
            try {
                image = loadTextureImage(model, ref);
            } catch (const Error& e) {
                if (ref.embedded >= 0) throw;  // the message names the model already
                throw Error(displayPath(model.file) + ": texture " + e.what());
            }
            textures_[{ref, colorSpace}] = std::make_unique<Texture2D>(image, colorSpace);
        }
        const std::tuple key{ref.wrapS, ref.wrapT, ref.magFilter, ref.minFilter};
        if (samplers_.count(key)) return;
        GlSampler sampler;
        glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_S, ref.wrapS);
        glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_T, ref.wrapT);
        glSamplerParameteri(sampler.id(), GL_TEXTURE_MAG_FILTER,
                            ref.magFilter ? ref.magFilter : GL_LINEAR);
        glSamplerParameteri(sampler.id(), GL_TEXTURE_MIN_FILTER,
                            ref.minFilter ? ref.minFilter : GL_LINEAR_MIPMAP_LINEAR);
        samplers_.emplace(key, std::move(sampler));
    };
    for (const Material& m : model.materials) {
        const auto slots = m.textures();
        for (size_t slot = 0; slot < slots.size(); ++slot) {
            upload(*slots[slot],
                   Material::isSrgbSlot(slot) ? ColorSpace::Srgb : ColorSpace::Linear);
        }
    }
    for (const ModelPrimitive& p : model.primitives) {
        glm::vec3 low(INFINITY), high(-INFINITY);
        for (const glm::vec3& position : p.mesh.positions) {
            low = glm::min(low, position);
            high = glm::max(high, position);
        }
        primitives_.push_back({GpuMesh(p.mesh), model.materials[size_t(p.material)], p.transform,
                               0.5f * (low + high)});
    }
}

const Texture2D* GpuModel::texture(const TextureRef& ref, ColorSpace colorSpace) const {
    auto found = textures_.find({ref, colorSpace});
    return found == textures_.end() ? nullptr : found->second.get();
}

bool GpuModel::bindTexture(const TextureRef& ref, ColorSpace colorSpace, int unit,
                           const Texture2D& fallback) const {
    const Texture2D* own = texture(ref, colorSpace);
    auto sampler = samplers_.find({ref.wrapS, ref.wrapT, ref.magFilter, ref.minFilter});
    glBindSampler(GLuint(unit), own && sampler != samplers_.end() ? sampler->second.id() : 0);
    (own ? own : &fallback)->bind(unit);
    return own != nullptr;
}

void GpuModel::unbindSamplers(int count) {
    for (int unit = 0; unit < count; ++unit) glBindSampler(GLuint(unit), 0);
}

}  // namespace pbr
