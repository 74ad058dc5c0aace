// Radiance .hdr files (files/image.h, decodeHdr): any bytes either decode to width x height RGB
// floats, each finite and not negative, that encode and decode again to the same size, or are
// refused in one line naming the file.
#include "files/image.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace pbr;
    const std::string name = "fuzz.hdr";
    HdrImage image;
    if (!fuzz::reads(name, [&] { image = decodeHdr(fuzz::bytesOf(data, size), name); })) return 0;
    fuzz::expect(
        image.width >= 1 && image.height >= 1 && image.width <= 32768 && image.height <= 32768,
        "a size of 1 to 32768 a side");
    fuzz::expect(image.pixels.size() == size_t(image.width) * size_t(image.height) * 3,
                 "width x height x 3 floats");
    for (const float value : image.pixels)
        fuzz::expect(fuzz::finite(value) && value >= 0.0f, "radiance finite, not negative");
    fuzz::expect(fuzz::finite(maxValue(image)), "a finite largest value");
    // What 06 and the tests write of it reads back (RGBE is lossy: the size, not the bits).
    const HdrImage again = decodeHdr(encodeHdr(image), "encoded");
    fuzz::expect(again.width == image.width && again.height == image.height,
                 "encoded, it decodes to the same size");
    return 0;
}
