// The model loader's materials and geometry for known files. Expected values are read off each
// file's JSON (quoted beside them), not off the loader.
#include <gtest/gtest.h>

#include "support/test_data.h"

#include "base/error.h"
#include "base/paths.h"
#include "gltf/model.h"

namespace pbr {
namespace {

namespace fs = std::filesystem;

const Material& materialNamed(const Model& model, const std::string& name) {
    for (const Material& m : model.materials) {
        if (m.name == name) return m;
    }
    throw std::runtime_error("no material " + name);
}

TEST(Model, OwnShowcaseHasTheThreeUnlitInputs) {
    const Model model = loadModel(modelDir() / "unlit_showcase.gltf");
    ASSERT_EQ(model.primitives.size(), 4u);
    // every material: "extensions":{"KHR_materials_unlit":{}}
    const Material& colours = materialNamed(model, "vertex colours");
    const Material& factor = materialNamed(model, "base colour factor");
    const Material& texture = materialNamed(model, "base colour texture");
    const Material& all = materialNamed(model, "all three");
    for (const Material* m : {&colours, &factor, &texture, &all}) EXPECT_TRUE(m->unlit) << m->name;
    EXPECT_EQ(factor.baseColorFactor, glm::vec4(1.0f, 0.42f, 0.08f, 1.0f));
    EXPECT_FALSE(factor.baseColorTexture.present());
    EXPECT_EQ(all.baseColorFactor, glm::vec4(0.95f, 0.85f, 1.0f, 1.0f));
    EXPECT_EQ(texture.baseColorTexture.file.filename(), "unlit_showcase_texture.png");
    EXPECT_EQ(all.baseColorTexture.file, texture.baseColorTexture.file);
    EXPECT_FALSE(colours.baseColorTexture.present());
    // COLOR_0 on the cube and the all-three quad only; the nodes' translations are applied
    int withColours = 0;
    for (const ModelPrimitive& p : model.primitives) {
        withColours += p.mesh.colors.empty() ? 0 : 1;
        const glm::vec3 t(p.transform[3]);
        EXPECT_NEAR(std::abs(t.x), 1.1f, 1e-6f);
        EXPECT_NEAR(std::abs(t.y), 0.6f, 1e-6f);
    }
    EXPECT_EQ(withColours, 2);
    EXPECT_NEAR(model.boundsMax.x, 1.55f, 1e-5f);  // the sphere: 1.1 + 0.45
}

TEST(Model, BoxTexturedInItsThreeForms) {
    PBR_NEED_ASSIMP_MODELS(kGltf);
    // "materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0},"metallicFactor":0.0},"name":"Texture"}]
    for (const char* file :
         {"BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb",
          "BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
        const Model model = loadModel(kGltf / file);
        const Material& m = materialNamed(model, "Texture");
        EXPECT_FALSE(m.unlit) << file;
        EXPECT_EQ(m.baseColorFactor, glm::vec4(1.0f)) << file;  // the default
        EXPECT_EQ(m.metallicFactor, 0.0f) << file;
        EXPECT_EQ(m.roughnessFactor, 1.0f) << file;  // the default
        EXPECT_TRUE(m.baseColorTexture.present()) << file;
        EXPECT_FALSE(m.normalTexture.present()) << file;
        EXPECT_EQ(m.alphaMode, AlphaMode::Opaque) << file;
        EXPECT_FALSE(m.doubleSided) << file;
        const Image image = loadTextureImage(model, m.baseColorTexture);
        EXPECT_EQ(image.width, 211) << file;  // CesiumLogoFlat.png: 211 x 211
        EXPECT_EQ(image.height, 211) << file;
        EXPECT_EQ(model.primitives.size(), 1u);
        EXPECT_EQ(model.primitives[0].mesh.indices.size(), 36u);  // 12 triangles
    }
    // external file, embedded base64, GLB buffer
    auto where = [&kGltf](const char* file) {
        return materialNamed(loadModel(kGltf / file), "Texture").baseColorTexture;
    };
    EXPECT_EQ(where("BoxTextured-glTF/BoxTextured.gltf").embedded, -1);
    EXPECT_EQ(where("BoxTextured-glTF/BoxTextured.gltf").file.filename(), "CesiumLogoFlat.png");
    EXPECT_GE(where("BoxTextured-glTF-Binary/BoxTextured.glb").embedded, 0);
    EXPECT_GE(where("BoxTextured-glTF-Embedded/BoxTextured.gltf").embedded, 0);
}

TEST(Model, SpecularGlossiness) {
    PBR_NEED_ASSIMP_MODELS(kGltf);
    // "KHR_materials_pbrSpecularGlossiness":{"diffuseTexture":{"index":0},
    //     "specularFactor":[0.2,0.2,0.2],"glossinessFactor":1.0}
    const Model model =
        loadModel(kGltf / "BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf");
    const Material& m = materialNamed(model, "Texture");
    EXPECT_TRUE(m.specularGlossiness);
    EXPECT_FLOAT_EQ(m.glossinessFactor, 1.0f);
    EXPECT_NEAR(m.specularFactor.r, 0.2f, 1e-6f);
    EXPECT_NEAR(m.specularFactor.b, 0.2f, 1e-6f);
    EXPECT_TRUE(m.baseColorTexture.present());
}

TEST(Model, ClearCoatTestFactors) {
    PBR_NEED_ASSIMP_MODELS(kGltf);
    // "Simple_Base": "baseColorFactor":[0.5,0.02,0.01,1],"metallicFactor":0,"roughnessFactor":0.44
    const Model model = loadModel(kGltf / "ClearCoat-glTF/ClearCoatTest.gltf");
    const Material& m = materialNamed(model, "Simple_Base");
    EXPECT_NEAR(m.baseColorFactor.r, 0.5f, 1e-6f);
    EXPECT_NEAR(m.baseColorFactor.g, 0.02f, 1e-6f);
    EXPECT_NEAR(m.baseColorFactor.b, 0.01f, 1e-6f);
    EXPECT_EQ(m.metallicFactor, 0.0f);
    EXPECT_NEAR(m.roughnessFactor, 0.44f, 1e-6f);
    EXPECT_GT(model.primitives.size(), 10u);
}

TEST(Model, BadFilesAreOneLineErrorsNamingTheFile) {
    PBR_NEED_ASSIMP_MODELS(kGltf);
    auto messageOf = [](const fs::path& file) {
        try {
            loadModel(file);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("loaded");
    };
    const std::string missing = messageOf("/nowhere/model.gltf");
    EXPECT_NE(missing.find("model.gltf: no such file"), std::string::npos) << missing;
    const std::string bin = messageOf(kGltf / "MissingBin/BoxTextured.gltf");
    EXPECT_NE(bin.find("BoxTextured.gltf: cannot load"), std::string::npos) << bin;
    EXPECT_NE(bin.find("BoxTextured0.bin"), std::string::npos) << bin;
    const std::string inf = messageOf(kGltf / "BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb");
    EXPECT_NE(inf.find("non-finite position"), std::string::npos) << inf;
    const std::string empty = messageOf(kGltf / "TestNoRootNode/SceneWithoutNodes.gltf");
    EXPECT_NE(empty.find("no meshes to draw"), std::string::npos) << empty;
}

}  // namespace
}  // namespace pbr
