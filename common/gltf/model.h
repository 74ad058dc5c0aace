#pragma once
// Models through Assimp (glTF 2.0 first): geometry with node transforms accumulated, and every
// primitive's material read into one plain struct. Model is pure data (no GL); GpuModel uploads
// it. Drawing policy (which shader, which inputs) is the sample's.
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <glm/glm.hpp>

#include "files/image.h"
#include "gl/mesh.h"
#include "gl/texture.h"
#include "math/punctual_light.h"

namespace pbr {

// Where a texture's pixels are: a file beside the model, or an image inside it (embedded as
// base64 or in the GLB buffer; Assimp hands both over as "*N").
struct TextureRef {
    std::filesystem::path file;  // absolute; empty when embedded or absent
    int embedded = -1;           // index into Model::embeddedImages, or -1
    int uvSet = 0;               // TEXCOORD_0 or TEXCOORD_1
    // The glTF sampler, in its own numbers (which are GL's enums): wrap 10497 REPEAT, 33071
    // CLAMP_TO_EDGE, 33648 MIRRORED_REPEAT; filters 9728 NEAREST, 9729 LINEAR, 9984-9987 the
    // mipmapped ones, 0 where the file leaves them to the renderer.
    int wrapS = 10497, wrapT = 10497;
    int magFilter = 0, minFilter = 0;
    // KHR_texture_transform as one matrix on glTF's uv (origin at the image's top left):
    // uv' = (transform * vec3(uv, 1)).xy = translation x rotation x scale, as the extension has it.
    glm::mat3 transform{1.0f};
    bool present() const { return embedded >= 0 || !file.empty(); }
    bool operator<(const TextureRef& o) const {
        return std::tie(file, embedded) < std::tie(o.file, o.embedded);
    }
};

enum class AlphaMode { Opaque, Mask, Blend };

// The KHR_materials_* extensions of sample 10, each with its specification's defaults, which are
// also what a material without the extension is: no coat, no sheen, opaque, IOR 1.5, the core
// specular reflectance, emission as the factor says. Texture channels as the specifications
// assign them.
struct Clearcoat {  // KHR_materials_clearcoat
    float factor = 0.0f;
    TextureRef texture;  // R
    float roughnessFactor = 0.0f;
    TextureRef roughnessTexture;  // G
    TextureRef normalTexture;
    float normalScale = 1.0f;
};
struct Sheen {  // KHR_materials_sheen
    glm::vec3 colorFactor{0.0f};
    TextureRef colorTexture;  // RGB, sRGB
    float roughnessFactor = 0.0f;
    TextureRef roughnessTexture;  // A
};
struct Transmission {  // KHR_materials_transmission
    float factor = 0.0f;
    TextureRef texture;  // R
};
struct Volume {  // KHR_materials_volume
    float thicknessFactor = 0.0f;
    TextureRef thicknessTexture;           // G
    float attenuationDistance = INFINITY;  // no attenuation
    glm::vec3 attenuationColor{1.0f};      // linear
};
struct SpecularLayer {  // KHR_materials_specular (not the specular-glossiness workflow's)
    float factor = 1.0f;
    TextureRef texture;  // A
    glm::vec3 colorFactor{1.0f};
    TextureRef colorTexture;  // RGB, sRGB
};

// A glTF 2.0 material as the samples use it, with the spec's defaults.
struct Material {
    std::string name;
    bool unlit = false;  // KHR_materials_unlit
    glm::vec4 baseColorFactor{1.0f};
    TextureRef baseColorTexture;  // sRGB
    float metallicFactor = 1.0f;
    float roughnessFactor = 1.0f;
    TextureRef metallicRoughnessTexture;  // G = roughness, B = metallic
    TextureRef normalTexture;
    float normalScale = 1.0f;
    TextureRef occlusionTexture;  // R
    float occlusionStrength = 1.0f;
    TextureRef emissiveTexture;  // sRGB
    glm::vec3 emissiveFactor{0.0f};
    // KHR_materials_pbrSpecularGlossiness: the diffuse factor and texture are baseColorFactor and
    // baseColorTexture above (sRGB; alpha as in the metallic-roughness workflow)
    bool specularGlossiness = false;
    glm::vec3 specularFactor{1.0f};
    float glossinessFactor = 1.0f;
    TextureRef specularGlossinessTexture;  // RGB = specular (sRGB), A = glossiness
    // KHR_materials_clearcoat, _sheen, _transmission, _volume, _ior, _specular and
    // _emissive_strength (sample 10 draws them; 07 and 08 draw the core material alone)
    Clearcoat clearcoat;
    Sheen sheen;
    Transmission transmission;
    Volume volume;
    float ior = 1.5f;
    SpecularLayer khrSpecular;
    float emissiveStrength = 1.0f;
    // The extensions the material's own "extensions" object names (glTF only), in the file's
    // order: what a renderer checks before it says it draws them all.
    std::vector<std::string> extensions;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
    // glTF's default material, for primitives that name none: every factor at its default (a
    // white, fully metallic, fully rough surface), no textures.
    bool gltfDefault = false;

