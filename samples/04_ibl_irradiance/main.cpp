// 04 ibl_irradiance: LearnOpenGL "PBR / IBL / Diffuse irradiance". An HDR environment becomes a
// cube map, its irradiance is convolved into a small cube map, and the sphere grid of 01 takes its
// ambient light from it; the environment is drawn behind as a skybox. See README.md beside this
// file.
#include <algorithm>
#include <optional>

#include "app/app.h"
#include "app/views.h"
#include "base/error.h"
#include "gl/mesh.h"
#include "ibl/ibl.h"
#include "ibl/ibl_cache.h"
#include "math/sphere_grid.h"

int main(int argc, char** argv) try {
    std::vector<pbr::FlagSpec> flags = pbr::iblFlags();
    // The parts of the light, and what is seen: read every frame (live in the window's panel).
    for (const pbr::FlagSpec& flag : pbr::iblGridFlags(false)) flags.push_back(flag);
    flags.insert(flags.end(), {pbr::viewFlag(pbr::kIrradianceViews).asLive(), pbr::viewGainFlag()});
    pbr::App app(argc, argv,
                 {.name = "04_ibl_irradiance",
                  .title = "04 IBL: diffuse irradiance",
                  .cameraPosition = {0.0f, 0.0f, 21.0f},  // 23 from the grid at z = -2
                  .flags = flags});

    // Precompute (or load from the cache): the environment cube (512^2, mipmapped) and its
    // irradiance (32^2). Again after R: the cache's keys hold the shaders' code, so an edited
    // irradiance.frag is computed anew, and an undone edit finds its maps in the cache.
    pbr::IblCache cache(pbr::cacheDir(app.options()));
    std::optional<pbr::IblEnvironment> environment;
    std::optional<pbr::TextureCube> irradianceMap;
    const auto precompute = [&] {
        environment.emplace(cache, pbr::environmentFile(app.options()));
        environment->environmentMap();
        irradianceMap.emplace(environment->irradianceMap(32));
    };
    precompute();
    app.addPrecomputeSeconds(cache.computeSeconds());

    pbr::Skybox skybox;
    const pbr::GpuMesh sphere(pbr::uvSphere(64, 64));
    const pbr::SphereGrid grid{.nrRows = 7, .nrColumns = 7, .spacing = 2.5f, .z = -2.0f};

    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);  // closed meshes, counter-clockwise outside: their backs never show
    while (app.nextFrame()) {
        if (app.shadersReloaded()) precompute();  // (the passes give back the frame's target)
        const pbr::TextureCube& environmentMap = environment->environmentMap();
        const pbr::View view = pbr::viewNamed(app.flagChoice("--view"));
        pbr::Shader& shader =
            app.shader("common/pbr.vert", "04_ibl_irradiance/pbr.frag", pbr::viewDefines(view));

        app.clearFrame(view, {0.2f, 0.3f, 0.3f});  // the picture's: hidden by its sky

        shader.use();
        shader.set("projection", app.projection());
        shader.set("view", app.view());
        shader.set("camPos", app.camera().position());
        shader.set("albedo", glm::vec3(0.5f, 0.0f, 0.0f));
        shader.set("ao", 1.0f);
        shader.set("irradianceMap", 0);
        shader.set("noIbl", app.options().has("--no-ibl") ? 1 : 0);
        pbr::selectView(shader, view, app.flagNumber("--gain"));
        pbr::setPointLights(shader, pbr::gridLights(app), glm::vec3(300.0f));
        irradianceMap->bind(0);
        const pbr::Frustum frustum = app.frustum();  // a sphere wholly out of view draws nothing
        for (int row = 0; row < grid.nrRows; ++row) {
            shader.set("metallic", float(row) / float(grid.nrRows));
            for (int col = 0; col < grid.nrColumns; ++col) {
                if (!frustum.mayContain(grid.position(row, col), 1.0f)) continue;
                shader.set("roughness",
                           std::clamp(float(col) / float(grid.nrColumns), 0.05f, 1.0f));
                shader.setModel(grid.model(row, col));
                sphere.draw();
            }
        }

        pbr::labelSphereGrid(app, grid);  // the axes, in a window (and with --panel)

        // Last, the picture's sky: only where nothing is (a view stays on its grey).
        const bool irradianceSky = app.flagChoice("--background") == "irradiance";
        if (view == pbr::View::Final)
            skybox.draw(irradianceSky ? *irradianceMap : environmentMap, app.view(),
                        app.projection());
    }
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
