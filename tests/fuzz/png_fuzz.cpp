// Images a user hands over as texture maps (files/image.h, decodeImage): the PNG guard in front of
// stb_image, and stb behind it. Any bytes either decode to width x height pixels of 1 to 4
// channels, within the 16384^2 pixels the reader takes, or are refused in one line naming the
// image.
#include "files/image.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace pbr;
    const std::string name = "fuzz.png";
    Image image;
    const std::vector<std::uint8_t> bytes(data, data + size);
    if (!fuzz::reads(name, [&] { image = decodeImage(bytes, name); })) return 0;
    fuzz::expect(image.width >= 1 && image.height >= 1, "at least one pixel");
    fuzz::expect(double(image.width) * double(image.height) <= double(1 << 28),
                 "at most 16384^2 pixels");
    fuzz::expect(image.channels >= 1 && image.channels <= 4, "1 to 4 channels");
    fuzz::expect(
        image.pixels.size() == size_t(image.width) * size_t(image.height) * size_t(image.channels),
        "width x height x channels bytes");
    return 0;
}
