// The native loader: glTF 2.0 (and whatever else Assimp reads) through Assimp 5.2, into a
// pbr::Model (model.h). Not in the browser build (Debian has no Assimp for WebAssembly): a page
// reads the compact form of the Model this loader made (model_pack.h).
#include "gltf/model.h"

#include <assimp/GltfMaterial.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <type_traits>
#include <utility>

#include "base/error.h"
#include "base/paths.h"
#include "files/gltf_file.h"

namespace pbr {

namespace fs = std::filesystem;

namespace {

glm::mat4 toGlm(const aiMatrix4x4& m) {
    // Assimp is row-major, GLM column-major
    return glm::mat4(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4,
                     m.b4, m.c4, m.d4);
}

struct Reader {
    const aiScene* scene;
    Model& model;
    std::string where;  // "<file>: "

    // The texture `index` of a type (Assimp keeps an extension's several textures under one
    // type: AI_MATKEY_CLEARCOAT_ROUGHNESS_TEXTURE is aiTextureType_CLEARCOAT, 1).
    TextureRef texture(const aiMaterial* material, aiTextureType type, unsigned index = 0) {
        TextureRef ref;
        aiString path;
        unsigned uvIndex = 0;
        if (material->GetTextureCount(type) <= index ||
            material->GetTexture(type, index, &path, nullptr, &uvIndex) != AI_SUCCESS) {
            return ref;
        }
        ref.uvSet = int(uvIndex);
        readSampler(material, type, index, ref);
        const std::string name = path.C_Str();
        if (!name.empty() && name[0] == '*') {
            const int index = std::atoi(name.c_str() + 1);
            if (index < 0 || index >= int(scene->mNumTextures)) {
                throw Error(where + "texture '" + printable(name) + "' is not in the file");
            }
            ref.embedded = index;
            return ref;
        }
        if (const aiTexture* embedded = scene->GetEmbeddedTexture(name.c_str())) {
            for (unsigned i = 0; i < scene->mNumTextures; ++i) {
                if (scene->mTextures[i] == embedded) ref.embedded = int(i);
            }
            return ref;
        }
        ref.file = model.file.parent_path() / name;
        std::error_code ec;
        if (!fs::is_regular_file(ref.file, ec)) {
            throw Error(where + "texture '" + printable(name) + "' not found (" +
                        printable(displayPath(ref.file)) + ")");
        }
        return ref;
    }

    // The glTF sampler and KHR_texture_transform of a texture, as Assimp 5.2 reports them (see
    // DESIGN.md, "glTF through Assimp 5.2").
    static void readSampler(const aiMaterial* material, aiTextureType type, unsigned index,
                            TextureRef& ref) {
        auto wrap = [](int mode) {
            return mode == aiTextureMapMode_Clamp    ? 33071
                   : mode == aiTextureMapMode_Mirror ? 33648
                                                     : 10497;
        };
        int mode = aiTextureMapMode_Wrap;
        if (material->Get(AI_MATKEY_MAPPINGMODE_U(type, index), mode) == AI_SUCCESS)
            ref.wrapS = wrap(mode);
        mode = aiTextureMapMode_Wrap;
        if (material->Get(AI_MATKEY_MAPPINGMODE_V(type, index), mode) == AI_SUCCESS)
            ref.wrapT = wrap(mode);
        material->Get(AI_MATKEY_GLTF_MAPPINGFILTER_MAG(type, index), ref.magFilter);
        material->Get(AI_MATKEY_GLTF_MAPPINGFILTER_MIN(type, index), ref.minFilter);
        aiUVTransform uv;
        if (material->Get(AI_MATKEY_UVTRANSFORM(type, index), uv) == AI_SUCCESS) {
            // Assimp turns the extension's offset, rotation and scale into its own convention
            // (rotation negated, about the image centre, for its flipped v); undo that to get
            // glTF's values back. Measured on Assimp 5.2: with R the glTF rotation,
            //   translation.x = offset.x + S.x / 2 (1 - cos R + sin R)
            //   translation.y = S.y / 2 (sin R + cos R - 1) + 1 - S.y - offset.y
            const float rotation = -uv.mRotation;
            const float c = std::cos(rotation), s = std::sin(rotation);
            const glm::vec2 scale(uv.mScaling.x, uv.mScaling.y);
            const glm::vec2 offset(
                uv.mTranslation.x - 0.5f * scale.x * (1.0f - c + s),
                0.5f * scale.y * (s + c - 1.0f) + 1.0f - scale.y - uv.mTranslation.y);
            ref.transform = textureTransform(offset, rotation, scale);
        }
    }

