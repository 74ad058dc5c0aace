#pragma once
// KTX 1 files (the Khronos texture container the cookbook's precompute tools write): 2D textures
// and cube maps with mip chains, float formats, key/value metadata. Pure file I/O, no OpenGL
// calls; the GL enums a KTX 1 header stores are written as numbers.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pbr {

enum class KtxFormat { RG16F, RGB16F, RGBA16F, RGBA32F };

struct KtxImage {
    KtxFormat format = KtxFormat::RGBA16F;
    int width = 0, height = 0;
    int faces = 1;   // 1, or 6 for a cube map (+X, -X, +Y, -Y, +Z, -Z)
    int levels = 1;  // mip levels, each half the size of the one before
    // images[level * faces + face]: the texels of one face of one level, tightly packed rows
    std::vector<std::vector<std::uint8_t>> images{};
    std::map<std::string, std::string> metadata{};  // KTX key/value pairs (UTF-8, no NUL)

    int channels() const;
    int bytesPerChannel() const;
    size_t imageBytes(int level) const;  // one face of `level`
};

// The bytes of a KTX 1 file holding `image`; throws Error when the image is inconsistent.
std::string encodeKtx(const KtxImage& image);
// Writes `image` as a KTX 1 file, whole or not at all (see output.h). Throws Error("<path>:
// <reason>") when the image is inconsistent or the file cannot be written.
void writeKtx(const std::filesystem::path& path, const KtxImage& image);
// Throws Error("<path>: <reason>") for anything but a complete, consistent KTX 1 file of one of
// the formats above (wrong identifier, truncated, sizes that do not add up, ...).
KtxImage readKtx(const std::filesystem::path& path);
// The same from a file's bytes; `name` is what the error messages call it.
KtxImage decodeKtx(std::string_view bytes, const std::string& name);

// Why `image` cannot become a float texture on the GPU, or nullopt when it can: a 2D texture
// (`cube` false) takes one face; a cube map (`cube` true) six square faces, RGB or RGBA, and no
// more mip levels than its size has. Texture2D::fromKtx and TextureCube::fromKtx throw this
// reason; the IBL cache asks it of a file before it uploads one.
std::optional<std::string> ktxShapeError(const KtxImage& image, bool cube);

// IEEE 754 half precision, for RG16F / RGBA16F data.
std::uint16_t floatToHalf(float value);
float halfToFloat(std::uint16_t half);

}  // namespace pbr
