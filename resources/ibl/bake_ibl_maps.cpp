// bake_ibl_maps DIR: the IBL maps that depend on no user input, made once by the build instead of
// at every start, with the cache's metadata under their renderer-free keys (MapFile::bakedKey),
// so that IblCache finds them in iblDir():
// - brdf_lut_512.ktx (05: LearnOpenGL's 512^2 RG16F), brdf_lut_sheen_256.ktx (06: the
//   cookbook's 256^2 with sheen; 10 reads its sheen) and brdf_lut_gltf_512.ktx (07, 08, 10: the
//   glTF BRDF's, 512^2 RG16F), read by every build;
// - the project's environment's cube (512^2, every mip), irradiance (32^2) and prefiltered
//   (128^2, 5 levels) maps, which only the pages read (a page has no cache; natively the cache
//   keeps what a first run made).
// Computed by the same GPU code as at run time (pbr::computeBrdfLut, IblEnvironment), in a
// headless context.
#include <filesystem>
#include <string>
#include <vector>

#include "app/app.h"
#include "base/error.h"
#include "base/paths.h"
#include "files/ktx.h"
#include "ibl/ibl.h"
#include "ibl/ibl_cache.h"

namespace {

void write(const std::filesystem::path& dir, pbr::MapFile file, pbr::KtxImage image) {
    file.key = file.bakedKey;
    pbr::writeKtx(dir / file.name, file.withMetadata(std::move(image)));
}

}  // namespace

int main(int argc, char** argv) try {
    if (argc != 2) throw pbr::Error("usage: bake_ibl_maps DIR");
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    std::vector<std::string> args = {argv[0], "--headless", "--size", "16x16"};
    std::vector<char*> argp;
    for (std::string& arg : args) argp.push_back(arg.data());
    pbr::App app(int(argp.size()), argp.data(), {.name = "bake_ibl_maps"});
    for (const auto& [size, channels] : {std::pair{512, pbr::BrdfLutChannels::ScaleBias},
                                         {256, pbr::BrdfLutChannels::ScaleBiasSheen},
                                         {512, pbr::BrdfLutChannels::GltfScaleBias}}) {
        write(dir, pbr::brdfLutFile(size, 1024, channels),
              pbr::computeBrdfLut(size, 1024, channels).toKtx(pbr::brdfLutFormat(channels)));
    }
    pbr::IblCache none(std::nullopt);
    pbr::IblEnvironment environment(none, pbr::environmentDir() / "sunny_courtyard.hdr");
    write(dir, environment.environmentFile(), environment.environmentMap().toKtx());
    write(dir, environment.irradianceFile(32), environment.irradianceMap(32).toKtx());
    write(dir, environment.prefilteredFile(128, 5, pbr::kPrefilterSamples),
          environment.prefilteredMap(128, 5, pbr::kPrefilterSamples).toKtx());
    write(dir, environment.sheenFile(), environment.sheenMap().toKtx());  // sample 10's
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
