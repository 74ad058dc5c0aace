// KTX 1 files (files/ktx.h, decodeKtx): any bytes either decode to an image whose levels and faces
// hold exactly the bytes their sizes need, and which encodes to a file that decodes to the same
// image, or are refused in one line naming the file.
#include "files/ktx.h"
#include "fuzz_check.h"

namespace pbr::fuzz {

// The promises decodeKtx makes of what it returns.
void expectWhole(const KtxImage& image) {
    expect(image.width >= 1 && image.height >= 1 && image.width <= 65536 && image.height <= 65536,
           "a size of 1 to 65536 a side");
    expect(image.faces == 1 || (image.faces == 6 && image.width == image.height),
           "one face, or six square ones");
    expect(image.levels >= 1 && (image.levels == 1 ||
                                 (std::max(image.width, image.height) >> (image.levels - 1)) >= 1),
           "a mip chain no longer than the size allows");
    expect(image.images.size() == size_t(image.levels) * size_t(image.faces),
           "levels x faces images");
    for (size_t i = 0; i < image.images.size(); ++i) {
        expect(image.images[i].size() == image.imageBytes(int(i / size_t(image.faces))),
               "each image the bytes of its level's size");
    }
}

}  // namespace pbr::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace pbr;
    const std::string name = "fuzz.ktx";
    KtxImage image;
    if (!fuzz::reads(name, [&] { image = decodeKtx(fuzz::bytesOf(data, size), name); })) return 0;
    fuzz::expectWhole(image);
    // What was read is what the cache and 06 write: it must encode, and read back the same.
    std::string encoded;
    if (!fuzz::reads("", [&] { encoded = encodeKtx(image); }))
        fuzz::finding("a decoded image that encodeKtx refuses");
    const KtxImage again = decodeKtx(encoded, "encoded");
    fuzz::expect(again.format == image.format && again.width == image.width &&
                     again.height == image.height && again.faces == image.faces &&
                     again.levels == image.levels && again.images == image.images &&
                     again.metadata == image.metadata,
                 "encoded, it decodes to the same image");
    return 0;
}
