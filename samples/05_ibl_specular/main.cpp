// 05 ibl_specular: LearnOpenGL "PBR / IBL / Specular IBL". The split-sum approximation: the
// environment prefiltered for each roughness (one mip level each) and the BRDF lookup table join
// 04's irradiance, so the grid's spheres reflect their surroundings. --textured shows the
// project's five material sets instead. See README.md beside this file.
#include <algorithm>
#include <array>
#include <optional>

#include "app/app.h"
#include "app/views.h"
#include "base/error.h"
#include "base/paths.h"
#include "gl/mesh.h"
#include "gl/texture.h"
#include "ibl/ibl_cache.h"
#include "math/sphere_grid.h"

// The --textured row, left to right, in the text's order.
constexpr std::array<const char*, 5> kMaterials = {"rusted_iron", "gold", "grass", "plastic",
                                                   "wall"};

int main(int argc, char** argv) try {
    std::vector<pbr::FlagSpec> flags = pbr::iblFlags();
    flags.push_back(
        pbr::FlagSpec::toggle("--textured", "five spheres in the project's material sets"));
    // The ambient term's form (--split-sum), the parts of the light, and what is seen: read every
    // frame (live in the window's panel).
    for (const pbr::FlagSpec& flag : pbr::iblGridFlags(true)) flags.push_back(flag);
    flags.insert(flags.end(), {pbr::viewFlag(pbr::kSplitSumViews).asLive(), pbr::viewGainFlag()});
    pbr::App app(argc, argv,
                 {.name = "05_ibl_specular",
                  .title = "05 IBL: specular",
                  .cameraPosition = {0.0f, 0.0f, 21.0f},  // 23 from the grid at z = -2
                  .flags = flags});
    const bool textured = app.options().has("--textured");
    if (textured) app.setDefaultCamera({0.0f, 0.0f, 8.0f});  // the row of five, 10 away

    // Precompute (or load from the cache) the text's maps (pbr::SplitSumMaps); again after R, as
    // the cache's keys hold the shaders' code: an edited prefilter.frag is computed anew.
    pbr::IblCache cache(pbr::cacheDir(app.options()));
    std::optional<pbr::SplitSumMaps> maps;
    const auto precompute = [&] { maps.emplace(cache, pbr::environmentFile(app.options())); };
    precompute();
    app.addPrecomputeSeconds(cache.computeSeconds());

    pbr::Skybox skybox;
    const pbr::GpuMesh sphere(pbr::uvSphere(64, 64));
    std::vector<pbr::PbrTextures> materials;  // --textured's sets
    for (const char* name : kMaterials) {
        if (textured) materials.push_back(pbr::loadPbrTextures(pbr::materialDir() / name));
    }
    const pbr::SphereGrid grid{.nrRows = 7, .nrColumns = 7, .spacing = 2.5f, .z = -2.0f};
    const pbr::SphereGrid row{.nrRows = 1, .nrColumns = 5, .spacing = 2.5f, .z = -2.0f};

    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);  // closed meshes, counter-clockwise outside: their backs never show
    while (app.nextFrame()) {
        if (app.shadersReloaded()) precompute();  // (the passes give back the frame's target)
        const pbr::View view = pbr::viewNamed(app.flagChoice("--view"));
        pbr::Shader& shader =
            app.shader(textured ? "common/pbr_tangent.vert" : "common/pbr.vert",
                       textured ? "05_ibl_specular/pbr_textured.frag" : "05_ibl_specular/pbr.frag",
                       pbr::viewDefines(view));

        app.clearFrame(view, {0.2f, 0.3f, 0.3f});  // the picture's: hidden by its sky

        shader.use();
        shader.set("projection", app.projection());
        shader.set("view", app.view());
        shader.set("camPos", app.camera().position());
        if (textured) {
            pbr::PbrTextures::setSamplers(shader);
        } else {
            shader.set("albedo", glm::vec3(0.5f, 0.0f, 0.0f));
            shader.set("ao", 1.0f);
        }
        // Units 5-7 hold the split-sum maps: the materials take 0-4.
        maps->use(shader, 5);
        shader.set("exactSplitSum", app.flagChoice("--split-sum") == "exact" ? 1 : 0);
        shader.set("noIbl", app.options().has("--no-ibl") ? 1 : 0);
        pbr::selectView(shader, view, app.flagNumber("--gain"));
        pbr::setPointLights(shader, pbr::gridLights(app), glm::vec3(300.0f));
        const pbr::Frustum frustum = app.frustum();  // a sphere wholly out of view draws nothing
        // In a window (and with --panel) each set's name under it, or the grid's axes.
        if (textured) {
            for (int col = 0; col < row.nrColumns; ++col) {
                app.label(row.position(0, col) - glm::vec3(0.0f, 1.4f, 0.0f),
                          kMaterials[size_t(col)]);
                if (!frustum.mayContain(row.position(0, col), 1.0f)) continue;
                materials[size_t(col)].bind();
                shader.setModel(row.model(0, col));
                sphere.draw();
            }
        } else {
            for (int r = 0; r < grid.nrRows; ++r) {
                shader.set("metallic", float(r) / float(grid.nrRows));
                for (int col = 0; col < grid.nrColumns; ++col) {
                    if (!frustum.mayContain(grid.position(r, col), 1.0f)) continue;
                    shader.set("roughness",
                               std::clamp(float(col) / float(grid.nrColumns), 0.05f, 1.0f));
                    shader.setModel(grid.model(r, col));
                    sphere.draw();
                }
            }
            pbr::labelSphereGrid(app, grid);
        }
        // Last, the picture's sky: only where nothing is (a view stays on its grey).
        const std::string background = app.flagChoice("--background");
        const pbr::TextureCube& sky = background == "irradiance" ? maps->irradiance
                                      : background == "prefiltered"
                                          ? maps->prefiltered
                                          : maps->environment.environmentMap();
        if (view == pbr::View::Final)
            skybox.draw(sky, app.view(), app.projection(), app.flagNumber("--background-lod"));
    }
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
