#pragma once
// The promises of a loaded model (gltf/model.h) that the model and model_pack targets check: a
// loadModel result and a decoded pack, which stands for one, keep the same ones.
#include <cmath>

#include "fuzz_check.h"
#include "gltf/model.h"

namespace pbr::fuzz {

inline bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Triangles to draw; finite bounds, lights, transforms, positions and normals; each attribute one
// per vertex (or none), indices and materials in range; textures on TEXCOORD_0 or _1, embedded
// ones among the model's images, raw images of width x height RGBA texels.
inline void expectModelPromises(const Model& model) {
    expect(!model.primitives.empty(), "triangles to draw");
    expect(finite(model.boundsMin) && finite(model.boundsMax), "finite bounds");
    for (const PunctualLight& light : model.lights) {
        expect(finite(light.position) && finite(light.direction) && finite(light.color),
               "a light's place, direction and colour are finite");
    }
    for (const EmbeddedImage& image : model.embeddedImages) {
        expect(image.width <= 0 ||
                   image.bytes.size() == size_t(image.width) * size_t(image.height) * 4,
               "raw texels are width x height RGBA");
    }
    for (const Material& m : model.materials) {
        for (const TextureRef* ref : m.textures()) {
            expect(ref->embedded >= -1 && ref->embedded < int(model.embeddedImages.size()),
                   "a texture is one of the model's images, or a file");
            expect(ref->uvSet == 0 || ref->uvSet == 1, "TEXCOORD_0 or TEXCOORD_1");
        }
    }
    for (const ModelPrimitive& p : model.primitives) {
        expect(p.material >= 0 && size_t(p.material) < model.materials.size(),
               "a primitive's material is in the model");
        for (int column = 0; column < 4; ++column) {
            expect(finite(glm::vec3(p.transform[column])) && std::isfinite(p.transform[column].w),
                   "a finite transform");
        }
        const MeshData& mesh = p.mesh;
        const size_t n = mesh.positions.size();
        for (const size_t count : {mesh.normals.size(), mesh.uvs.size(), mesh.tangents.size(),
                                   mesh.colors.size(), mesh.uvs1.size()}) {
            expect(count == 0 || count == n, "each attribute one per vertex, or none");
        }
        for (const glm::vec3& position : mesh.positions)
            expect(finite(position), "finite positions");
        for (const glm::vec3& normal : mesh.normals) expect(finite(normal), "finite normals");
        for (const std::uint32_t index : mesh.indices) expect(index < n, "indices in range");
    }
}

}  // namespace pbr::fuzz
