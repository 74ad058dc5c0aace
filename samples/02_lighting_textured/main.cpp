// 02 lighting_textured: LearnOpenGL "PBR / Lighting", textured. The 7 x 7 grid again, every
// sphere in the same material from five maps (rusted iron, made by the project), one light.
// See README.md beside this file.
#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "app/app.h"
#include "app/views.h"
#include "base/error.h"
#include "base/paths.h"
#include "gl/mesh.h"
#include "gl/texture.h"
#include "math/sphere_grid.h"

namespace {
// The project's material sets (--material), and the five maps in the order of their texture
// units: each one's sampler, and the switch that leaves it out (the shaders' NO_..._MAP defines,
// material_maps.glsl).
const std::vector<std::string> kMaterialSets = {"rusted_iron", "gold", "grass", "plastic", "wall"};
struct MapSwitch {
    const char *sampler, *flag, *define;
};
constexpr std::array<MapSwitch, 5> kMaps = {{
    {"albedoMap", "--no-albedo-map", "NO_ALBEDO_MAP"},
    {"normalMap", "--no-normal-map", "NO_NORMAL_MAP"},
    {"metallicMap", "--no-metallic-map", "NO_METALLIC_MAP"},
    {"roughnessMap", "--no-roughness-map", "NO_ROUGHNESS_MAP"},
    {"aoMap", "--no-ao-map", "NO_AO_MAP"},
}};
}  // namespace

int main(int argc, char** argv) try {
    std::vector<pbr::FlagSpec> flags = {
        pbr::FlagSpec::text("--material-dir", "DIR",
                            "a folder of PBR maps: albedo (or basecolor, diffuse, color), normal, "
                            "metallic, roughness, optional ao; any prefix, .png or .jpg (default: "
                            "the project's set --material names)"),
        // the rest are read every frame (live in the panel)
        pbr::FlagSpec::choice("--material", kMaterialSets,
                              "which of the project's material sets (default rusted_iron; "
                              "--material-dir wins)")
            .asLive(),
        pbr::FlagSpec::choice("--tangent-frame", {"mesh", "derivatives"},
                              "tangents from the sphere (default) or from screen-space derivatives")
            .asLive(),
        pbr::FlagSpec::choice("--filter", {"trilinear", "nearest"},
                              "texture filtering (default trilinear)"),
        pbr::viewFlag(pbr::kDirectLightViews).asLive(), pbr::viewGainFlag()};
    flags.push_back(
        pbr::FlagSpec::toggle("--no-albedo-map", "mid grey instead of the albedo map").asLive());
    flags.push_back(
        pbr::FlagSpec::toggle("--no-normal-map", "the mesh's own normal instead of the normal map")
            .asLive());
    flags.push_back(
        pbr::FlagSpec::toggle("--no-metallic-map", "metallic 0 instead of the metallic map")
            .asLive());
    flags.push_back(
        pbr::FlagSpec::toggle("--no-roughness-map", "roughness 0.5 instead of the roughness map")
            .asLive());
    flags.push_back(pbr::FlagSpec::toggle("--no-ao-map", "ao 1 instead of the ao map").asLive());
    pbr::App app(argc, argv,
                 {.name = "02_lighting_textured",
                  .title = "02 lighting textured: rusted iron from five maps",
                  // 5 x 3 spheres, the maps readable (the whole grid: 0,0,23)
                  .cameraPosition = {0.0f, 0.0f, 9.0f},
                  .flags = flags});
    const pbr::TextureFilter filter = app.flagChoice("--filter") == "nearest"
                                          ? pbr::TextureFilter::Nearest
                                          : pbr::TextureFilter::Trilinear;

    const pbr::GpuMesh sphere(pbr::uvSphere(64, 64));
    // The material: --material-dir's folder, read at start-up; else the set --material names,
    // each read the first time it is shown.
    std::map<std::filesystem::path, pbr::PbrTextures> materials;
    const auto materialFolder = [&] {
        return app.flagPath("--material-dir")
            .value_or(pbr::materialDir() / app.flagChoice("--material"));
    };
    materials.emplace(materialFolder(), pbr::loadPbrTextures(materialFolder(), filter));

    const glm::vec3 lightPosition(0.0f, 0.0f, 10.0f);  // one light in front of the grid
    const pbr::SphereGrid grid{.nrRows = 7, .nrColumns = 7, .spacing = 2.5f};

    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);  // closed meshes, counter-clockwise outside: their backs never show
    while (app.nextFrame()) {
        const pbr::View view = pbr::viewNamed(app.flagChoice("--view"));
        std::vector<std::string> defines = pbr::viewDefines(view);
        for (const MapSwitch& map : kMaps) {
            if (app.options().has(map.flag)) defines.push_back(map.define);
        }
        pbr::Shader& shader =
            app.shader("common/pbr_tangent.vert", "02_lighting_textured/pbr.frag", defines);
        const std::filesystem::path folder = materialFolder();
        if (!materials.contains(folder)) {
            materials.emplace(folder, pbr::loadPbrTextures(folder, filter));
        }
        const pbr::PbrTextures& material = materials.at(folder);

        glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

        shader.use();
        shader.set("projection", app.projection());
        shader.set("view", app.view());
        shader.set("camPos", app.camera().position());
        for (size_t unit = 0; unit < kMaps.size(); ++unit) {  // (a map left out has no sampler)
            if (!app.options().has(kMaps[unit].flag)) shader.set(kMaps[unit].sampler, int(unit));
        }
        shader.set("useDerivativeTangents",
                   app.flagChoice("--tangent-frame") == "derivatives" ? 1 : 0);
        pbr::selectView(shader, view, app.flagNumber("--gain"));
        pbr::setPointLights(shader, std::span(&lightPosition, 1), glm::vec3(150.0f));
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
