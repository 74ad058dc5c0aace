// 10 gltf_advanced_materials: the cookbook's chapter after the glTF PBR one, "Advanced PBR
// extensions" (3D Graphics Rendering Cookbook, second edition): 07's viewer with the layers the
// Khronos material extensions add over the core material, each as its specification has it
// (shaders/include/gltf_extensions.glsl): a clear coat (KHR_materials_clearcoat), a sheen
// (KHR_materials_sheen), light through the surface and a volume behind it
// (KHR_materials_transmission, KHR_materials_volume), the dielectric's reflectance from its index
// of refraction and a specular layer (KHR_materials_ior, KHR_materials_specular), and emission
// past 1 (KHR_materials_emissive_strength). The program is common/gltf/gltf_viewer.cpp (shared with
// 07 and 08). See README.md beside this file.
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
         // a row a layer, named at its left end (the bounds: the backdrop behind the glass
         // rows, x -2.75 .. 2.75, y -2.1 .. 4.9, z -1.25 .. 0.4; the spheres at z = 0)
         .defaultModelLabels = {{{-0.04f, 0.943f, 0.76f}, "clear coat"},
                                {{-0.04f, 0.8f, 0.76f}, "sheen"},
                                {{-0.04f, 0.657f, 0.76f}, "specular"},
                                {{-0.04f, 0.514f, 0.76f}, "ior"},
                                {{-0.04f, 0.371f, 0.76f}, "emissive strength"},
                                {{-0.04f, 0.229f, 0.76f}, "transmission"},
                                {{-0.04f, 0.086f, 0.76f}, "volume"}},
         // in front of the grid's middle: the seven rows fill the frame's height
         .defaultModelCamera = glm::vec3(0.0f, 1.4f, 9.3f),
         .extensions = true});
} catch (...) {
    return pbr::reportFailure();
}
