#pragma once
// Textures on the GPU, each owning its GL name.
#include <filesystem>

#include "gl.h"
#include "image.h"

namespace pbr {

enum class ColorSpace { Linear, Srgb };

class Texture2D {
public:
    // Uploads an 8-bit image (1-4 channels), with mipmaps, repeat wrap and trilinear filtering.
    // Srgb: colour data decoded to linear by the sampler (GL_SRGB8 / GL_SRGB8_ALPHA8).
    Texture2D(const Image& image, ColorSpace colorSpace);
    // Loads a file; throws Error("<path>: <reason>").
    static Texture2D load(const std::filesystem::path& path, ColorSpace colorSpace);

    void bind(int unit) const;
    int width() const { return width_; }
    int height() const { return height_; }

private:
    GlTexture texture_;
    int width_ = 0, height_ = 0;
};

}  // namespace pbr
