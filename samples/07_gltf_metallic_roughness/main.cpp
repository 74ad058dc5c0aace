// 07 gltf_metallic_roughness: the cookbook's "metallic-roughness" recipe (3D Graphics Rendering
// Cookbook, the glTF PBR chapter). A glTF 2.0 model with the whole core material (base colour,
// metallic-roughness, normal, occlusion and emissive maps; alpha modes; double-sided;
// KHR_texture_transform) under image-based light from 05's maps and the file's own
// KHR_lights_punctual lights, seen through an orbit camera and a tone mapper. The program is
// common/gltf/gltf_viewer.cpp (shared with 08); the material is shaders/include/gltf_material.glsl.
// See README.md beside this file.
#include "base/error.h"
#include "base/paths.h"
#include "gltf/gltf_viewer.h"

int main(int argc, char** argv) try {
    return pbr::runGltfViewer(argc, argv,
                              {.name = "07_gltf_metallic_roughness",
                               .title = "07 glTF metallic-roughness",
                               .defaultModel = pbr::modelDir() / "pbr_showcase.gltf",
                               .defaultModelDescription = "the project's PBR showcase",
                               // above the front row, the floor seen from above: the showcase
                               // fills the frame (the bounds' framing left it a third of it)
                               .defaultModelCamera = glm::vec3(0.0f, 2.2f, 5.5f)});
} catch (...) {
    return pbr::reportFailure();
}
