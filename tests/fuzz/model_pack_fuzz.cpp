// The compact form of a model the pages read (gltf/model_pack.h, decodeModelPack): any bytes
// either give a Model that keeps loadModel's promises (triangles to draw, indices and materials
// in range, attributes one per vertex, finite positions, normals, transforms, bounds and lights),
// whose pack reads back to the same pack, or are refused in one line naming the pack.
#include "fuzz_check.h"
#include "gltf/model_pack.h"

namespace pbr::fuzz {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void expectTexture(const TextureRef& ref, const Model& model) {
    expect(ref.file.empty(), "a pack's textures are inside it");
    expect(ref.embedded >= -1 && ref.embedded < int(model.embeddedImages.size()),
           "a texture is one of the pack's images");
    expect(ref.uvSet == 0 || ref.uvSet == 1, "TEXCOORD_0 or TEXCOORD_1");
}

// The promises of loadModel (model.h), which a pack stands for.
void expectDrawable(const Model& model) {
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
        for (const TextureRef* ref :
             {&m.baseColorTexture, &m.metallicRoughnessTexture, &m.normalTexture,
              &m.occlusionTexture, &m.emissiveTexture, &m.specularGlossinessTexture}) {
            expectTexture(*ref, model);
        }
    }
    for (const ModelPrimitive& p : model.primitives) {
        expect(p.material >= 0 && size_t(p.material) < model.materials.size(),
               "a primitive's material is in the pack");
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

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace pbr;
    const std::string name = "fuzz.gltf.pbrmodel";
    const std::filesystem::path file = "fuzz/model.gltf";
    Model model;
    if (!fuzz::reads(name, [&] { model = decodeModelPack(fuzz::bytesOf(data, size), file, name); }))
        return 0;
    fuzz::expectDrawable(model);
    // Packed again, it reads back, and packs to the same bytes (the file's name may differ
    // from the first reading's: a pack names the model's file, and "a/b" is read as "b").
    const std::string packed = encodeModelPack(model);
    std::string again;
    if (!fuzz::reads("", [&] { again = encodeModelPack(decodeModelPack(packed, file, "again")); }))
        fuzz::finding("a pack of a decoded model that does not decode");
    fuzz::expect(again == packed, "a decoded model packs to the same bytes again");
    return 0;
}