    Material material(const aiMaterial* m) {
        Material out;
        out.name = m->GetName().C_Str();
        int shading = 0;
        if (m->Get(AI_MATKEY_SHADING_MODEL, shading) == AI_SUCCESS)
            out.unlit = shading == aiShadingMode_Unlit;
        // KHR_materials_pbrSpecularGlossiness: told by its glossiness factor (such a material
        // still reports metallic and roughness 1, and base colour 1 from the absent
        // pbrMetallicRoughness). Its diffuse factor and texture are on the diffuse slots.
        out.specularGlossiness =
            m->Get(AI_MATKEY_GLOSSINESS_FACTOR, out.glossinessFactor) == AI_SUCCESS;
        aiColor4D color;
        if (out.specularGlossiness ? m->Get(AI_MATKEY_COLOR_DIFFUSE, color) == AI_SUCCESS
                                   : (m->Get(AI_MATKEY_BASE_COLOR, color) == AI_SUCCESS ||
                                      m->Get(AI_MATKEY_COLOR_DIFFUSE, color) == AI_SUCCESS)) {
            out.baseColorFactor = {color.r, color.g, color.b, color.a};
        }
        out.baseColorTexture =
            texture(m, out.specularGlossiness ? aiTextureType_DIFFUSE : aiTextureType_BASE_COLOR);
        if (!out.baseColorTexture.present())
            out.baseColorTexture = texture(m, aiTextureType_DIFFUSE);
        m->Get(AI_MATKEY_METALLIC_FACTOR, out.metallicFactor);
        m->Get(AI_MATKEY_ROUGHNESS_FACTOR, out.roughnessFactor);
        out.metallicRoughnessTexture = texture(m, aiTextureType_UNKNOWN);
        out.normalTexture = texture(m, aiTextureType_NORMALS);
        m->Get(AI_MATKEY_GLTF_TEXTURE_SCALE(aiTextureType_NORMALS, 0), out.normalScale);
        out.occlusionTexture = texture(m, aiTextureType_LIGHTMAP);
        m->Get(AI_MATKEY_GLTF_TEXTURE_STRENGTH(aiTextureType_LIGHTMAP, 0), out.occlusionStrength);
        out.emissiveTexture = texture(m, aiTextureType_EMISSIVE);
        aiColor3D emissive;
        if (m->Get(AI_MATKEY_COLOR_EMISSIVE, emissive) == AI_SUCCESS) {
            out.emissiveFactor = {emissive.r, emissive.g, emissive.b};
        }
        if (out.specularGlossiness) {
            // the factor is $clr.specular; AI_MATKEY_SPECULAR_FACTOR is never set for glTF
            aiColor3D specular;
            if (m->Get(AI_MATKEY_COLOR_SPECULAR, specular) == AI_SUCCESS) {
                out.specularFactor = {specular.r, specular.g, specular.b};
            }
            out.specularGlossinessTexture = texture(m, aiTextureType_SPECULAR);
        }
        aiString alphaMode;
        if (m->Get(AI_MATKEY_GLTF_ALPHAMODE, alphaMode) == AI_SUCCESS) {
            const std::string mode = alphaMode.C_Str();
            out.alphaMode = mode == "MASK"    ? AlphaMode::Mask
                            : mode == "BLEND" ? AlphaMode::Blend
                                              : AlphaMode::Opaque;
        }
        m->Get(AI_MATKEY_GLTF_ALPHACUTOFF, out.alphaCutoff);
        readExtensions(m, out);
        int twoSided = 0;
        if (m->Get(AI_MATKEY_TWOSIDED, twoSided) == AI_SUCCESS) out.doubleSided = twoSided != 0;
        return out;
    }

