// The compact form of a Model the pages read (gltf/model_pack.h): what the native loader made of
// a file comes back field for field, its texture files inside with the same pixels; bytes that
// are not a whole pack are one error naming the file, never a model.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "support/gltf_scene.h"
#include "support/process.h"
#include "support/test_data.h"

#include "base/error.h"
#include "base/paths.h"
#include "gltf/model.h"
#include "gltf/model_pack.h"

namespace pbr {
namespace {

namespace fs = std::filesystem;

void expectSameMesh(const MeshData& a, const MeshData& b) {
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.normals, b.normals);
    EXPECT_EQ(a.uvs, b.uvs);
    EXPECT_EQ(a.tangents, b.tangents);
    EXPECT_EQ(a.colors, b.colors);
    EXPECT_EQ(a.uvs1, b.uvs1);
    EXPECT_EQ(a.indices, b.indices);
    EXPECT_EQ(a.primitive, b.primitive);
}

// A texture reference of the pack against the loader's: the same sampling, the same pixels.
void expectSameTexture(const Model& original, const TextureRef& a, const Model& packed,
                       const TextureRef& b) {
    ASSERT_EQ(a.present(), b.present());
    EXPECT_EQ(a.uvSet, b.uvSet);
    EXPECT_EQ(std::tie(a.wrapS, a.wrapT, a.magFilter, a.minFilter),
              std::tie(b.wrapS, b.wrapT, b.magFilter, b.minFilter));
    EXPECT_EQ(a.transform, b.transform);
    if (!a.present()) return;
    EXPECT_TRUE(b.file.empty()) << "a pack carries its textures inside";
    const Image x = loadTextureImage(original, a), y = loadTextureImage(packed, b);
    EXPECT_EQ(std::tie(x.width, x.height, x.channels), std::tie(y.width, y.height, y.channels));
    EXPECT_TRUE(x.pixels == y.pixels);
}

void expectRoundTrip(const fs::path& file) {
    SCOPED_TRACE(file.string());
    const Model original = loadModel(file);
    const std::string bytes = encodeModelPack(original);
    const Model packed = decodeModelPack(bytes, file, "pack");
    EXPECT_EQ(packed.file, original.file);
    EXPECT_EQ(packed.extensionsUsed, original.extensionsUsed);
    EXPECT_EQ(packed.extensionsRequired, original.extensionsRequired);
    EXPECT_EQ(packed.notes, original.notes);
    EXPECT_EQ(packed.primitivesWithoutMaterial, original.primitivesWithoutMaterial);
    EXPECT_EQ(packed.boundsMin, original.boundsMin);
    EXPECT_EQ(packed.boundsMax, original.boundsMax);
    ASSERT_EQ(packed.lights.size(), original.lights.size());
    for (size_t i = 0; i < original.lights.size(); ++i) {
        const PunctualLight &a = original.lights[i], &b = packed.lights[i];
        EXPECT_EQ(std::tie(a.type, a.name, a.color, a.position, a.direction),
                  std::tie(b.type, b.name, b.color, b.position, b.direction));
        EXPECT_EQ(std::tie(a.range, a.innerConeAngle, a.outerConeAngle),
                  std::tie(b.range, b.innerConeAngle, b.outerConeAngle));
    }
    ASSERT_EQ(packed.materials.size(), original.materials.size());
    for (size_t i = 0; i < original.materials.size(); ++i) {
        const Material &a = original.materials[i], &b = packed.materials[i];
        SCOPED_TRACE(a.name);
        EXPECT_EQ(std::tie(a.name, a.unlit, a.specularGlossiness, a.doubleSided, a.gltfDefault),
                  std::tie(b.name, b.unlit, b.specularGlossiness, b.doubleSided, b.gltfDefault));
        EXPECT_EQ(a.baseColorFactor, b.baseColorFactor);
        EXPECT_EQ(std::tie(a.metallicFactor, a.roughnessFactor, a.normalScale, a.occlusionStrength,
                           a.glossinessFactor, a.alphaMode, a.alphaCutoff),
                  std::tie(b.metallicFactor, b.roughnessFactor, b.normalScale, b.occlusionStrength,
                           b.glossinessFactor, b.alphaMode, b.alphaCutoff));
        EXPECT_EQ(a.emissiveFactor, b.emissiveFactor);
        EXPECT_EQ(a.specularFactor, b.specularFactor);
        // sample 10's extensions
        EXPECT_EQ(std::tie(a.clearcoat.factor, a.clearcoat.roughnessFactor, a.clearcoat.normalScale,
                           a.sheen.colorFactor, a.sheen.roughnessFactor, a.transmission.factor,
                           a.volume.thicknessFactor, a.volume.attenuationDistance,
                           a.volume.attenuationColor, a.ior),
                  std::tie(b.clearcoat.factor, b.clearcoat.roughnessFactor, b.clearcoat.normalScale,
                           b.sheen.colorFactor, b.sheen.roughnessFactor, b.transmission.factor,
                           b.volume.thicknessFactor, b.volume.attenuationDistance,
                           b.volume.attenuationColor, b.ior));
        EXPECT_EQ(std::tie(a.khrSpecular.factor, a.khrSpecular.colorFactor, a.emissiveStrength,
                           a.extensions),
                  std::tie(b.khrSpecular.factor, b.khrSpecular.colorFactor, b.emissiveStrength,
                           b.extensions));
        const auto slotsA = a.textures(), slotsB = b.textures();
        for (size_t slot = 0; slot < slotsA.size(); ++slot) {
            SCOPED_TRACE(Material::kTextureNames[slot]);
            expectSameTexture(original, *slotsA[slot], packed, *slotsB[slot]);
        }
    }
    ASSERT_EQ(packed.primitives.size(), original.primitives.size());
    for (size_t i = 0; i < original.primitives.size(); ++i) {
        EXPECT_EQ(packed.primitives[i].material, original.primitives[i].material);
        EXPECT_EQ(packed.primitives[i].transform, original.primitives[i].transform);
        expectSameMesh(original.primitives[i].mesh, packed.primitives[i].mesh);
    }
    // each texture file once, however many materials name it
    size_t files = 0;
    std::set<fs::path> seen;
    for (const Material& m : original.materials) {
        for (const TextureRef* ref : m.textures()) {
            if (!ref->file.empty() && seen.insert(ref->file).second) ++files;
        }
    }
    EXPECT_EQ(packed.embeddedImages.size(), original.embeddedImages.size() + files);
}

TEST(ModelPack, TheProjectsModelsComeBackAsTheLoaderMadeThem) {
    for (const char* name : {"unlit_showcase.gltf", "pbr_showcase.gltf", "pbr_workflows.gltf"})
        expectRoundTrip(modelDir() / name);
}

// Sample 10's material extensions, a texture in every slot, half of them inside the file.
TEST(ModelPack, MaterialExtensionsComeBack) {
    expectRoundTrip(
        test::writeMaterialExtensionsFile(test::testOutputDir("model_pack_extensions")));
}

// Embedded images (a .glb's buffer), two texture coordinate sets, texture transforms.
TEST(ModelPack, EmbeddedImagesAndTransformsComeBack) {
    PBR_NEED_ASSIMP_MODELS(models);
    expectRoundTrip(models / "BoxTextured-glTF-Binary" / "BoxTextured.glb");
    expectRoundTrip(models / "textureTransform" / "TextureTransformTest.gltf");
}

// What the build packed is what the loader makes now (the page draws the native model).
TEST(ModelPack, TheBuildsPacksAreTheLoadersModels) {
    for (const char* name : {"unlit_showcase.gltf", "pbr_showcase.gltf", "pbr_workflows.gltf"}) {
        const fs::path file = modelDir() / name;
        EXPECT_TRUE(readTextFile(packedModelPath(file)) == encodeModelPack(loadModel(file)))
            << name << ": the build's pack differs from the loader's model";
    }
}

TEST(ModelPack, DamagedPacksAreOneErrorNamingTheFile) {
    const std::string bytes = encodeModelPack(loadModel(modelDir() / "unlit_showcase.gltf"));
    auto error = [](std::string_view data) {
        try {
            decodeModelPack(data, "/m/x.gltf", "x.gltf.pbrmodel");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    EXPECT_EQ(error("not a pack"), "x.gltf.pbrmodel: not a model pack");
    for (const size_t size : {size_t(10), size_t(100), bytes.size() / 2, bytes.size() - 1}) {
        EXPECT_EQ(error(std::string_view(bytes).substr(0, size)),
                  "x.gltf.pbrmodel: truncated (not a whole model pack)")
            << size;
    }
    EXPECT_EQ(error(bytes + "x"),
              "x.gltf.pbrmodel: bytes after the model (not a model pack of "
              "this layout)");
    std::string other = bytes;
    other[8] = 7;  // the layout's version
    EXPECT_EQ(error(other),
              "x.gltf.pbrmodel: a model pack of layout 7, not 2 (made by another "
              "version of the suite)");
}

}  // namespace
}  // namespace pbr
