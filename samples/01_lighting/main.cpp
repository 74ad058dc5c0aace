// 01 lighting: LearnOpenGL "PBR / Lighting". A 7 x 7 grid of spheres under four point lights;
// metallic grows up the rows, roughness across the columns. See README.md beside this file.
#include <algorithm>
#include <array>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "app/app.h"
#include "app/views.h"
#include "base/error.h"
#include "gl/mesh.h"
#include "math/sphere_grid.h"

int main(int argc, char** argv) try {
    // The lesson's knobs, each a flag and, in a window, a control of the live panel: the sample
    // reads them every frame (asLive), so a change shows in the next frame. The first two pick
    // the lights (--lights N, --light K: pbr::gridLightFlags).
    std::vector<pbr::FlagSpec> flags = pbr::gridLightFlags();
    flags.insert(
        flags.end(),
        {pbr::FlagSpec::numbers("--light-color", "R,G,B",
                                "the point lights' radiance, as the text's", 3, 0.0, 1000.0,
                                {300.0, 300.0, 300.0})
             .asLive(),
         pbr::FlagSpec::numbers("--albedo", "R,G,B",
                                "every sphere's albedo, linear (the text's dark red)", 3, 0.0, 1.0,
                                {0.5, 0.0, 0.0})
             .asLive(),
         pbr::FlagSpec::number("--roughness-offset", "D",
                               "add D (-1 to 1) to every sphere's roughness", -1.0, 1.0, 0.0)
             .asLive(),
         pbr::FlagSpec::number("--metallic-offset", "D",
                               "add D (-1 to 1) to every sphere's metallic", -1.0, 1.0, 0.0)
             .asLive(),
         pbr::viewFlag(pbr::kDirectLightViews).asLive(), pbr::viewGainFlag()});
    pbr::App app(argc, argv,
                 {.name = "01_lighting",
                  .title = "01 lighting: Cook-Torrance, 4 point lights",
                  .cameraPosition = {0.0f, 0.0f, 23.0f},  // the whole grid; the text: (0,0,3)
                  .flags = flags});
    const pbr::GpuMesh sphere(pbr::uvSphere(64, 64));
    const pbr::SphereGrid grid{.nrRows = 7, .nrColumns = 7, .spacing = 2.5f};

    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);  // closed meshes, counter-clockwise outside: their backs never show
    while (app.nextFrame()) {
        const float roughnessOffset = app.flagNumber("--roughness-offset");
        const float metallicOffset = app.flagNumber("--metallic-offset");
        const pbr::View view = pbr::viewNamed(app.flagChoice("--view"));
        pbr::Shader& shader =
            app.shader("common/pbr.vert", "01_lighting/pbr.frag", pbr::viewDefines(view));

        glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

        shader.use();
        shader.set("projection", app.projection());
        shader.set("view", app.view());
        shader.set("camPos", app.camera().position());
        // The material (one albedo, ao 1) and the lights.
        shader.set("albedo", app.flagVec3("--albedo"));
        shader.set("ao", 1.0f);
        pbr::selectView(shader, view, app.flagNumber("--gain"));
        const std::span<const glm::vec3> lights = pbr::gridLights(app);
        pbr::setPointLights(shader, lights, app.flagVec3("--light-color"));

        // Metallic rises with the row (bottom row 0), roughness with the column; roughness is
        // kept at 0.05 or above, since a perfectly smooth sphere's point-light highlight vanishes.
        // A sphere wholly out of view is skipped: it would draw nothing.
        const pbr::Frustum frustum = app.frustum();
        for (int row = 0; row < grid.nrRows; ++row) {
            const float metallic = float(row) / float(grid.nrRows) + metallicOffset;
            shader.set("metallic", std::clamp(metallic, 0.0f, 1.0f));
            for (int col = 0; col < grid.nrColumns; ++col) {
                if (!frustum.mayContain(grid.position(row, col), 1.0f)) continue;
                const float roughness = float(col) / float(grid.nrColumns) + roughnessOffset;
                shader.set("roughness", std::clamp(roughness, 0.05f, 1.0f));
                shader.setModel(grid.model(row, col));
                sphere.draw();
            }
        }

        // The lights themselves, as small spheres in the same shader, so their places show.
        for (const glm::vec3& light : lights) {
            shader.setModel(glm::scale(glm::translate(glm::mat4(1.0f), light), glm::vec3(0.5f)));
            sphere.draw();
        }
        // The axes, in a window (and with --panel).
        pbr::labelSphereGrid(app, grid, roughnessOffset, metallicOffset);
    }
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
