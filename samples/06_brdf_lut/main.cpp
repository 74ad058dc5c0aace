// 06 brdf_lut: the cookbook's "precompute BRDF LUT" (and "FilterEnvmap") as a tool. Bakes the
// BRDF lookup table (256^2, R/G = GGX scale and bias, B = Charlie sheen) and, given --hdr, an
// environment's irradiance and prefiltered specular maps, writes them as KTX 1 files, and shows
// the LUT. See README.md beside this file.
#include <cstdio>
#include <filesystem>

#include "app.h"
#include "error.h"
#include "ibl.h"
#include "ibl_cache.h"
#include "mesh.h"
#include "paths.h"

namespace {
// Writes `image` to <dir>/<name> with a line saying what it holds; reports the path.
void writeMap(const std::filesystem::path& dir, const std::string& name, pbr::KtxImage image,
              const std::string& contents) {
    image.metadata["KTXorientation"] = "S=r,T=u";  // row 0 at t = 0, as glTexImage2D takes it
    image.metadata["pbr.contents"] = contents;
    const std::filesystem::path path = dir / name;
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

    pbr::IblCache cache(pbr::cacheDir(app.options()));
    const pbr::Texture2D brdfLUT =
        pbr::brdfLut(cache, 256, 1024, pbr::BrdfLutChannels::ScaleBiasSheen);
    writeMap(ktxDir, "brdf_lut.ktx", brdfLUT.toKtx(pbr::KtxFormat::RGBA16F),
             "BRDF LUT, 1024 samples; x = NdotV, y = roughness at texel centres; R = GGX scale, "
             "G = GGX bias to F0, B = Charlie sheen");
    if (const auto hdr = app.flag("--hdr")) {
        pbr::IblEnvironment environment(cache, *hdr);
        const std::string stem = std::filesystem::path(*hdr).stem().string();
        writeMap(ktxDir, stem + "_irradiance.ktx", environment.irradianceMap(32).toKtx(),
                 "diffuse irradiance / pi, 32^2 cube map");
        writeMap(
            ktxDir, stem + "_prefiltered.ktx", environment.prefilteredMap(128, 5, 1024).toKtx(),
            "GGX-prefiltered specular cube map, 128^2, mip m for roughness m / 4, 1024 samples");
    }
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
