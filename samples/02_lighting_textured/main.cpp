// 02 lighting_textured: LearnOpenGL "PBR / Lighting", textured. The 7 x 7 grid again, every
// sphere in the same material from five maps (rusted iron, made by the project), one light.
// See README.md beside this file.
#include "app/app.h"
#include "app/views.h"
#include "base/error.h"
#include "base/paths.h"
#include "gl/mesh.h"
#include "gl/texture.h"
#include "math/sphere_grid.h"

int main(int argc, char** argv) try {
    pbr::App app(
        argc, argv,
        {.name = "02_lighting_textured",
         .title = "02 lighting textured: rusted iron from five maps",
         .cameraPosition = {0.0f, 0.0f, 9.0f},  // 5 x 3 spheres, the maps readable (the grid: 0,0,23)
         .flags = {pbr::FlagSpec::text("--material-dir", "DIR",
                                       "a folder of PBR maps: albedo (or basecolor, diffuse, "
                                       "color), normal, metallic, roughness, optional ao; any "
                                       "prefix, .png or .jpg (default: the baked rusted iron)"),
                   // --tangent-frame and --view are read every frame (live in the panel)
                   pbr::FlagSpec::choice(
                       "--tangent-frame", {"mesh", "derivatives"},
                       "tangents from the sphere (default) or from screen-space derivatives")
                       .asLive(),
                   pbr::FlagSpec::choice("--filter", {"trilinear", "nearest"},
                                         "texture filtering (default trilinear)"),
                   pbr::viewFlag(pbr::kDirectLightViews).asLive()}});
    const std::string filter = app.flagChoice("--filter");

    const pbr::GpuMesh sphere(pbr::uvSphere(64, 64));
    const pbr::PbrTextures material = pbr::loadPbrTextures(
        app.flag("--material-dir").value_or((pbr::materialDir() / "rusted_iron").string()),
        filter == "nearest" ? pbr::TextureFilter::Nearest : pbr::TextureFilter::Trilinear);

    const glm::vec3 lightPosition(0.0f, 0.0f, 10.0f);  // one light in front of the grid
    const pbr::SphereGrid grid{.nrRows = 7, .nrColumns = 7, .spacing = 2.5f};

    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);  // closed meshes, counter-clockwise outside: their backs never show
    while (app.nextFrame()) {
        const pbr::View view = pbr::viewNamed(app.flagChoice("--view"));
        pbr::Shader& shader = app.shader("common/pbr_tangent.vert",
                                         "02_lighting_textured/pbr.frag", pbr::viewDefines(view));

        glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

        shader.use();
        shader.set("projection", app.projection());
        shader.set("view", app.view());
        shader.set("camPos", app.camera().position());
        shader.set("albedoMap", 0);
        shader.set("normalMap", 1);
        shader.set("metallicMap", 2);
        shader.set("roughnessMap", 3);
        shader.set("aoMap", 4);
        shader.set("useDerivativeTangents",
                   app.flagChoice("--tangent-frame") == "derivatives" ? 1 : 0);
        pbr::selectView(shader, view);
        pbr::setPointLights(shader, std::span(&lightPosition, 1), glm::vec3(150.0f, 150.0f, 150.0f));
        material.bind();

        const pbr::Frustum frustum = app.frustum();  // a sphere wholly out of view draws nothing
        for (int row = 0; row < grid.nrRows; ++row) {
            for (int col = 0; col < grid.nrColumns; ++col) {
                if (!frustum.mayContain(grid.position(row, col), 1.0f)) continue;
                shader.setModel(grid.model(row, col));
                sphere.draw();
            }
        }
    }
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
