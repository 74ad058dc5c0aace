// 06 brdf_lut: the cookbook's "precompute BRDF LUT" (and "FilterEnvmap") as a tool. Bakes the
// BRDF lookup table (256^2, R/G = GGX scale and bias, B = Charlie sheen) and, given --hdr, an
// environment's irradiance and prefiltered specular maps, writes them as KTX 1 files, and shows
// the LUT. See README.md beside this file.
#include <cstdio>
#include <filesystem>
#include <utility>

#include "app/app.h"
#include "base/error.h"
#include "files/ktx.h"
#include "gl/mesh.h"
#include "ibl/ibl.h"
#include "ibl/ibl_cache.h"

int main(int argc, char** argv) try {
    pbr::App app(
        argc, argv,
        {.name = "06_brdf_lut",
         .title = "06 BRDF LUT: GGX scale and bias (left), Charlie sheen (right)",
         .flags = {
             pbr::FlagSpec::text("--hdr", "FILE",
                                 "also bake this environment's irradiance and prefiltered maps"),
             pbr::FlagSpec::outputFolder(
                 "--ktx-dir", "DIR",
                 "an existing folder for the .ktx files (default: the folder of --output, "
                 "else the current folder)"),
             pbr::FlagSpec::toggle("--no-cache",
                                   "compute the maps even when the cache holds them")},
         .fixedView = true});  // two panels of the table, no camera
    const std::filesystem::path output = app.outputPath();
    const std::filesystem::path ktxDir =
        app.flagPath("--ktx-dir").value_or(output.has_parent_path() ? output.parent_path() : ".");

    // The maps under the names (and with the bytes) the IBL cache gives them. They are handed to
    // the App, which writes them with the picture at the end of the run: all of them, or none.
    pbr::IblCache cache(pbr::cacheDir(app.options()));
    auto bake = [&](const pbr::MapFile& file, pbr::KtxImage image) {
        app.addOutputFile(ktxDir / file.name, pbr::encodeKtx(file.withMetadata(std::move(image))));
    };
    constexpr auto kChannels = pbr::BrdfLutChannels::ScaleBiasSheen;
    const pbr::Texture2D brdfLUT = pbr::brdfLut(cache, 256, 1024, kChannels);
    const pbr::KtxImage lutImage = brdfLUT.toKtx(pbr::brdfLutFormat(kChannels));
    bake(pbr::brdfLutFile(256, 1024, kChannels), lutImage);
    if (const auto hdr = app.flagPath("--hdr")) {
        pbr::IblEnvironment environment(cache, *hdr);
        bake(environment.irradianceFile(32), environment.irradianceMap(32).toKtx());
        bake(environment.prefilteredFile(128, 5, pbr::kPrefilterSamples),
             environment.prefilteredMap(128, 5, pbr::kPrefilterSamples).toKtx());
    }
    app.addPrecomputeSeconds(cache.computeSeconds());

    pbr::Shader& shader = app.shader("ibl/fullscreen.vert", "06_brdf_lut/show_lut.frag");
    shader.set("brdfLUT", 0);
    const pbr::GpuMesh quad(pbr::quad());

    glDisable(GL_DEPTH_TEST);
    while (app.nextFrame()) {
        glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        // Two square panels side by side, as large as the frame allows, with a margin.
        const int side = std::min(app.height() * 9 / 10, app.width() * 9 / 20);
        const int gap = side / 12;
        const int left = (app.width() - 2 * side - gap) / 2, bottom = (app.height() - side) / 2;
        shader.use();
        brdfLUT.bind(0);
        for (int panel = 0; panel < 2; ++panel) {
            glViewport(left + panel * (side + gap), bottom, side, side);
            shader.set("showSheen", panel);
            quad.draw();
        }
        glViewport(0, 0, app.width(), app.height());

        // In a window (and with --panel): what each panel and axis is, and the table's value
        // under the cursor.
        const int top = app.height() - bottom - side;  // from the top, as labels count
        for (int panel = 0; panel < 2; ++panel) {
            const float x0 = float(left + panel * (side + gap)), mid = x0 + 0.5f * float(side);
            app.label({mid, float(top) - 12.0f},
                      panel == 0 ? "GGX scale (red) and bias (green)" : "Charlie sheen (blue)");
            app.label({mid, float(top + side) + 12.0f}, "NdotV: 0 at the left, 1 at the right");
            app.label({x0 + 56.0f, float(top) + 12.0f}, "roughness 1");
            app.label({x0 + 56.0f, float(top + side) - 12.0f}, "roughness 0");
        }
        if (const auto cursor = app.cursor()) {
            for (int panel = 0; panel < 2; ++panel) {
                const float u = (cursor->x - float(left + panel * (side + gap))) / float(side);
                const float v = 1.0f - (cursor->y - float(top)) / float(side);
                if (u < 0.0f || u >= 1.0f || v < 0.0f || v >= 1.0f) continue;
                const pbr::LutTexel texel = pbr::lutTexel(lutImage, u, v);
                char text[200];
                std::snprintf(text, sizeof text,
                              "NdotV %.3f, roughness %.3f\nscale %.4f, bias %.4f, sheen %.4f "
                              "(with Charlie's visibility %.4f)",
                              u, v, texel.scale, texel.bias, texel.sheen, texel.sheenAlbedo);
                app.label(*cursor + glm::vec2(0.0f, 36.0f), text);
            }
        }
    }
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
