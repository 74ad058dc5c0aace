// What a file of the IBL cache goes through before the GPU sees it (ibl/ibl_cache.cpp's load, the
// shape checks of files/ktx.h that Texture2D::fromKtx and TextureCube::fromKtx make): any bytes
// either decode, and each shape the cache asks for is accepted only when every image the upload
// reads holds the bytes it reads, or they are refused in one line.
#include "files/ktx.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace pbr;
    const std::string name = "cache/sunny_courtyard.irradiance.ktx";
    KtxImage image;
    if (!fuzz::reads(name, [&] { image = decodeKtx(fuzz::bytesOf(data, size), name); })) return 0;
    // IblCache::load then compares the key the file was made under (a lookup in the decoded
    // metadata) and uses the file only when it is the one asked for: every file that decodes is
    // taken here as current, so that each reaches the shape checks.
    const size_t bytesPerTexel = size_t(image.channels()) * size_t(image.bytesPerChannel());
    // The LUT's upload: level 0 of one face, width x height texels.
    if (const std::optional<std::string> problem = ktxShapeError(image, false)) {
        fuzz::expectOneLine(*problem, "");
    } else {
        fuzz::expect(image.faces == 1 && !image.images.empty() &&
                         image.images[0].size() ==
                             size_t(image.width) * size_t(image.height) * bytesPerTexel,
                     "a 2D texture's level 0 holds width x height texels");
    }
    // The cube's upload: six square faces at each level, each max(1, size >> level) a side.
    if (const std::optional<std::string> problem = ktxShapeError(image, true)) {
        fuzz::expectOneLine(*problem, "");
        return 0;
    }
    fuzz::expect(image.faces == 6 && image.width == image.height && image.channels() >= 3,
                 "a cube map of six square RGB(A) faces");
    fuzz::expect(image.images.size() == size_t(image.levels) * 6, "six faces a level");
    for (int level = 0; level < image.levels; ++level) {
        const size_t side = size_t(std::max(1, image.width >> level));
        for (int face = 0; face < 6; ++face) {
            fuzz::expect(
                image.images[size_t(level * 6 + face)].size() == side * side * bytesPerTexel,
                "each face holds the texels its level's upload reads");
        }
    }
    return 0;
}
