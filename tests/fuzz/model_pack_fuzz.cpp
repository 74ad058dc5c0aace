// The compact form of a model the pages read (gltf/model_pack.h, decodeModelPack): any bytes
// either give a Model that keeps loadModel's promises (triangles to draw, indices and materials
// in range, attributes one per vertex, finite positions, normals, transforms, bounds and lights),
// whose pack reads back to the same pack, or are refused in one line naming the pack.
#include "gltf/model_pack.h"
#include "model_promises.h"

namespace pbr::fuzz {

// A pack's own promises beyond a loaded model's: its textures are inside it.
void expectPack(const Model& model) {
    expectModelPromises(model);
    for (const Material& m : model.materials) {
        for (const TextureRef* ref : m.textures())
            expect(ref->file.empty(), "a pack's textures are inside it");
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
    fuzz::expectPack(model);
    // Packed again, it reads back, and packs to the same bytes (the file's name may differ
    // from the first reading's: a pack names the model's file, and "a/b" is read as "b").
    const std::string packed = encodeModelPack(model);
    std::string again;
    if (!fuzz::reads("", [&] { again = encodeModelPack(decodeModelPack(packed, file, "again")); }))
        fuzz::finding("a pack of a decoded model that does not decode");
    fuzz::expect(again == packed, "a decoded model packs to the same bytes again");
    return 0;
}