    // The KHR_materials_* that Assimp 5.2.5 reads (clearcoat, sheen, transmission, volume, ior);
    // _specular and _emissive_strength it drops, and readWhatAssimpDrops reads them.
    void readExtensions(const aiMaterial* m, Material& out) {
        m->Get(AI_MATKEY_CLEARCOAT_FACTOR, out.clearcoat.factor);
        m->Get(AI_MATKEY_CLEARCOAT_ROUGHNESS_FACTOR, out.clearcoat.roughnessFactor);
        out.clearcoat.texture = texture(m, AI_MATKEY_CLEARCOAT_TEXTURE);
        out.clearcoat.roughnessTexture = texture(m, AI_MATKEY_CLEARCOAT_ROUGHNESS_TEXTURE);
        out.clearcoat.normalTexture = texture(m, AI_MATKEY_CLEARCOAT_NORMAL_TEXTURE);
        m->Get(AI_MATKEY_GLTF_TEXTURE_SCALE(aiTextureType_CLEARCOAT, 2), out.clearcoat.normalScale);
        aiColor4D sheen;
        if (m->Get(AI_MATKEY_SHEEN_COLOR_FACTOR, sheen) == AI_SUCCESS)
            out.sheen.colorFactor = {sheen.r, sheen.g, sheen.b};
        m->Get(AI_MATKEY_SHEEN_ROUGHNESS_FACTOR, out.sheen.roughnessFactor);
        out.sheen.colorTexture = texture(m, AI_MATKEY_SHEEN_COLOR_TEXTURE);
        out.sheen.roughnessTexture = texture(m, AI_MATKEY_SHEEN_ROUGHNESS_TEXTURE);
        m->Get(AI_MATKEY_TRANSMISSION_FACTOR, out.transmission.factor);
        out.transmission.texture = texture(m, AI_MATKEY_TRANSMISSION_TEXTURE);
        m->Get(AI_MATKEY_VOLUME_THICKNESS_FACTOR, out.volume.thicknessFactor);
        out.volume.thicknessTexture = texture(m, AI_MATKEY_VOLUME_THICKNESS_TEXTURE);
        m->Get(AI_MATKEY_VOLUME_ATTENUATION_DISTANCE, out.volume.attenuationDistance);
        aiColor4D attenuation;
        if (m->Get(AI_MATKEY_VOLUME_ATTENUATION_COLOR, attenuation) == AI_SUCCESS)
            out.volume.attenuationColor = {attenuation.r, attenuation.g, attenuation.b};
        m->Get(AI_MATKEY_REFRACTI, out.ior);
        keepVolumeInRange(out);
    }

    // The transmission and the volume as their specifications bound them, so that the shading
    // never meets what no file may hold (a number past a float, 1e39, reads as infinity): the
    // transmission factor in [0, 1] (no number: 0), a thickness of 0 or more that is a number
    // (else 0, thin-walled), an attenuation colour in [0, 1] (no number: 1) and a distance above
    // 0 (else infinity, no attenuation).
    static void keepVolumeInRange(Material& out) {
        auto within = [](float v, float lo, float hi, float otherwise) {
            return std::isnan(v) ? otherwise : std::clamp(v, lo, hi);
        };
        out.transmission.factor = within(out.transmission.factor, 0.0f, 1.0f, 0.0f);
        float& thickness = out.volume.thicknessFactor;
        thickness = std::isfinite(thickness) && thickness > 0.0f ? thickness : 0.0f;
        for (int c = 0; c < 3; ++c)
            out.volume.attenuationColor[c] = within(out.volume.attenuationColor[c], 0.0f, 1.0f, 1.0f);
        float& distance = out.volume.attenuationDistance;
        distance = distance > 0.0f ? distance : INFINITY;  // NaN, 0 or less: none
    }

    MeshData mesh(const aiMesh* in) {
        const std::string what = where + "mesh '" + printable(in->mName.C_Str()) + "': ";
        MeshData out;
        const unsigned n = in->mNumVertices;
        if (!in->mVertices || n == 0) throw Error(what + "no vertices");
        out.positions.reserve(n);
        for (unsigned i = 0; i < n; ++i) {
            const aiVector3D& p = in->mVertices[i];
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
                throw Error(what + "vertex " + std::to_string(i) + " has a non-finite position");
            }
            out.positions.push_back({p.x, p.y, p.z});
        }
        for (unsigned i = 0; i < n; ++i) {
            glm::vec3 normal(0.0f, 0.0f, 1.0f);
            if (in->mNormals) {
                const aiVector3D& v = in->mNormals[i];
                const glm::vec3 candidate(v.x, v.y, v.z);
                const float length = glm::length(candidate);
                // a zero or broken normal (BoxBadNormals) becomes +Z rather than NaN in the shader
                if (std::isfinite(length) && length > 1e-6f) normal = candidate / length;
            }
            out.normals.push_back(normal);
            glm::vec2 uv(0.0f);  // glTF: a missing uv is (0, 0)
            if (in->mTextureCoords[0]) {
                // Assimp turns glTF's v upside down; turn it back, so images load top row first
                uv = {in->mTextureCoords[0][i].x, 1.0f - in->mTextureCoords[0][i].y};
            }
            out.uvs.push_back(uv);
            if (in->mTextureCoords[1])
                out.uvs1.push_back({in->mTextureCoords[1][i].x, 1.0f - in->mTextureCoords[1][i].y});
            glm::vec4 tangent(1.0f, 0.0f, 0.0f, 1.0f);
            if (in->mTangents && in->mBitangents) {
                const glm::vec3 t(in->mTangents[i].x, in->mTangents[i].y, in->mTangents[i].z);
                const glm::vec3 b(in->mBitangents[i].x, in->mBitangents[i].y, in->mBitangents[i].z);
                // Assimp's bitangent follows its flipped v, i.e. towards the image's top
                if (std::isfinite(glm::dot(t, t)) && glm::length(t) > 1e-6f) {
                    tangent = glm::vec4(glm::normalize(t),
                                        glm::dot(glm::cross(normal, t), b) < 0.0f ? -1.0f : 1.0f);
                }
            }
            out.tangents.push_back(tangent);
            if (in->mColors[0]) {
                const aiColor4D& c = in->mColors[0][i];
                out.colors.push_back({c.r, c.g, c.b, c.a});
            }
        }
        out.indices.reserve(size_t(in->mNumFaces) * 3);
        for (unsigned f = 0; f < in->mNumFaces; ++f) {
            const aiFace& face = in->mFaces[f];
            if (face.mNumIndices != 3) continue;  // points and lines are not drawn
            for (unsigned k = 0; k < 3; ++k) {
                if (face.mIndices[k] >= n) {
                    throw Error(what + "index " + std::to_string(face.mIndices[k]) +
                                " out of range (" + std::to_string(n) + " vertices)");
                }
                out.indices.push_back(face.mIndices[k]);
            }
        }
        return out;
    }

