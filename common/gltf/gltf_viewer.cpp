#include "gltf/gltf_viewer.h"

#include <cstdio>
#include <optional>
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

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

// What a learner should hear about a file before its picture: what it asks for that is not
// drawn, and what stands in for what it lacks.
void describe(const Model& model, bool punctual) {
    const std::string file = displayPath(model.file);
    if (const auto required = extensionsNotDrawn(model, kDrawnExtensions, true);
        !required.empty()) {
        std::fprintf(stderr,
                     "warning: %s: requires %s, which this renderer does not draw; drawn "
                     "without %s\n",
                     file.c_str(), joined(required).c_str(), required.size() > 1 ? "them" : "it");
    }
    if (const auto used = extensionsNotDrawn(model, kDrawnExtensions, false); !used.empty()) {
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
    flags.push_back(FlagSpec::choice(
        "--tonemap", cpu::toneMapperChoices(cpu::ToneMapper::KhronosNeutral),
        "the tone mapper after exposure (default khronos-neutral: keeps base colours true up to "
        "0.8, then rolls highlights off to white)"));
    flags.push_back(FlagSpec::number("--exposure", "FACTOR",
                                     "a linear factor on the light before tone mapping "
                                     "(default 1)",
                                     1e-4, 1e4));
    flags.push_back(FlagSpec::toggle("--no-ibl", "leave out the image-based light"));
    flags.push_back(FlagSpec::toggle("--no-punctual", "leave out the file's punctual lights"));
    flags.push_back(viewFlag(kGltfViews));
    flags.push_back(FlagSpec::toggle("--single-scattering",
                                     "image-based light without the multiple-scattering energy "
                                     "(rough metals darken, as in 05)"));
    App app(argc, argv,
            {.name = config.name,
             .title = config.title,
             .flags = flags,
             .srgbTarget = true,  // linear out of the shaders, encoded by the GL
             .orbitCamera = true});
    const bool ibl = !app.options().has("--no-ibl");
    const bool punctual = !app.options().has("--no-punctual");
    const int toneMapper = int(*cpu::toneMapperFromName(app.flagChoice("--tonemap")));
    const float exposure = app.flagNumber("--exposure", 1.0f);

    const Model model = loadModel(app.flag("--model").value_or(config.defaultModel.string()));
    const GpuModel gpuModel(model);  // every texture read: a broken one ends the run here
    describe(model, punctual);
    app.useOrbitCamera(model.boundsMin, model.boundsMax);

    const View view = viewNamed(app.flagChoice("--view"));
    Shader& shader = app.shader("common/gltf.vert", "common/gltf.frag", viewDefines(view));
    GltfRenderer renderer(shader);
    if (punctual) {
        const std::vector<PunctualLight> fallback = {defaultLight()};
        renderer.setLights(model.lights.empty() ? fallback : model.lights);
    }
    shader.set("usePunctual", punctual ? 1 : 0);
    shader.set("useIbl", ibl ? 1 : 0);
    shader.set("multipleScattering", app.options().has("--single-scattering") ? 0 : 1);
    shader.set("toneMapper", toneMapper);
    shader.set("exposure", exposure);
    selectView(shader, view);

    // 05's maps, from the same cache: irradiance 32^2, prefiltered 128^2 with 5 mips, the BRDF
    // LUT 512^2. Units 5-7 hold them for the whole run. Every map is made (or read) here, before
    // the first frame; the environment keeps a reference to the cache, so both live as long.
    std::optional<IblCache> cache;
    std::optional<IblEnvironment> environment;
    std::optional<TextureCube> irradianceMap, prefilterMap;
    std::optional<Texture2D> brdfLUT;
    std::optional<Skybox> skybox;
    if (ibl) {
        cache.emplace(cacheDir(app.options()));
        environment.emplace(*cache, environmentFile(app.options()));
        environment->environmentMap();  // for the sky
        irradianceMap.emplace(environment->irradianceMap(32));
        prefilterMap.emplace(environment->prefilteredMap(128, 5, kPrefilterSamples));
        brdfLUT.emplace(brdfLut(*cache, 512, 1024, BrdfLutChannels::ScaleBias));
        app.addPrecomputeSeconds(cache->computeSeconds());
        useIblMaps(shader, environment->environmentMap(), *irradianceMap, *prefilterMap, *brdfLUT,
                   GltfRenderer::kFirstIblUnit);
        skybox.emplace();
        skybox->setToneMapping(toneMapper, exposure);
    }

    glEnable(GL_DEPTH_TEST);
    while (app.nextFrame()) {
        // Without the environment, a dark grey background (linear; the target encodes it).
        glClearColor(0.02f, 0.02f, 0.02f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        shader.use();
        shader.set("projection", app.projection());
        shader.set("view", app.view());
        shader.set("camPos", app.cameraPosition());
        // the sky first here: blended primitives must be drawn over it
        if (skybox) skybox->draw(environment->environmentMap(), app.view(), app.projection());
        renderer.draw(gpuModel, glm::mat4(1.0f), app.view());
    }
    return 0;
}

}  // namespace pbr
