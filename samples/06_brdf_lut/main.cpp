// 06 brdf_lut: the cookbook's "precompute BRDF LUT" (and "FilterEnvmap") as a tool. Bakes the
// BRDF lookup table (256^2, R/G = GGX scale and bias, B = Charlie sheen) and, given --hdr, an
// environment's irradiance and prefiltered specular maps, writes them as KTX 1 files, and shows
// the LUT. See README.md beside this file.
#include <cstdio>
#include <filesystem>
#include <utility>
#include <vector>

#include "app.h"
#include "error.h"
#include "ibl.h"
#include "ibl_cache.h"
#include "mesh.h"
#include "paths.h"

namespace {
// Writes `image` to `path` with its orientation stated, and says so.
void writeMap(const std::filesystem::path& path, pbr::KtxImage image) {
    image.metadata["KTXorientation"] = "S=r,T=u";  // row 0 at t = 0, as glTexImage2D takes it
    pbr::writeKtx(path, image);
    std::printf("06_brdf_lut: wrote %s\n", pbr::displayPath(path).c_str());
}
}  // namespace

int main(int argc, char** argv) try {
    pbr::App app(
        argc, argv,
        {.name = "06_brdf_lut",
         .title = "06 BRDF LUT: GGX scale and bias (left), Charlie sheen x 8 (right)",
         .flags = {
             {"--hdr", "FILE", "also bake this environment's irradiance and prefiltered maps"},
             {"--ktx-dir", "DIR", "where the .ktx files go (default: beside --output, else .)"},
             {"--no-cache", "", "compute the maps even when the cache holds them"}}});
    const std::filesystem::path output = app.options().output;
    const std::filesystem::path ktxDir =
        app.flag("--ktx-dir")
            .value_or(output.has_parent_path() ? output.parent_path().string() : ".");

    // Everything is computed (or loaded) before any file is written: a broken --hdr leaves none.
    pbr::IblCache cache(pbr::cacheDir(app.options()));
    std::vector<std::pair<std::string, pbr::KtxImage>> files;
    if (const auto hdr = app.flag("--hdr")) {
        pbr::IblEnvironment environment(cache, *hdr);
        const std::string stem = std::filesystem::path(*hdr).stem().string();
        pbr::KtxImage irradiance = environment.irradianceMap(32).toKtx();
        irradiance.metadata["pbr.contents"] = "diffuse irradiance / pi, 32^2 cube map";
        pbr::KtxImage prefiltered = environment.prefilteredMap(128, 5, 1024).toKtx();
        prefiltered.metadata["pbr.contents"] =
            "GGX-prefiltered specular cube map, 128^2, mip m for roughness m / 4, 1024 samples";
        files.emplace_back(stem + "_irradiance.ktx", std::move(irradiance));
        files.emplace_back(stem + "_prefiltered.ktx", std::move(prefiltered));
    }
    const pbr::Texture2D brdfLUT =
        pbr::brdfLut(cache, 256, 1024, pbr::BrdfLutChannels::ScaleBiasSheen);
    pbr::KtxImage lut = brdfLUT.toKtx(pbr::KtxFormat::RGBA16F);
    lut.metadata["pbr.contents"] =
        "BRDF LUT, 1024 samples; x = NdotV, y = roughness at texel centres; R = GGX scale, "
        "G = GGX bias to F0, B = Charlie sheen";
    files.emplace(files.begin(), "brdf_lut.ktx", std::move(lut));
    for (auto& [name, image] : files) writeMap(ktxDir / name, std::move(image));
    app.addPrecomputeSeconds(cache.computeSeconds());

    pbr::Shader& shader = app.shader("ibl/fullscreen.vert", "06_brdf_lut/show_lut.frag");
    shader.set("brdfLUT", 0);
    shader.set("sheenScale", 8.0f);
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
    }
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