    void visit(const aiNode* node, const glm::mat4& parent, int depth,
               std::set<const aiNode*>& seen) {
        if (depth > 256 || !seen.insert(node).second)
            throw Error(where + "the node hierarchy loops or is too deep");
        const glm::mat4 transform = parent * toGlm(node->mTransformation);
        for (unsigned i = 0; i < node->mNumMeshes; ++i) {
            if (node->mMeshes[i] >= scene->mNumMeshes)
                throw Error(where + "a node names a mesh that does not exist");
            const aiMesh* in = scene->mMeshes[node->mMeshes[i]];
            if (!(in->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
            ModelPrimitive primitive{mesh(in), int(in->mMaterialIndex), transform};
            if (primitive.mesh.indices.empty()) continue;
            if (primitive.material < 0 || primitive.material >= int(model.materials.size())) {
                throw Error(where + "a mesh names a material that does not exist");
            }
            model.primitives.push_back(std::move(primitive));
        }
        for (unsigned i = 0; i < node->mNumChildren; ++i)
            visit(node->mChildren[i], transform, depth + 1, seen);
    }
};

// Gives every triangle of a mesh its own three vertices (points and lines are left as they are:
// they are not drawn). Bones and morph targets are not carried over; they are not drawn either.
void unweld(aiMesh* mesh) {
    if (!(mesh->mPrimitiveTypes == aiPrimitiveType_TRIANGLE) || mesh->mNumFaces == 0) return;
    const unsigned count = mesh->mNumFaces * 3;
    auto remap = [&](auto*& data) {
        if (!data) return;
        using T = std::remove_reference_t<decltype(*data)>;
        T* out = new T[count];
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            for (unsigned k = 0; k < 3; ++k) out[f * 3 + k] = data[mesh->mFaces[f].mIndices[k]];
        }
        delete[] data;
        data = out;
    };
    remap(mesh->mVertices);
    for (auto*& set : mesh->mTextureCoords) remap(set);
    for (auto*& set : mesh->mColors) remap(set);
    delete[] mesh->mTangents;
    delete[] mesh->mBitangents;
    mesh->mTangents = mesh->mBitangents = nullptr;
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
        for (unsigned k = 0; k < 3; ++k) mesh->mFaces[f].mIndices[k] = f * 3 + k;
    }
    mesh->mNumVertices = count;
    for (unsigned i = 0; i < mesh->mNumBones; ++i) delete mesh->mBones[i];
    delete[] mesh->mBones;
    mesh->mBones = nullptr;
    mesh->mNumBones = 0;
    for (unsigned i = 0; i < mesh->mNumAnimMeshes; ++i) delete mesh->mAnimMeshes[i];
    delete[] mesh->mAnimMeshes;
    mesh->mAnimMeshes = nullptr;
    mesh->mNumAnimMeshes = 0;
}

// The global transform of a node: its own and its parents'.
glm::mat4 globalTransform(const aiNode* node) {
    glm::mat4 transform(1.0f);
    for (int depth = 0; node && depth < 256; node = node->mParent, ++depth)
        transform = toGlm(node->mTransformation) * transform;
    return transform;
}

// KHR_lights_punctual: Assimp hands each light over at its node's origin, shining down the
// node's -Z, with colour x intensity as its diffuse colour; the range is node metadata.
std::vector<PunctualLight> readLights(const aiScene* scene, const std::string& where) {
    std::vector<PunctualLight> lights;
    for (unsigned i = 0; i < scene->mNumLights; ++i) {
        const aiLight* in = scene->mLights[i];
        PunctualLight light;
        light.name = in->mName.C_Str();
        switch (in->mType) {
            case aiLightSource_DIRECTIONAL:
                light.type = PunctualLight::Type::Directional;
                break;
            case aiLightSource_POINT:
                light.type = PunctualLight::Type::Point;
                break;
            case aiLightSource_SPOT:
                light.type = PunctualLight::Type::Spot;
                break;
            default:
                continue;
        }
        light.color = {in->mColorDiffuse.r, in->mColorDiffuse.g, in->mColorDiffuse.b};
        glm::mat4 transform(1.0f);
        const aiNode* node = scene->mRootNode->FindNode(in->mName);
        if (node) {
            transform = globalTransform(node);
            float range = 0.0f;
            if (node->mMetaData && node->mMetaData->Get("PBR_LightRange", range))
                light.range = range;
        }
        const glm::vec3 position(in->mPosition.x, in->mPosition.y, in->mPosition.z);
        const glm::vec3 direction(in->mDirection.x, in->mDirection.y, in->mDirection.z);
        light.position = glm::vec3(transform * glm::vec4(position, 1.0f));
        // a point light shines every way (Assimp gives it no direction)
        light.direction =
            glm::mat3(transform) *
            (light.type == PunctualLight::Type::Point ? glm::vec3(0.0f, 0.0f, -1.0f) : direction);
        const float length = glm::length(light.direction);
        if (!std::isfinite(length) || length < 1e-12f ||
            !std::isfinite(glm::dot(light.position, light.position)) ||
            !std::isfinite(glm::dot(light.color, light.color))) {
            throw Error(where + "light '" + printable(light.name) +
                        "' has a broken transform or colour");
        }
        light.direction /= length;
        if (light.type == PunctualLight::Type::Spot) {
            light.innerConeAngle = in->mAngleInnerCone;
            light.outerConeAngle = in->mAngleOuterCone;
        }
        lights.push_back(light);
    }
    return lights;
}

// What Assimp 5.2.5 drops of a glTF material, read from the file's JSON: KHR_texture_transform's
// texCoord (it overrides the textureInfo's texture coordinate set), KHR_materials_specular and
// KHR_materials_emissive_strength, and the names in each material's "extensions". Assimp's
// materials are matched with the file's by the order it reads them in (assimpMaterialOrder),
// checked against their names; where they do not match, these are left out, saying so.

// A JSON number as a float, or nullopt when the value is absent, not a number, or past a
// float's range (a file's 1e300 is refused, not turned into infinity).
std::optional<float> jsonNumber(const JsonValue* value) {
    if (!value || value->type != JsonValue::Type::Number || !std::isfinite(value->number) ||
        std::abs(value->number) > double(std::numeric_limits<float>::max()))
        return std::nullopt;
    return float(value->number);
}
std::optional<glm::vec3> jsonVec3(const JsonValue* value) {
    if (!value || value->type != JsonValue::Type::Array || value->items.size() != 3)
        return std::nullopt;
    glm::vec3 out;
    for (int i = 0; i < 3; ++i) {
        const auto number = jsonNumber(&value->items[size_t(i)]);
        if (!number) return std::nullopt;
        out[i] = *number;
    }
    return out;
}
// The TextureRef of a textureInfo that Assimp did not read, as Assimp would have made it: an
// image with its bytes inside the file (a buffer view, a data: URI) is embedded image N, N
// counting the file's images with bytes inside it before it (Assimp numbers them so); any other
// is a file beside the model.
TextureRef jsonTexture(const JsonValue& document, const JsonValue& textureInfo, const Model& model,
                       const std::string& what) {
    TextureRef ref;
    const int index = jsonIndex(textureInfo.find("index"));
    const JsonValue* texture = jsonItem(document, "textures", index);
    if (!texture) throw Error(what + " names a texture the file does not have");
    const int source = jsonIndex(texture->find("source"));
    const JsonValue* image = jsonItem(document, "images", source);
    if (!image) throw Error(what + " names an image the file does not have");
    auto inside = [](const JsonValue& candidate) {
        const JsonValue* uri = candidate.find("uri");
        return !uri || uri->type != JsonValue::Type::String || uri->text.starts_with("data:");
    };
    if (inside(*image)) {
        ref.embedded = 0;
        for (int i = 0; i < source; ++i) ref.embedded += inside(*jsonItem(document, "images", i));
        if (ref.embedded >= int(model.embeddedImages.size()))
            throw Error(what + ": its image is not in the file");
    } else {
        ref.file = model.file.parent_path() / image->find("uri")->text;
        std::error_code ec;
        if (!fs::is_regular_file(ref.file, ec)) {
            throw Error(what + ": texture '" + printable(image->find("uri")->text) +
                        "' not found (" + printable(displayPath(ref.file)) + ")");
        }
    }
    ref.uvSet = std::max(jsonIndex(textureInfo.find("texCoord")), 0);
    if (const JsonValue* sampler =
            jsonItem(document, "samplers", jsonIndex(texture->find("sampler")))) {
        auto number = [&](const char* name, int fallback) {
            const int value = jsonIndex(sampler->find(name));
            return value < 0 ? fallback : value;
        };
        ref.wrapS = number("wrapS", 10497);
        ref.wrapT = number("wrapT", 10497);
        ref.magFilter = number("magFilter", 0);
        ref.minFilter = number("minFilter", 0);
    }
    const JsonValue* extensions = textureInfo.find("extensions");
    if (const JsonValue* transform =
            extensions ? extensions->find("KHR_texture_transform") : nullptr) {
        const JsonValue* offset = transform->find("offset");
        const JsonValue* scale = transform->find("scale");
        auto vec2 = [](const JsonValue* value, glm::vec2 fallback) {
            if (!value || value->items.size() != 2) return fallback;
            const auto x = jsonNumber(&value->items[0]), y = jsonNumber(&value->items[1]);
            return x && y ? glm::vec2(*x, *y) : fallback;
        };
        ref.transform = textureTransform(vec2(offset, glm::vec2(0.0f)),
                                         jsonNumber(transform->find("rotation")).value_or(0.0f),
                                         vec2(scale, glm::vec2(1.0f)));
    }
    return ref;
}

// Whether a JSON value holds what Assimp drops: a KHR_texture_transform that sets texCoord,
// KHR_materials_specular or KHR_materials_emissive_strength.
bool holdsWhatAssimpDrops(const JsonValue& value) {
    for (const auto& [name, member] : value.members) {
        if ((name == "KHR_texture_transform" && member.find("texCoord")) ||
            name == "KHR_materials_specular" || name == "KHR_materials_emissive_strength" ||
            holdsWhatAssimpDrops(member))
            return true;
    }
    for (const JsonValue& item : value.items) {
        if (holdsWhatAssimpDrops(item)) return true;
    }
    return false;
}

void readWhatAssimpDrops(const JsonValue& document, Model& model, const std::string& where) {
    std::vector<Material>& materials = model.materials;
    const JsonValue* list = document.find("materials");
    if (!list || materials.empty()) return;
    const bool drops = holdsWhatAssimpDrops(*list);
    const bool named = std::any_of(list->items.begin(), list->items.end(),
                                   [](const JsonValue& m) { return m.find("extensions"); });
    if (!drops && !named) return;
    const std::vector<int> order = assimpMaterialOrder(document);
    auto nameOf = [&](int index) {
        const JsonValue* name = list->items[size_t(index)].find("name");
        return name && name->type == JsonValue::Type::String ? name->text : std::string();
    };
    const size_t imported = materials.size() - (materials.back().gltfDefault ? 1 : 0);
    bool matched = order.size() == imported;
    for (size_t i = 0; matched && i < order.size(); ++i)
        matched = nameOf(order[i]) == materials[i].name;
    if (!matched) {
        // (where only the extensions' names were wanted, nothing drawn is lost: no note)
        if (drops) {
            model.notes.push_back(
                "the file's materials could not be matched with Assimp's; KHR_texture_transform's "
                "texCoord, KHR_materials_specular and KHR_materials_emissive_strength are ignored");
        }
        return;
    }
    for (size_t i = 0; i < order.size(); ++i) {
        const JsonValue& in = list->items[size_t(order[i])];
        Material& out = materials[i];
        const std::string what = where + "material '" + printable(out.name) + "'";
        auto apply = [](const JsonValue* textureInfo, TextureRef& ref) {
            if (!textureInfo || !ref.present()) return;
            if (const auto set = texCoordOverride(*textureInfo)) ref.uvSet = *set;
        };
        const JsonValue* pbr = in.find("pbrMetallicRoughness");
        const JsonValue* extensions = in.find("extensions");
        auto extension = [&](const char* name) {
            return extensions ? extensions->find(name) : nullptr;
        };
        const JsonValue* specGloss = extension("KHR_materials_pbrSpecularGlossiness");
        if (out.specularGlossiness) {
            apply(specGloss ? specGloss->find("diffuseTexture") : nullptr, out.baseColorTexture);
            apply(specGloss ? specGloss->find("specularGlossinessTexture") : nullptr,
                  out.specularGlossinessTexture);
        } else {
            apply(pbr ? pbr->find("baseColorTexture") : nullptr, out.baseColorTexture);
            apply(pbr ? pbr->find("metallicRoughnessTexture") : nullptr,
                  out.metallicRoughnessTexture);
        }
        apply(in.find("normalTexture"), out.normalTexture);
        apply(in.find("occlusionTexture"), out.occlusionTexture);
        apply(in.find("emissiveTexture"), out.emissiveTexture);
        if (const JsonValue* coat = extension("KHR_materials_clearcoat")) {
            apply(coat->find("clearcoatTexture"), out.clearcoat.texture);
            apply(coat->find("clearcoatRoughnessTexture"), out.clearcoat.roughnessTexture);
            apply(coat->find("clearcoatNormalTexture"), out.clearcoat.normalTexture);
        }
        if (const JsonValue* sheen = extension("KHR_materials_sheen")) {
            apply(sheen->find("sheenColorTexture"), out.sheen.colorTexture);
            apply(sheen->find("sheenRoughnessTexture"), out.sheen.roughnessTexture);
        }
        if (const JsonValue* transmission = extension("KHR_materials_transmission"))
            apply(transmission->find("transmissionTexture"), out.transmission.texture);
        if (const JsonValue* volume = extension("KHR_materials_volume"))
            apply(volume->find("thicknessTexture"), out.volume.thicknessTexture);
        // KHR_materials_specular: all of it (Assimp 5.2.5 has no key for it)
        if (const JsonValue* specular = extension("KHR_materials_specular")) {
            out.khrSpecular.factor =
                jsonNumber(specular->find("specularFactor")).value_or(out.khrSpecular.factor);
            out.khrSpecular.colorFactor = jsonVec3(specular->find("specularColorFactor"))
                                              .value_or(out.khrSpecular.colorFactor);
            if (const JsonValue* texture = specular->find("specularTexture")) {
                out.khrSpecular.texture = jsonTexture(
                    document, *texture, model, what + ": KHR_materials_specular's specularTexture");
            }
            if (const JsonValue* texture = specular->find("specularColorTexture")) {
                out.khrSpecular.colorTexture =
                    jsonTexture(document, *texture, model,
                                what + ": KHR_materials_specular's specularColorTexture");
            }
        }
        // KHR_materials_emissive_strength (Assimp 5.2.5 reads none of it)
        if (const JsonValue* strength = extension("KHR_materials_emissive_strength")) {
            out.emissiveStrength =
                jsonNumber(strength->find("emissiveStrength")).value_or(out.emissiveStrength);
        }
        if (extensions) {
            for (const auto& [name, member] : extensions->members) out.extensions.push_back(name);
        }
    }
}

}  // namespace

