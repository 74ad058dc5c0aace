// bake_brdf_luts DIR: the BRDF LUTs the samples read, made once by the build instead of at every
// start (they depend on no input): brdf_lut_512.ktx (05, 07, 08: LearnOpenGL's 512^2 RG16F) and
// brdf_lut_sheen_256.ktx (06: the cookbook's 256^2 with sheen), with the cache's metadata, so
// that IblCache finds them in iblDir(). Computed by the same GPU code as at run time
// (pbr::computeBrdfLut), in a headless context.
#include <filesystem>
#include <string>
#include <vector>

#include "app/app.h"
#include "base/error.h"
#include "files/ktx.h"
#include "ibl/ibl.h"
#include "ibl/ibl_cache.h"

namespace {

void bake(const std::filesystem::path& dir, int size, int samples, pbr::BrdfLutChannels channels) {
    const pbr::MapFile file = pbr::brdfLutFile(size, samples, channels);
    const pbr::Texture2D lut = pbr::computeBrdfLut(size, samples, channels);
    pbr::writeKtx(dir / file.name, file.withMetadata(lut.toKtx(pbr::brdfLutFormat(channels))));
}

}  // namespace

int main(int argc, char** argv) try {
    if (argc != 2) throw pbr::Error("usage: bake_brdf_luts DIR");
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    std::vector<std::string> args = {argv[0], "--headless", "--size", "16x16"};
    std::vector<char*> argp;
    for (std::string& arg : args) argp.push_back(arg.data());
    pbr::App app(int(argp.size()), argp.data(), {.name = "bake_brdf_luts"});
    bake(dir, 512, 1024, pbr::BrdfLutChannels::ScaleBias);
    bake(dir, 256, 1024, pbr::BrdfLutChannels::ScaleBiasSheen);
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
