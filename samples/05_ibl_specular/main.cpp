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
#include "ibl/ibl.h"
#include "ibl/ibl_cache.h"
#include "math/sphere_grid.h"

namespace {
// The --textured row, left to right, in the text's order.
constexpr std::array<const char*, 5> kMaterials = {"rusted_iron", "gold", "grass", "plastic",
                                                   "wall"};
}  // namespace

int main(int argc, char** argv) try {
    std::vector<pbr::FlagSpec> flags = pbr::iblFlags();
    flags.push_back(
        pbr::FlagSpec::toggle("--textured", "five spheres in the project's material sets"));
    // The ambient term's form, the parts of the light, and what is seen: read every frame (live
    // in the window's panel).
    flags.push_back(pbr::FlagSpec::choice(
        "--split-sum", {"text", "exact"},
        "the ambient term: the text's (F times the LUT's scale; default) or the split sum as its "
        "derivation has it (F0 times the scale, diffuse weighted by what the lobe leaves)").asLive());
    for (const pbr::FlagSpec& flag : pbr::gridLightFlags()) flags.push_back(flag);
    flags.push_back(
        pbr::FlagSpec::toggle("--no-ibl", "leave out the image-based light").asLive());
    flags.push_back(pbr::FlagSpec::choice(
        "--background", {"environment", "irradiance", "prefiltered"},
        "what the sky shows: the environment (default), its irradiance, or the prefiltered "
        "map at --background-lod").asLive());
    flags.push_back(pbr::FlagSpec::number(
        "--background-lod", "L",
        "the sky's mip level: of the prefiltered map, roughness L / 4; of the environment, its "
        "box-filtered mips", 0.0, 4.0, 0.0).asLive());
    flags.push_back(pbr::viewFlag(pbr::kSplitSumViews).asLive());
    pbr::App app(argc, argv,
                 {.name = "05_ibl_specular",
                  .title = "05 IBL: specular",
                  .cameraPosition = {0.0f, 0.0f, 21.0f},  // 23 from the grid at z = -2
                  .flags = flags});
    const bool textured = app.options().has("--textured");
    if (textured) app.setDefaultCamera({0.0f, 0.0f, 8.0f});  // the row of five, 10 away

    // Precompute (or load from the cache): environment 512^2, irradiance 32^2, prefiltered
    // specular 128^2 with 5 mips (roughness = mip / 4) from pbr::kPrefilterSamples (256) samples
    // a texel, the sun summed apart (see README.md), and the BRDF LUT 512^2 RG16F from 1024.
    // Again after R: the cache's keys hold the shaders' code, so an edited prefilter.frag (or
    // irradiance.frag, brdf_lut.frag) is computed anew.
    pbr::IblCache cache(pbr::cacheDir(app.options()));
    std::optional<pbr::IblEnvironment> environment;
    std::optional<pbr::TextureCube> irradianceMap, prefilterMap;
    std::optional<pbr::Texture2D> brdfLUT;
    const auto precompute = [&] {
        environment.emplace(cache, pbr::environmentFile(app.options()));
        environment->environmentMap();
        irradianceMap.emplace(environment->irradianceMap(32));
        prefilterMap.emplace(environment->prefilteredMap(128, 5, pbr::kPrefilterSamples));
        brdfLUT.emplace(pbr::brdfLut(cache, 512, 1024, pbr::BrdfLutChannels::ScaleBias));
    };
    precompute();
    app.addPrecomputeSeconds(cache.computeSeconds());

    pbr::Skybox skybox;
    const pbr::GpuMesh sphere(pbr::uvSphere(64, 64));
    std::vector<pbr::PbrTextures> materials;
    if (textured) {
        for (const char* name : kMaterials) {
            materials.push_back(pbr::loadPbrTextures(pbr::materialDir() / name));
        }
    }
    const pbr::SphereGrid grid{.nrRows = 7, .nrColumns = 7, .spacing = 2.5f, .z = -2.0f};
    const pbr::SphereGrid row{.nrRows = 1, .nrColumns = 5, .spacing = 2.5f, .z = -2.0f};

    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);  // closed meshes, counter-clockwise outside: their backs never show
    while (app.nextFrame()) {
        if (app.shadersReloaded()) precompute();  // (the passes give back the frame's target)
        const pbr::TextureCube& environmentMap = environment->environmentMap();
        const pbr::View view = pbr::viewNamed(app.flagChoice("--view"));
        pbr::Shader& shader = textured ? app.shader("common/pbr_tangent.vert",
                                                    "05_ibl_specular/pbr_textured.frag",
                                                    pbr::viewDefines(view))
                                       : app.shader("common/pbr.vert", "05_ibl_specular/pbr.frag",
                                                    pbr::viewDefines(view));

        glClearColor(0.2f, 0.3f, 0.3f, 1.0f);  // hidden by the skybox wherever it is drawn
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

        shader.use();
        shader.set("projection", app.projection());
        shader.set("view", app.view());
        shader.set("camPos", app.camera().position());
        if (textured) {
            shader.set("albedoMap", 0);
            shader.set("normalMap", 1);
            shader.set("metallicMap", 2);
            shader.set("roughnessMap", 3);
            shader.set("aoMap", 4);
        } else {
            shader.set("albedo", glm::vec3(0.5f, 0.0f, 0.0f));
            shader.set("ao", 1.0f);
        }
        // Units 5-7 hold the split-sum maps: the materials take 0-4.
        pbr::useIblMaps(shader, environmentMap, *irradianceMap, *prefilterMap, *brdfLUT, 5);
        shader.set("exactSplitSum", app.flagChoice("--split-sum") == "exact" ? 1 : 0);
        shader.set("noIbl", app.options().has("--no-ibl") ? 1 : 0);
        pbr::selectView(shader, view);
        pbr::setPointLights(shader, pbr::gridLights(app),
                            glm::vec3(300.0f));
        const pbr::Frustum frustum = app.frustum();  // a sphere wholly out of view draws nothing
        if (textured) {
            for (int col = 0; col < row.nrColumns; ++col) {
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
        }
        // In a window (and with --panel): the grid's axes, or the material sets' names.
        if (textured) {
            for (int col = 0; col < row.nrColumns; ++col) {
                app.label(row.position(0, col) - glm::vec3(0.0f, 1.4f, 0.0f), kMaterials[size_t(col)]);
            }
        } else {
            pbr::labelSphereGrid(app, grid);
        }

        // Last: only where nothing is.
        const std::string background = app.flagChoice("--background");
        const pbr::TextureCube& sky = background == "irradiance"    ? *irradianceMap
                                      : background == "prefiltered" ? *prefilterMap
                                                                    : environmentMap;
        skybox.draw(sky, app.view(), app.projection(), app.flagNumber("--background-lod"));
    }
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