    // Its texture slots, in a fixed order (the model pack's), and their names in glTF (an
    // extension's as "<extension>.<name>").
    static constexpr size_t kTextureCount = 15;
    static constexpr std::array<const char*, kTextureCount> kTextureNames = {
        "baseColorTexture",
        "metallicRoughnessTexture",
        "normalTexture",
        "occlusionTexture",
        "emissiveTexture",
        "specularGlossinessTexture",
        "KHR_materials_clearcoat.clearcoatTexture",
        "KHR_materials_clearcoat.clearcoatRoughnessTexture",
        "KHR_materials_clearcoat.clearcoatNormalTexture",
        "KHR_materials_sheen.sheenColorTexture",
        "KHR_materials_sheen.sheenRoughnessTexture",
        "KHR_materials_transmission.transmissionTexture",
        "KHR_materials_volume.thicknessTexture",
        "KHR_materials_specular.specularTexture",
        "KHR_materials_specular.specularColorTexture"};
    std::array<TextureRef*, kTextureCount> textures() {
        return {&baseColorTexture,        &metallicRoughnessTexture,
                &normalTexture,           &occlusionTexture,
                &emissiveTexture,         &specularGlossinessTexture,
                &clearcoat.texture,       &clearcoat.roughnessTexture,
                &clearcoat.normalTexture, &sheen.colorTexture,
                &sheen.roughnessTexture,  &transmission.texture,
                &volume.thicknessTexture, &khrSpecular.texture,
                &khrSpecular.colorTexture};
    }
    std::array<const TextureRef*, kTextureCount> textures() const {
        const auto slots = const_cast<Material*>(this)->textures();
        std::array<const TextureRef*, kTextureCount> out{};
        for (size_t i = 0; i < kTextureCount; ++i) out[i] = slots[i];
        return out;
    }
    // Whether a texture slot holds colour (sRGB): base colour, emissive, specular-glossiness,
    // sheen colour and specular colour.
    static constexpr bool isSrgbSlot(size_t slot) {
        return slot == 0 || slot == 4 || slot == 5 || slot == 9 || slot == 14;
    }
};

struct ModelPrimitive {
    MeshData mesh;        // triangles; colours empty when the file has none (white)
    int material = 0;     // index into Model::materials
    glm::mat4 transform;  // the node's world transform, the hierarchy accumulated
};

struct EmbeddedImage {
    std::vector<std::uint8_t> bytes;  // a PNG/JPEG file's bytes, or raw RGBA8 texels
    int width = 0, height = 0;        // set for raw texels only
    std::string name;                 // for messages
};

struct Model {
    std::filesystem::path file;
    std::vector<ModelPrimitive> primitives;
    std::vector<Material> materials;
    std::vector<EmbeddedImage> embeddedImages;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // of all primitives, in world space
    int primitivesWithoutMaterial = 0;           // drawn with glTF's default material
    std::vector<PunctualLight> lights;           // KHR_lights_punctual, placed by their nodes
    // The file's top-level extension lists (glTF only), so a renderer can say what it ignores.
    std::vector<std::string> extensionsUsed, extensionsRequired;
    std::vector<std::string> notes;  // what the loader could not honour, for the sample to say
};

// The note a sample prints when primitives fall back to glTF's default material, or nullopt:
//   "note: <file>: 4 primitive(s) name no material; drawn in glTF's default material (base
//   colour white, metallic 1, roughness 1)"
std::optional<std::string> defaultMaterialNote(const Model& model);

// KHR_texture_transform's matrix: translation x rotation x scale (the extension's order), the
// rotation as the extension's example and TextureTransformTest model turn it (see model.cpp).
glm::mat3 textureTransform(const glm::vec2& offset, float rotation, const glm::vec2& scale);

// The extensions a glTF file uses (or, `required`, requires) that are not in `drawn`: what a
// renderer that draws `drawn` should warn about.
std::vector<std::string> extensionsNotDrawn(const Model& model,
                                            const std::vector<std::string>& drawn, bool required);

// An extension's name with the materials that use it, for a note: "KHR_materials_sheen (materials
// 'Velvet', 'Cushion')", at most three named ("and 2 more"); the name alone where no material
// names it (an extension of the file or its lights).
std::string extensionAndItsMaterials(const Model& model, const std::string& extension);

// Loads and checks a model. Throws Error("<file>: <reason>") for anything that cannot be drawn
// sanely: unreadable files, Assimp's refusals, no triangles, non-finite positions, indices out of
// range, missing texture files. glTF's uv origin (top left) is kept, so images load top row first.
Model loadModel(const std::filesystem::path& file);

// The pixels of a texture reference (8-bit, channels as stored, or `wantChannels`).
Image loadTextureImage(const Model& model, const TextureRef& ref, int wantChannels = 0);

// The model on the GPU: one GpuMesh per primitive, each texture uploaded once. It keeps its own
// copy of every material, so it owes nothing to the Model it was made from: `GpuModel
// gpu(loadModel(file))` is fine.
class GpuModel {
public:
    explicit GpuModel(const Model& model);

    struct Primitive {
        GpuMesh mesh;
        Material material;
        glm::mat4 transform;
        glm::vec3 centre;  // of the mesh's bounds, in its own space (for sorting)
    };
    const std::vector<Primitive>& primitives() const { return primitives_; }
    // The texture for a reference, or nullptr when absent. The colour slots (Material::isSrgbSlot)
    // are sRGB, the others linear.
    const Texture2D* texture(const TextureRef& ref, ColorSpace colorSpace) const;
    // Binds a reference's texture to `unit` with a sampler object for its glTF sampler (wrap
    // and filters; the renderer's choice, trilinear, where the file leaves a filter open), or
    // `fallback` with GL's default sampling when the reference is absent. Returns whether the
    // reference's own texture was bound. unbindSamplers() gives units 0..count-1 back to the
    // textures' own parameters.
    bool bindTexture(const TextureRef& ref, ColorSpace colorSpace, int unit,
                     const Texture2D& fallback) const;
    static void unbindSamplers(int count);

private:
    std::vector<Primitive> primitives_;
    std::map<std::pair<TextureRef, ColorSpace>, std::unique_ptr<Texture2D>> textures_;
    std::map<std::tuple<int, int, int, int>, GlSampler> samplers_;  // wrap s, t, mag, min
};

}  // namespace pbr
