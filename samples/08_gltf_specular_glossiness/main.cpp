// 08 gltf_specular_glossiness: the cookbook's "specular-glossiness" recipe (3D Graphics Rendering
// Cookbook, the glTF PBR chapter). KHR_materials_pbrSpecularGlossiness, glTF's older workflow,
// converted into the one material description of 07 (F0 = specular, roughness = 1 - glossiness,
// c_diff = diffuse x (1 - max(specular))) and drawn by the same program:
// common/gltf/gltf_viewer.cpp, shaders/include/gltf_material.glsl. The default asset shows the same
// spheres in both workflows side by side. See README.md beside this file.
#include "base/error.h"
#include "base/paths.h"
#include "gltf/gltf_viewer.h"

int main(int argc, char** argv) try {
    return pbr::runGltfViewer(
        argc, argv,
        {.name = "08_gltf_specular_glossiness",
         .title = "08 glTF specular-glossiness",
         .defaultModel = pbr::modelDir() / "pbr_workflows.gltf",
         .defaultModelDescription = "the project's two-workflow spheres",
         .defaultModelLabels = {{{0.25f, 1.12f, 0.5f}, "metallic-roughness"},
                                {{0.75f, 1.12f, 0.5f}, "specular-glossiness"}}});
} catch (...) {
    return pbr::reportFailure();
}
