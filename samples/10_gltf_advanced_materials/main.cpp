// 10 gltf_advanced_materials: the cookbook's chapter after the glTF PBR one, "Advanced PBR
// extensions" (3D Graphics Rendering Cookbook, second edition): 07's viewer with the layers the
// Khronos material extensions add over the core material, each as its specification has it
// (shaders/include/gltf_extensions.glsl): a clear coat (KHR_materials_clearcoat), a sheen
// (KHR_materials_sheen), the dielectric's reflectance from its index of refraction and a specular
// layer (KHR_materials_ior, KHR_materials_specular), and emission past 1
// (KHR_materials_emissive_strength). The program is common/gltf/gltf_viewer.cpp (shared with 07
// and 08). See README.md beside this file.
#include "base/error.h"
#include "base/paths.h"
#include "gltf/gltf_viewer.h"

int main(int argc, char** argv) try {
    return pbr::runGltfViewer(
        argc, argv,
        {.name = "10_gltf_advanced_materials",
         .title = "10 glTF advanced materials",
         .defaultModel = pbr::modelDir() / "advanced_materials.gltf",
         .defaultModelDescription = "the project's advanced materials showcase",
         // a row a layer, named at its left end
         .defaultModelLabels = {{{-0.04f, 0.9f, 0.5f}, "clear coat"},
                                {{-0.04f, 0.7f, 0.5f}, "sheen"},
                                {{-0.04f, 0.5f, 0.5f}, "specular"},
                                {{-0.04f, 0.3f, 0.5f}, "ior"},
                                {{-0.04f, 0.1f, 0.5f}, "emissive strength"}},
         // in front of the grid's middle: the five rows fill the frame's height
         .defaultModelCamera = glm::vec3(0.0f, 2.5f, 7.2f),
         .extensions = true});
} catch (...) {
    return pbr::reportFailure();
}
