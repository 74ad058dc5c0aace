#include "gltf/gltf_viewer.h"

#include <cstdio>
#include <algorithm>
#include <optional>
#include <span>
#include <vector>

#include "app/app.h"
#include "app/views.h"
#include "base/paths.h"
#include "gltf/gltf_renderer.h"
#include "gltf/model.h"
#include "ibl/ibl.h"
#include "ibl/ibl_cache.h"
#include "math/tonemap.h"

namespace pbr {

namespace {

// The glTF extensions the shading path draws; any other a file lists gets a line on stderr.
const std::vector<std::string> kDrawnExtensions = {"KHR_lights_punctual", "KHR_texture_transform",
                                                   "KHR_materials_unlit",
                                                   "KHR_materials_pbrSpecularGlossiness"};
// and those the advanced material's layers add (sample 10)
const std::vector<std::string> kLayerExtensions = {
    "KHR_materials_clearcoat", "KHR_materials_sheen", "KHR_materials_ior",
    "KHR_materials_specular", "KHR_materials_emissive_strength", "KHR_materials_transmission",
    "KHR_materials_volume"};

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

// What a learner should hear about a file before its picture: what it asks for that is not
// drawn, and what stands in for what it lacks.
void describe(const Model& model, bool punctual, bool extensions) {
    const std::string file = displayPath(model.file);
    std::vector<std::string> drawn = kDrawnExtensions;
    if (extensions) drawn.insert(drawn.end(), kLayerExtensions.begin(), kLayerExtensions.end());
    if (const auto required = extensionsNotDrawn(model, drawn, true);
        !required.empty()) {
        std::fprintf(stderr,
                     "warning: %s: requires %s, which this renderer does not draw; drawn "
                     "without %s\n",
                     file.c_str(), joined(required).c_str(), required.size() > 1 ? "them" : "it");
    }
    if (auto used = extensionsNotDrawn(model, drawn, false); !used.empty()) {
        for (std::string& name : used) name = extensionAndItsMaterials(model, name);
        std::fprintf(stderr, "note: %s: uses %s (optional), not drawn\n", file.c_str(),
                     joined(used).c_str());
    }
    if (const auto note = defaultMaterialNote(model)) std::fprintf(stderr, "%s\n", note->c_str());
    for (const std::string& note : model.notes)
        std::fprintf(stderr, "note: %s: %s\n", file.c_str(), note.c_str());
    if (punctual && model.lights.empty()) {
        std::fprintf(stderr, "note: %s: no KHR_lights_punctual lights; one default light\n",
                     file.c_str());
    }
    if (punctual && int(model.lights.size()) > GltfRenderer::kMaxLights) {
        std::fprintf(stderr, "note: %s: %zu lights; the first %d are drawn\n", file.c_str(),
                     model.lights.size(), GltfRenderer::kMaxLights);
    }
}

}  // namespace

int runGltfViewer(int argc, char** argv, const GltfViewerConfig& config) {
    std::vector<FlagSpec> flags = iblFlags();
    flags.push_back(FlagSpec::text(
        "--model", "FILE",
        "a .gltf or .glb to draw (default: " + config.defaultModelDescription + ")"));
    // The output and the parts of the light: read every frame (live in the window's panel).
    flags.push_back(
        FlagSpec::choice("--tonemap", cpu::toneMapperChoices(cpu::ToneMapper::KhronosNeutral),
                         "the tone mapper after exposure (default khronos-neutral: keeps base "
                         "colours true up to 0.8, then rolls highlights off to white)")
            .asLive());
    flags.push_back(FlagSpec::number("--exposure", "FACTOR",
                                     "a linear factor on the light before tone mapping", 1e-4, 1e4,
                                     1.0)
                        .asLive());
    flags.push_back(FlagSpec::toggle("--no-ibl", "leave out the image-based light").asLive());
    flags.push_back(
        FlagSpec::toggle("--no-punctual", "leave out the file's punctual lights").asLive());
    flags.push_back(FlagSpec::integer("--light", "K",
                                      "the file's punctual light K alone (1 the first), its terms "
                                      "alone in a view (0: all of them)",
                                      0, GltfRenderer::kMaxLights, 0)
                        .asLive());
    flags.insert(flags.end(),
                 {(config.extensions ? viewFlag(kLayerViews) : viewFlag(kGltfViews)).asLive(),
                  viewGainFlag()});
    flags.push_back(FlagSpec::toggle("--single-scattering",
                                     "image-based light without the multiple-scattering energy "
                                     "(rough metals darken, as in 05)")
                        .asLive());
    if (config.extensions) {
        // The layers' factors, live (withLayerFactors): each one given replaces that factor in
        // every material with its extension; not given, each material's own from its file.
        auto factor = [](const char* name, const char* valueName, const std::string& help,
                         double min, double max) {
            return FlagSpec::number(name, valueName, help + " (not given: each material's own)",
                                    min, max, min)
                .withoutDefault()
                .asLive();
        };
        auto colour = [](const char* name, const std::string& help) {
            return FlagSpec::numbers(name, "R,G,B", help + " (not given: each material's own)", 3,
                                     0.0, 1.0)
                .asLive();
        };
        flags.insert(
            flags.end(),
            {factor("--clearcoat", "F", "the clear coat's factor of the clear-coated materials",
                    0.0, 1.0),
             factor("--clearcoat-roughness", "R", "the clear coat's roughness of the clear-coated materials", 0.0, 1.0),
             colour("--sheen-color", "the sheen's colour of the materials with a sheen (linear)"),
             factor("--sheen-roughness", "R", "the sheen's roughness of the materials with a sheen", 0.0, 1.0),
             factor("--transmission", "F",
                    "the share of light through the surface of the transmissive materials", 0.0,
                    1.0),
             factor("--thickness", "T",
                    "the volume's thickness of the transmissive materials, in the mesh's units (0: thin-walled)", 0.0, 10.0),
             colour("--attenuation-color",
                    "the colour white light turns after --attenuation-distance in a transmissive volume"),
             factor("--attenuation-distance", "D",
                    "the distance in a transmissive volume after which light has the attenuation colour",
                    1e-3, 1e3),
             factor("--ior", "N",
                    "every material's index of refraction (F0 = ((N-1)/(N+1))^2)",
                    1.0, 3.0),
             factor("--specular", "F",
                    "every material's KHR_materials_specular factor", 0.0, 1.0),
             colour("--specular-color", "every material's KHR_materials_specular colour"),
             factor("--emissive-strength", "S",
                    "every material's emissive strength (emission is factor x strength)",
                    0.0, 100.0)});
    }
    App app(argc, argv,
            {.name = config.name,
             .title = config.title,
             .flags = flags,
             .srgbTarget = true,  // linear out of the shaders, encoded by the GL
             .orbitCamera = true});
    const Model model = loadModel(app.flagPath("--model").value_or(config.defaultModel));
    const GpuModel gpuModel(model);  // every texture read: a broken one ends the run here
    describe(model, !app.options().has("--no-punctual"), config.extensions);
    app.useOrbitCamera(model.boundsMin, model.boundsMax,
                       app.flag("--model") ? std::nullopt : config.defaultModelCamera);
    const std::vector<PunctualLight> fallback = {defaultLight()};
    const std::span<const PunctualLight> lights =
        model.lights.empty() ? std::span<const PunctualLight>(fallback) : model.lights;

    // 05's maps, from the same cache: irradiance 32^2, prefiltered 128^2 with 5 mips, and the
    // glTF BRDF's LUT 512^2 (not 05's: see BrdfLutChannels::GltfScaleBias), on units 5-7. Made (or
    // read) before the first frame that has the image-based light, that is before the first frame
    // unless --no-ibl; the environment keeps a reference to the cache, so both live as long.
    std::optional<IblCache> cache;
    std::optional<SplitSumMaps> maps;
    Skybox skybox;
    // The program of the frame's view (its #defines) for a material's layers.
    std::vector<std::string> viewDefinitions;
    auto programFor = [&](const std::vector<std::string>& layers) -> Shader& {
        std::vector<std::string> defines = viewDefinitions;
        defines.insert(defines.end(), layers.begin(), layers.end());
        return app.shader("common/gltf.vert", "common/gltf.frag", defines);
    };
    GltfRenderer renderer(programFor, config.extensions);
    // the layers' LUT (baked: A is the sheen's albedo, RG the split sum's scale and bias), made
    // only for a model with a sheen or a transmission, and the sheen's prefiltered environment
    // (with the IBL maps), only for a model with a sheen
    auto anyMaterialHas = [&](const char* layer) {
        return config.extensions &&
               std::any_of(model.materials.begin(), model.materials.end(), [&](const Material& m) {
                   const auto layers = materialLayers(m);
                   return std::find(layers.begin(), layers.end(), layer) != layers.end();
               });
    };
    const bool sheen = anyMaterialHas("SHEEN");
    const bool layersLut = sheen || anyMaterialHas("TRANSMISSION");
    std::optional<Texture2D> sheenLut;
    std::optional<TextureCube> sheenMap;

    glEnable(GL_DEPTH_TEST);
    int saidAlone = 0;  // the --light K past the file's lights last said so (once a value)
    while (app.nextFrame()) {
        const bool ibl = !app.options().has("--no-ibl");
        const bool punctual = !app.options().has("--no-punctual");
        const int toneMapper = int(*cpu::toneMapperFromName(app.flagChoice("--tonemap")));
        const float exposure = app.flagNumber("--exposure");
        const View view = viewNamed(app.flagChoice("--view"));
        viewDefinitions = viewDefines(view);
        // a term view of the core material shows its terms: its program, without the layers; a
        // view of the layers, theirs
        renderer.setExtensions(config.extensions && (view == View::Final || isLayerView(view)));
        if (config.extensions) {
            auto colour = [&](const char* name) -> std::optional<glm::vec3> {
                const auto numbers = app.flagNumbers(name);
                if (!numbers) return std::nullopt;
                return glm::vec3((*numbers)[0], (*numbers)[1], (*numbers)[2]);
            };
            renderer.setLayerFactors(
                {.clearcoat = app.flagNumberIfAny("--clearcoat"),
                 .clearcoatRoughness = app.flagNumberIfAny("--clearcoat-roughness"),
                 .sheenColor = colour("--sheen-color"),
                 .sheenRoughness = app.flagNumberIfAny("--sheen-roughness"),
                 .transmission = app.flagNumberIfAny("--transmission"),
                 .thickness = app.flagNumberIfAny("--thickness"),
                 .attenuationColor = colour("--attenuation-color"),
                 .attenuationDistance = app.flagNumberIfAny("--attenuation-distance"),
                 .ior = app.flagNumberIfAny("--ior"),
                 .specular = app.flagNumberIfAny("--specular"),
                 .specularColor = colour("--specular-color"),
                 .emissiveStrength = app.flagNumberIfAny("--emissive-strength")});
        }
        // --light K: that light alone (none where the file has fewer)
        const int alone = app.flagInt("--light");
        std::span<const PunctualLight> shown = punctual ? lights : std::span<const PunctualLight>();
        if (alone > 0)
            shown = size_t(alone) <= shown.size() ? shown.subspan(size_t(alone - 1), 1)
                                                  : std::span<const PunctualLight>();
        if (alone > 0 && size_t(alone) > lights.size() && alone != saidAlone) {
            std::fprintf(stderr,
                         "note: --light %d: there %s only %zu punctual light%s (the model's, else "
                         "the default one); no light is drawn\n",
                         alone, lights.size() == 1 ? "is" : "are", lights.size(),
                         lights.size() == 1 ? "" : "s");
        }
        saidAlone = alone > 0 && size_t(alone) > lights.size() ? alone : 0;
        // Made again after R: the cache's keys hold the shaders' code, so an edited IBL shader
        // is computed anew.
        if (layersLut && (!sheenLut || app.shadersReloaded())) {
            if (!cache) cache.emplace(cacheDir(app.options()));
            sheenLut = brdfLut(*cache, 256, 1024, BrdfLutChannels::ScaleBiasSheen);
            app.bindRenderTarget();
        }
        if (ibl && (!maps || app.shadersReloaded())) {
            if (!cache) cache.emplace(cacheDir(app.options()));
            maps.emplace(*cache, environmentFile(app.options()), BrdfLutChannels::GltfScaleBias);
            if (sheen) sheenMap = maps->environment.sheenMap();
            app.addPrecomputeSeconds(cache->computeSeconds());
            app.bindRenderTarget();  // the frame's, after the precomputation's own
        }
        renderer.setLayerMaps(sheenLut ? &*sheenLut : nullptr, sheenMap ? &*sheenMap : nullptr);

        // Without the environment, a dark grey background (linear; the target encodes it); a view
        // on its neutral grey, without the sky.
        app.clearFrame(view, glm::vec3(0.02f));
        // what every program of the frame is given before its first primitive
        auto setFrame = [&](Shader& shader) {
            GltfRenderer::setLights(shader, shown);
            shader.set("projection", app.projection());
            shader.set("view", app.view());
            shader.set("camPos", app.cameraPosition());
            shader.set("usePunctual", punctual ? 1 : 0);
            shader.set("useIbl", ibl ? 1 : 0);
            shader.set("multipleScattering", app.options().has("--single-scattering") ? 0 : 1);
            shader.set("toneMapper", toneMapper);
            shader.set("exposure", exposure);
            if (renderer.drawingBackdrop()) {  // the picture, what comes through the glass
                if (view != View::Final) shader.set("termView", int(View::Final));
            } else {
                selectView(shader, view, app.flagNumber("--gain"));
            }
            if (ibl) maps->use(shader, GltfRenderer::kFirstIblUnit);
        };
        if (ibl) {
            // the sky first here: blended primitives must be drawn over it
            skybox.setToneMapping(toneMapper, exposure);
            if (view == View::Final)
                skybox.draw(maps->environment.environmentMap(), app.view(), app.projection());
        }
        // a transmissive primitive's backdrop: the same sky, as linear radiance
        auto background = [&] {
            if (!ibl) return;
            skybox.setToneMapping(GltfRenderer::kLinearRadiance, 1.0f);
            skybox.draw(maps->environment.environmentMap(), app.view(), app.projection());
            skybox.setToneMapping(toneMapper, exposure);
        };
        renderer.draw(gpuModel, glm::mat4(1.0f), app.view(), setFrame, background);
        if (!app.flag("--model")) {
            for (const GltfViewerConfig::Label& label : config.defaultModelLabels) {
                app.label(model.boundsMin + label.atBounds * (model.boundsMax - model.boundsMin),
                          label.text);
            }
        }
    }
    return 0;
}

}  // namespace pbr