Model loadModel(const fs::path& file) {
    std::error_code ec;
    if (!fs::exists(file, ec)) throw Error(displayPath(file) + ": no such file");
    if (!fs::is_regular_file(file, ec)) throw Error(displayPath(file) + ": not a file");
    if (fs::file_size(file, ec) == 0) throw Error(displayPath(file) + ": empty file");
    const std::string where = displayPath(file) + ": ";
    bool isGltf = false;
    std::vector<std::string> extensionsUsed, extensionsRequired;
    std::optional<JsonValue> document;  // a glTF file's JSON, for what Assimp does not read
    {
        // Assimp's answer to a broken glTF container is "no suitable reader": say what is wrong.
        std::string extension = file.extension().string();
        for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
        const std::string bytes = readTextFile(file);
        const size_t first = bytes.find_first_not_of(" \t\r\n");
        const bool json = first != std::string::npos && bytes[first] == '{';
        std::optional<JsonValue> parsed;
        if (bytes.starts_with("glTF") || json || extension == ".gltf") {
            if (const auto problem = gltfContainerError(bytes)) throw Error(where + *problem);
            // Assimp 5.2 crashes on some glTF files it should refuse (a skin without its
            // matrices, an accessor past its buffer): those are refused here, saying why.
            parsed = gltfJson(bytes);
            if (parsed) {
                const std::optional<std::string_view> bin = glbBin(bytes);
                const auto bufferBytes = [&](size_t index,
                                             std::string_view uri) -> std::optional<std::string> {
                    if (bin && index == 0) return std::string(*bin);
                    if (uri.empty() || uri.find(':') != std::string_view::npos) return std::nullopt;
                    try {  // a file beside the .gltf (Assimp says so when it is missing)
                        return readTextFile(file.parent_path() / pathFromUtf8(uri));
                    } catch (const Error&) {
                        return std::nullopt;
                    }
                };
                if (const auto problem = gltfStructureError(
                        *parsed, bin ? std::optional<std::uint64_t>(bin->size()) : std::nullopt,
                        bufferBytes))
                    throw Error(where + *problem);
            }
        } else if (extension == ".glb") {
            throw Error(where + "not a binary glTF file (it does not start with 'glTF')");
        }
        isGltf = bytes.starts_with("glTF") || json;
        if (isGltf) {
            GltfExtensions extensions = gltfExtensions(bytes);
            extensionsUsed = std::move(extensions.used);
            extensionsRequired = std::move(extensions.required);
            document = std::move(parsed);
        }
    }

    Assimp::Importer importer;
    const aiScene* scene =
        importer.ReadFile(utf8Path(file), aiProcess_Triangulate | aiProcess_SortByPType |
                                              aiProcess_ValidateDataStructure);
    if (scene) {
        // glTF 3.7.2.1: a primitive without NORMAL gets flat normals. Assimp's flat normals
        // are one per vertex, so the triangles of such a mesh stop sharing vertices first.
        for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
            if (!scene->mMeshes[i]->mNormals) unweld(scene->mMeshes[i]);
        }
        scene = importer.ApplyPostProcessing(aiProcess_GenNormals | aiProcess_CalcTangentSpace);
    }
    if (!scene) {
        std::string reason = importer.GetErrorString();
        while (!reason.empty() && (reason.back() == '\n' || reason.back() == ' '))
            reason.pop_back();
        // Assimp's reason may quote the file (a base64 text, a name): one line whatever it holds
        throw Error(where + "cannot load (" +
                    (reason.empty() ? "unknown reason" : printable(reason)) + ")");
    }
    if (!scene->mRootNode || scene->mNumMeshes == 0) {
        throw Error(
            where + "no meshes to draw" +
            std::string(scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE ? " (incomplete scene)" : ""));
    }

    Model model;
    model.file = fs::absolute(file);
    model.extensionsUsed = std::move(extensionsUsed);
    model.extensionsRequired = std::move(extensionsRequired);
    model.lights = readLights(scene, where);
    Reader reader{scene, model, where};
    for (unsigned i = 0; i < scene->mNumTextures; ++i) {
        const aiTexture* t = scene->mTextures[i];
        EmbeddedImage image;
        image.name = t->mFilename.length ? t->mFilename.C_Str() : "*" + std::to_string(i);
        if (t->mHeight == 0) {  // compressed: mWidth bytes of a PNG/JPEG file
            const auto* bytes = reinterpret_cast<const std::uint8_t*>(t->pcData);
            image.bytes.assign(bytes, bytes + t->mWidth);
        } else {  // raw ARGB8888 texels
            image.width = int(t->mWidth);
            image.height = int(t->mHeight);
            for (unsigned p = 0; p < t->mWidth * t->mHeight; ++p) {
                image.bytes.insert(image.bytes.end(), {t->pcData[p].r, t->pcData[p].g,
                                                       t->pcData[p].b, t->pcData[p].a});
            }
        }
        model.embeddedImages.push_back(std::move(image));
    }
    for (unsigned i = 0; i < scene->mNumMaterials; ++i)
        model.materials.push_back(reader.material(scene->mMaterials[i]));
    // Assimp appends a nameless material of its own to every glTF scene for the primitives that
    // name none: glTF's default material (all factors at their defaults, so white).
    if (isGltf && !model.materials.empty() && model.materials.back().name.empty()) {
        model.materials.back().gltfDefault = true;
    }
    if (document) readWhatAssimpDrops(*document, model, where);
    // The samples (their shaders, the pages' packs) read TEXCOORD_0 and TEXCOORD_1, as the
    // Khronos viewer does.
    for (Material& material : model.materials) {
        const auto slots = material.textures();
        for (size_t s = 0; s < slots.size(); ++s) {
            const int set = std::exchange(slots[s]->uvSet, slots[s]->uvSet == 1 ? 1 : 0);
            if (set == 0 || set == 1 || !slots[s]->present()) continue;
            model.notes.push_back("material '" + printable(material.name) + "': its " +
                                  Material::kTextureNames[s] + " reads TEXCOORD_" +
                                  std::to_string(set) +
                                  ", drawn with TEXCOORD_0 (the samples read sets 0 and 1)");
        }
    }
    std::set<const aiNode*> seen;
    reader.visit(scene->mRootNode, glm::mat4(1.0f), 0, seen);
    if (model.primitives.empty()) throw Error(where + "no triangles to draw");
    for (const ModelPrimitive& primitive : model.primitives) {
        if (model.materials[size_t(primitive.material)].gltfDefault)
            ++model.primitivesWithoutMaterial;
    }

    model.boundsMin = glm::vec3(INFINITY);
    model.boundsMax = glm::vec3(-INFINITY);
    for (const ModelPrimitive& primitive : model.primitives) {
        for (const glm::vec3& p : primitive.mesh.positions) {
            const glm::vec3 world = glm::vec3(primitive.transform * glm::vec4(p, 1.0f));
            model.boundsMin = glm::min(model.boundsMin, world);
            model.boundsMax = glm::max(model.boundsMax, world);
        }
    }
    if (!std::isfinite(glm::dot(model.boundsMin, model.boundsMax)))
        throw Error(where + "non-finite node transforms");
    return model;
}

}  // namespace pbr
