// 09 light_types: the Overload engine's standard PBR shader and its five light types (point,
// directional, spot, ambient box, ambient sphere), fed from one buffer: every light a mat4
// (common/math/light_block.h), all of them in one std140 uniform block the fragment shader loops
// over (shaders/include/light_types.glsl). A floor and a row of spheres in the project's material
// sets (scene.h), with the engine's material inputs (texture tiling and offset, an albedo tint).
// See README.md beside this file.
#include <map>
#include <string>
#include <vector>

#include "app/app.h"
#include "app/views.h"
#include "base/error.h"
#include "base/paths.h"
#include "gl/light_buffer.h"
#include "gl/mesh.h"
#include "gl/texture.h"
#include "scene.h"

int main(int argc, char** argv) try {
    pbr::App app(argc, argv,
                 {.name = "09_light_types",
                  .title = "09 light types: point, directional, spot, ambient box, ambient sphere",
                  .cameraPosition = {0.0f, 5.5f, 12.0f},
                  .cameraPitch = -22.0f,
                  .flags = light_types::flags()});
    const bool untextured = app.options().has("--untextured");

    const std::vector<light_types::Object> objects = light_types::objects();
    std::map<std::string, pbr::PbrTextures> sets;  // each material set loaded once
    for (const light_types::Object& object : objects) {
        if (!untextured && !sets.contains(object.materialSet))
            sets.emplace(object.materialSet,
                         pbr::loadPbrTextures(pbr::materialDir() / object.materialSet));
    }
    const pbr::GpuMesh sphere(pbr::uvSphere(64, 32));
    const pbr::GpuMesh floorMesh(pbr::quad());

    pbr::LightBuffer lightBuffer;
    std::vector<pbr::PackedLight> uploaded;  // what the buffer holds

    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);  // closed meshes, counter-clockwise outside: their backs never show
    while (app.nextFrame()) {
        const std::string only = app.flagChoice("--only");
        const pbr::View view = pbr::viewNamed(app.flagChoice("--view"));
        pbr::Shader& shader = app.shader("common/pbr_tangent.vert",
                                         "09_light_types/light_types.frag", pbr::viewDefines(view));
        // The scene's lights of the kinds asked for, and the moving ones where they are now.
        const glm::vec3 terms = app.flagVec3("--attenuation");
        const pbr::Attenuation attenuation{terms.x, terms.y, terms.z};
        std::vector<pbr::PackedLight> lights;
        for (const pbr::PackedLight& light : light_types::sceneLights(attenuation)) {
            if (only == "all" || pbr::kLightTypeNames[int(light.type())] == only)
                lights.push_back(light);
        }
        const auto moving = light_types::movingLights(app.flagInt("--point-lights"), app.time());
        lights.insert(lights.end(), moving.begin(), moving.end());
        if (lights != uploaded ||
            app.frameIndex() == 0) {  // a change in the panel, or a moving light
            lightBuffer.upload(lights);
            uploaded = lights;
        }

        glClearColor(0.02f, 0.02f, 0.03f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        shader.use();
        pbr::LightBuffer::attach(shader.id());
        pbr::PbrTextures::setSamplers(shader);
        shader.set("useDerivativeTangents", 0);
        shader.set("untextured", untextured ? 1 : 0);
        pbr::selectView(shader, view, app.flagNumber("--gain"));
        shader.set("projection", app.projection());
        shader.set("view", app.view());
        shader.set("camPos", app.camera().position());
        for (const light_types::Object& object : objects) {
            if (!untextured) sets.at(object.materialSet).bind();
            shader.set("textureTiling", object.tiling);
            shader.set("textureOffset", object.offset);
            shader.set("albedoTint", untextured && object.floor ? glm::vec4(0.8f, 0.8f, 0.8f, 1.0f)
                                                                : object.tint);
            shader.set("metallicFactor", untextured ? object.plainMetallic : object.metallic);
            shader.set("roughnessFactor", untextured ? object.plainRoughness : object.roughness);
            shader.setModel(object.model);
            (object.floor ? floorMesh : sphere).draw();
        }
    }
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
