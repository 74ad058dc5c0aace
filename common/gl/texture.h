#pragma once
// Textures on the GPU, each owning its GL name.
#include <filesystem>
#include <optional>
#include <string>

#include "files/image.h"
#include "files/ktx.h"
#include "gl/gl.h"
#include "gl/shader.h"

namespace pbr {

enum class ColorSpace { Linear, Srgb };

// Trilinear: mipmaps, linear within and between levels (what a sample wants). Nearest: level 0
// only, no filtering, so a pixel shows exactly one texel (what a texel-exact test wants).
enum class TextureFilter { Trilinear, Nearest };

class Texture2D {
public:
    // Uploads an 8-bit image (1-4 channels; row 0 at t = 0), repeat wrap. Srgb: colour decoded
    // to linear by the sampler (GL_SRGB8 / GL_SRGB8_ALPHA8; grey images are widened to RGB).
    Texture2D(const Image& image, ColorSpace colorSpace,
              TextureFilter filter = TextureFilter::Trilinear);
    // Loads a file; throws Error("<path>: <reason>").
    static Texture2D load(const std::filesystem::path& path, ColorSpace colorSpace,
                          TextureFilter filter = TextureFilter::Trilinear);

    // A float RGB image (an HDR environment): RGB16F while every value fits a half float
    // (65504), else RGB32F; linear filtering, no mipmaps, clamped.
    explicit Texture2D(const HdrImage& image);
    // An empty render target texture of `internalFormat` (GL_RG16F, ...), linear, clamped.
    Texture2D(int width, int height, GLenum internalFormat);
    // Level 0 as floats, `channels` (1-4) per texel, row 0 at t = 0.
    std::vector<float> readFloats(int channels) const;
    // Level 0 as a KTX image of `format` (row 0 at t = 0), and back: a float texture made from
    // level 0 of a 2D KTX image, linear, clamped, no mipmaps. Throws Error for a cube map.
    KtxImage toKtx(KtxFormat format) const;
    static Texture2D fromKtx(const KtxImage& image);

    void bind(int unit) const;
    int width() const { return width_; }
    int height() const { return height_; }
    GLuint id() const { return texture_.id(); }
    GLenum internalFormat() const { return internalFormat_; }

private:
    GlTexture texture_;
    int width_ = 0, height_ = 0;
    GLenum internalFormat_ = GL_RGBA8;
};

// A cube map of float RGB faces, seamless filtering expected (the App turns it on). Faces are
// rendered into by the IBL precomputation; `levels` mip levels are allocated. GL_RGB16F holds
// what an ordinary environment needs; GL_RGB32F one whose sun goes past half-float range.
class TextureCube {
public:
    TextureCube(int size, int levels, GLenum internalFormat = kHalfFloatRgb);
    void bind(int unit) const;
    int size() const { return size_; }
    int levels() const { return levels_; }
    GLuint id() const { return texture_.id(); }
    // The texels of one face at one level, RGB floats, row 0 at the face's t = 0.
    std::vector<float> readFace(int face, int level) const;
    // Replaces one face of one level with RGB floats (size^2 x 3, row 0 at t = 0); binds the
    // cube to unit 0.
    void writeFace(int face, int level, const std::vector<float>& rgb);
    GLenum internalFormat() const { return internalFormat_; }
    // Every face and level as RGBA16F (RGBA32F for a GL_RGB32F cube; alpha 1), and back (RGB16F,
    // RGBA16F or RGBA32F, square faces, a mip chain of halving sizes). fromKtx throws Error for
    // anything else.
    KtxImage toKtx() const;
    static TextureCube fromKtx(const KtxImage& image);

private:
    GlTexture texture_;
    int size_, levels_;
    GLenum internalFormat_;
};

// A PBR material folder: albedo, normal, metallic, roughness and optionally ao, under the names
// real texture sets use (see material_folder.h), each .png, .jpg or .jpeg. Without ao, ao is
// white, as the text suggests; any other missing map, and two files for one map, are an Error
// naming the folder. Maps may differ in size: each is sampled by uv. albedo is decoded
// from sRGB; normal, metallic, roughness and ao are linear; a DirectX normal map is flipped to
// OpenGL's convention (green up).
struct PbrTextures {
    Texture2D albedo, normal, metallic, roughness, ao;

    // Binds albedo, normal, metallic, roughness, ao to texture units 0-4.
    void bind() const;
    // Points the samplers albedoMap, normalMap, metallicMap, roughnessMap and aoMap at those
    // units (02 writes the five lines out, as the text does).
    static void setSamplers(Shader& shader);
};
PbrTextures loadPbrTextures(const std::filesystem::path& dir,
                            TextureFilter filter = TextureFilter::Trilinear);

}  // namespace pbr
