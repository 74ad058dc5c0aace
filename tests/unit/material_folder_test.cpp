// Which file of a material folder is which map (common/files/material_folder.h), under the names
// the texture sets people download use. The expected maps are read off the naming schemes of those
// sets (freepbr, ambientCG, Poly Haven), not off the code.
#include <gtest/gtest.h>

#include <fstream>

#include "base/error.h"
#include "files/material_folder.h"
#include "support/process.h"

namespace pbr {
namespace {

namespace fs = std::filesystem;

TEST(MaterialFolder, NamesOfRealSets) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"albedo.png", "albedo"},
        {"rustediron2_basecolor.png", "albedo"},
        {"Bricks076C_1K-JPG_Color.jpg", "albedo"},
        {"brick_wall_001_diff_4k.jpg", "albedo"},
        {"Metal_Base_Color.PNG", "albedo"},
        {"wood-diffuse.jpeg", "albedo"},
        {"normal.png", "normal"},
        {"Bricks076C_1K-JPG_NormalGL.jpg", "normal"},
        {"brick_wall_001_nor_gl_4k.jpg", "normal"},
        {"slate_normal-ogl.png", "normal"},
        {"Bricks076C_1K-JPG_NormalDX.jpg", "normal-directx"},
        {"brick_wall_001_nor_dx_4k.jpg", "normal-directx"},
        {"slate_normal-dx.png", "normal-directx"},
        {"rustediron2_metallic.png", "metallic"},
        {"Bricks076C_1K-JPG_Metalness.jpg", "metallic"},
        {"brick_wall_001_metal_4k.png", "metallic"},
        {"ROUGHNESS.PNG", "roughness"},
        {"brick_wall_001_rough_2k.jpg", "roughness"},
        {"ao.jpg", "ao"},
        {"Bricks076C_1K-JPG_AmbientOcclusion.jpg", "ao"},
        {"stone_occlusion.png", "ao"},
        {"stone ambient_occlusion.png", "ao"},
    };
    for (const auto& [file, map] : cases) {
        const auto found = materialMapOf(file);
        ASSERT_TRUE(found) << file;
        EXPECT_EQ(*found, map) << file;
    }
}

TEST(MaterialFolder, NotMaps) {
    for (const char* file :
         {"albedo.tga", "albedo.png.txt", "readme.md", "Bricks076C_1K-JPG_Displacement.jpg",
          "height.png", "preview.jpg", "brick_wall_001_arm_4k.jpg", "metallic_roughness.png",
          "MetallicRoughness.png", "orm.png", "coloring.png", "bigcolor.png", "nonmetallic.png",
          "abnormal.png", "cardiao.png", "4k.png"}) {
        EXPECT_FALSE(materialMapOf(file)) << file << " taken for " << *materialMapOf(file);
    }
}

// A folder of empty files named as listed.
fs::path folderWith(const std::string& name, const std::vector<std::string>& files) {
    const fs::path dir = test::testOutputDir("material_folder_" + name);
    for (const std::string& file : files) std::ofstream(dir / file).close();
    return dir;
}

std::string folderErrorOf(const fs::path& dir) {
    try {
        findMaterialFiles(dir);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(MaterialFolder, AmbientCgFolder) {
    const fs::path dir = folderWith(
        "ambientcg", {"Bricks_1K_Color.jpg", "Bricks_1K_NormalGL.jpg", "Bricks_1K_NormalDX.jpg",
                      "Bricks_1K_Roughness.jpg", "Bricks_1K_Metalness.jpg",
                      "Bricks_1K_Displacement.jpg", "Bricks.png"});
    const MaterialFiles files = findMaterialFiles(dir);
    EXPECT_EQ(files.albedo.filename(), "Bricks_1K_Color.jpg");
    EXPECT_EQ(files.normal.filename(), "Bricks_1K_NormalGL.jpg");  // GL wins over DX
    EXPECT_EQ(files.normalConvention, NormalConvention::OpenGL);
    EXPECT_EQ(files.metallic.filename(), "Bricks_1K_Metalness.jpg");
    EXPECT_EQ(files.roughness.filename(), "Bricks_1K_Roughness.jpg");
    EXPECT_FALSE(files.ao);
}

TEST(MaterialFolder, DirectXAlone) {
    const MaterialFiles files =
        findMaterialFiles(folderWith("directx", {"a_albedo.png", "a_normal_dx.png",
                                                 "a_metallic.png", "a_roughness.png", "a_ao.png"}));
    EXPECT_EQ(files.normal.filename(), "a_normal_dx.png");
    EXPECT_EQ(files.normalConvention, NormalConvention::DirectX);
    ASSERT_TRUE(files.ao);
    EXPECT_EQ(files.ao->filename(), "a_ao.png");
}

TEST(MaterialFolder, ProblemsAreOneLineEach) {
    const std::string twoAlbedos =
        folderErrorOf(folderWith("two_albedos", {"albedo.png", "BaseColor.jpg", "normal.png",
                                           "metallic.png", "roughness.png"}));
    EXPECT_NE(twoAlbedos.find(": 2 files for the albedo map (BaseColor.jpg and albedo.png); "
                              "keep one"),
              std::string::npos)
        << twoAlbedos;
    const std::string noRoughness =
        folderErrorOf(folderWith("no_roughness", {"albedo.png", "normal.png", "metallic.png"}));
    EXPECT_NE(noRoughness.find(": missing the roughness map (a .png or .jpg named roughness or "
                               "rough, after any prefix)"),
              std::string::npos)
        << noRoughness;
    const std::string noNormal =
        folderErrorOf(folderWith("no_normal", {"albedo.png", "roughness.png", "metallic.png"}));
    EXPECT_NE(noNormal.find("missing the normal map"), std::string::npos) << noNormal;
    EXPECT_NE(folderErrorOf(test::testOutputDir("material_folder_none") / "nowhere")
                  .find("nowhere: no such folder"),
              std::string::npos);
}

}  // namespace
}  // namespace pbr
