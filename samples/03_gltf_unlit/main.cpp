// 03 gltf_unlit: the cookbook's first glTF step. A glTF 2.0 model loaded through Assimp and drawn
// with KHR_materials_unlit: colour = baseColorFactor x vertex colour x baseColorTexture, turning
// about Y with time. See README.md beside this file.
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "app/app.h"
#include "base/error.h"
#include "base/paths.h"
#include "gltf/model.h"

int main(int argc, char** argv) try {
    pbr::App app(
        argc, argv,
        {.name = "03_gltf_unlit",
         .title = "03 glTF unlit",
         .flags = {pbr::FlagSpec::text(
             "--model", "FILE", "a .gltf or .glb to draw unlit (default: the project's showcase)")},
         .srgbTarget = true});  // linear out of the shader, encoded and blended by the GL

    const pbr::Model model =
        pbr::loadModel(app.flagPath("--model").value_or(pbr::modelDir() / "unlit_showcase.gltf"));
    if (const auto note = pbr::defaultMaterialNote(model)) std::fprintf(stderr, "%s\n", note->c_str());
    const pbr::GpuModel gpuModel(model);
    const pbr::Texture2D white(pbr::Image{1, 1, 3, {255, 255, 255}}, pbr::ColorSpace::Srgb);
    pbr::Shader& shader = app.shader("03_gltf_unlit/unlit.vert", "03_gltf_unlit/unlit.frag");
    shader.set("baseColorTexture", 0);

    // Frame the model from its bounds: centred, scaled into a unit sphere, the camera in front.
    const pbr::Framing framing = pbr::frameBounds(model.boundsMin, model.boundsMax,
                                                  pbr::FlyCamera::kDefaultZoom, app.aspect());
    app.setDefaultCamera(framing.cameraPosition);

    glEnable(GL_DEPTH_TEST);
    while (app.nextFrame()) {
        // Mid grey (sRGB 0.3, byte 76), not the text's white: glTF's default material is white,
        // and a model in it must not vanish into the background. A linear value: the sRGB
        // target encodes the clear colour too.
        glClearColor(0.0723f, 0.0723f, 0.0723f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

        shader.use();
        shader.set("projection", app.projection());
        shader.set("view", app.view());
        const glm::mat4 spin =
            glm::rotate(glm::mat4(1.0f), app.time(), glm::vec3(0.0f, 1.0f, 0.0f));

        // Opaque and masked primitives first, then the blended ones over them.
        for (const bool blendPass : {false, true}) {
            for (const pbr::GpuModel::Primitive& primitive : gpuModel.primitives()) {
                const pbr::Material& material = primitive.material;
                if ((material.alphaMode == pbr::AlphaMode::Blend) != blendPass) continue;
                if (blendPass) {
                    glEnable(GL_BLEND);
                    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                }
                if (material.doubleSided)
                    glDisable(GL_CULL_FACE);
                else
                    glEnable(GL_CULL_FACE);
                shader.set("model", spin * framing.normalize * primitive.transform);
                shader.set("baseColorFactor", material.baseColorFactor);
                shader.set("alphaMode", int(material.alphaMode));
                shader.set("alphaCutoff", material.alphaCutoff);
                const pbr::Texture2D* texture =
                    gpuModel.texture(material.baseColorTexture, pbr::ColorSpace::Srgb);
                (texture ? texture : &white)->bind(0);
                primitive.mesh.draw();
            }
        }
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
    }
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
