#pragma once
// Models through Assimp (glTF 2.0 first): geometry with node transforms accumulated, and every
// primitive's material read into one plain struct. Model is pure data (no GL); GpuModel uploads
// it. Drawing policy (which shader, which inputs) is the sample's.
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include <glm/glm.hpp>

#include "image.h"
#include "mesh.h"
#include "texture.h"

namespace pbr {

// Where a texture's pixels are: a file beside the model, or an image inside it (embedded as
// base64 or in the GLB buffer; Assimp hands both over as "*N").
struct TextureRef {
    std::filesystem::path file;  // absolute; empty when embedded or absent
    int embedded = -1;           // index into Model::embeddedImages, or -1
    int uvSet = 0;
    bool present() const { return embedded >= 0 || !file.empty(); }
    bool operator<(const TextureRef& o) const {
        return std::tie(file, embedded) < std::tie(o.file, o.embedded);
    }
};

enum class AlphaMode { Opaque, Mask, Blend };

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
    // KHR_materials_pbrSpecularGlossiness (the diffuse factor/texture are the base colour above)
    bool specularGlossiness = false;
    glm::vec3 specularFactor{1.0f};
    float glossinessFactor = 1.0f;
    TextureRef specularGlossinessTexture;  // RGB = specular (sRGB), A = glossiness
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
    // glTF's default material, for primitives that name none: every factor at its default (a
    // white, fully metallic, fully rough surface), no textures.
    bool gltfDefault = false;
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
};

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
    explicit GpuModel(const Model& model, TextureFilter filter = TextureFilter::Trilinear);

    struct Primitive {
        GpuMesh mesh;
        Material material;
        glm::mat4 transform;
    };
    const std::vector<Primitive>& primitives() const { return primitives_; }
    // The texture for a reference, or nullptr when absent. Base colour, emissive and
    // specular-glossiness textures are sRGB, the others linear.
    const Texture2D* texture(const TextureRef& ref, ColorSpace colorSpace) const;

private:
    std::vector<Primitive> primitives_;
    std::map<std::pair<TextureRef, ColorSpace>, std::unique_ptr<Texture2D>> textures_;
};

}  // namespace pbr
