#include "gl/texture.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "base/error.h"
#include "base/paths.h"
#include "files/material_folder.h"
#include "files/mip_chain.h"
#include "gl/framebuffer.h"

namespace pbr {

namespace {
// GL 3.3 has sRGB formats for RGB and RGBA only: grey (and grey + alpha) become RGB (RGBA).
bool needsWidening(const Image& image) {
    return image.channels < 3;
}

// Each pixel written in place, no call per pixel: a page's program routes every call that may
// throw through JavaScript (its exceptions), which made the five albedo maps of 09 cost 0.3 s.
Image widenForSrgb(const Image& image) {
    const bool alpha = image.channels == 2;
    const int in = image.channels, out = alpha ? 4 : 3;
    Image wide{image.width, image.height, out, {}};
    const size_t count = size_t(image.width) * size_t(image.height);
    wide.pixels.resize(count * size_t(out));
    const std::uint8_t* from = image.pixels.data();
    std::uint8_t* to = wide.pixels.data();
    for (size_t i = 0; i < count; ++i, from += in, to += out) {
        to[0] = from[0];
        to[1] = in >= 3 ? from[1] : from[0];
        to[2] = in >= 3 ? from[2] : from[0];
        if (alpha) to[3] = in == 2 ? from[1] : 255;
    }
    return wide;
}

#ifdef PBR_WEBGL
// WebGL 2 has no glGetTexImage: the level is attached to a framebuffer of its own and read back
// as RGBA floats (float colour buffers are readable with EXT_color_buffer_float).
std::vector<float> readLevelRgba(GLenum target, GLuint texture, int level, int width, int height) {
    const SavedGlState saved;
    const GlFramebuffer framebuffer;
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, target, texture, level);
    requireCompleteFramebuffer("texture read-back");
    std::vector<float> rgba(size_t(width) * size_t(height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, rgba.data());
    return rgba;
}

std::vector<float> firstChannels(const std::vector<float>& rgba, int channels) {
    std::vector<float> out(rgba.size() / 4 * size_t(channels));
    for (size_t i = 0, o = 0; i < rgba.size(); i += 4, o += size_t(channels)) {
        for (int c = 0; c < channels; ++c) out[o + size_t(c)] = rgba[i + size_t(c)];
    }
    return out;
}
#endif

// RGB floats with alpha 1 added.
std::vector<float> withOpaqueAlpha(const std::vector<float>& rgb) {
    std::vector<float> rgba(rgb.size() / 3 * 4);
    for (size_t i = 0, o = 0; i < rgb.size(); i += 3, o += 4) {
        rgba[o] = rgb[i];
        rgba[o + 1] = rgb[i + 1];
        rgba[o + 2] = rgb[i + 2];
        rgba[o + 3] = 1.0f;
    }
    return rgba;
}
}  // namespace

Texture2D::Texture2D(const Image& source, ColorSpace colorSpace, TextureFilter filter)
    : width_(source.width), height_(source.height) {
    static constexpr GLenum kLinear[] = {GL_R8, GL_RG8, GL_RGB8, GL_RGBA8};
    if (source.channels < 1 || source.channels > 4) {
        throw Error("Texture2D: unsupported channel count");
    }
    const bool widen = colorSpace == ColorSpace::Srgb && needsWidening(source);
    const Image widened = widen ? widenForSrgb(source) : Image{};
    const Image& image = widen ? widened : source;
    GLenum internalFormat = kLinear[image.channels - 1];
    if (colorSpace == ColorSpace::Srgb) {
        internalFormat = image.channels == 3 ? GL_SRGB8 : GL_SRGB8_ALPHA8;
    }
    const GLenum format = pixelFormatOf(internalFormat);
    glBindTexture(GL_TEXTURE_2D, texture_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internalFormat), image.width, image.height, 0, format,
                 GL_UNSIGNED_BYTE, image.pixels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    if (filter == TextureFilter::Trilinear) {
        // The texts call glGenerateMipmap here; the chain is made on the CPU instead, the same on
        // every GL (files/mip_chain.h says why).
        const std::vector<Image> levels = mipChain(image, colorSpace == ColorSpace::Srgb);
        for (size_t i = 0; i < levels.size(); ++i) {
            glTexImage2D(GL_TEXTURE_2D, GLint(i + 1), GLint(internalFormat), levels[i].width,
                         levels[i].height, 0, format, GL_UNSIGNED_BYTE, levels[i].pixels.data());
        }
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    } else {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    startGlWork();
}

Texture2D::Texture2D(const HdrImage& image)
    : width_(image.width),
      height_(image.height),
      internalFormat_(fitsHalfFloat(image) ? GL_RGB16F : GL_RGB32F) {
    glBindTexture(GL_TEXTURE_2D, texture_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internalFormat_), image.width, image.height, 0, GL_RGB,
                 GL_FLOAT, image.pixels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);  // the seam at u = 0 / 1
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    startGlWork();
}

Texture2D::Texture2D(int width, int height, GLenum internalFormat)
    : width_(width), height_(height), internalFormat_(internalFormat) {
    glBindTexture(GL_TEXTURE_2D, texture_.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internalFormat), width, height, 0,
                 pixelFormatOf(internalFormat), GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

std::vector<float> Texture2D::readFloats(int channels) const {
#ifdef PBR_WEBGL
    return firstChannels(readLevelRgba(GL_TEXTURE_2D, texture_.id(), 0, width_, height_), channels);
#else
    static constexpr GLenum kFormats[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
    std::vector<float> texels(size_t(width_) * size_t(height_) * size_t(channels));
    glBindTexture(GL_TEXTURE_2D, texture_.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, kFormats[channels - 1], GL_FLOAT, texels.data());
    return texels;
#endif
}

TextureCube::TextureCube(int size, int levels, GLenum internalFormat)
    : size_(size), levels_(levels), internalFormat_(internalFormat) {
    glBindTexture(GL_TEXTURE_CUBE_MAP, texture_.id());
    for (int level = 0; level < levels; ++level) {
        const int s = std::max(1, size >> level);
        for (int face = 0; face < 6; ++face) {
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + GLenum(face), level,
                         GLint(internalFormat), s, s, 0, pixelFormatOf(internalFormat), GL_FLOAT,
                         nullptr);
        }
    }
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER,
                    levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

void TextureCube::bind(int unit) const {
    glActiveTexture(GL_TEXTURE0 + GLenum(unit));
    glBindTexture(GL_TEXTURE_CUBE_MAP, texture_.id());
}

std::vector<float> TextureCube::readFace(int face, int level) const {
    const int s = std::max(1, size_ >> level);
#ifdef PBR_WEBGL
    return firstChannels(
        readLevelRgba(GL_TEXTURE_CUBE_MAP_POSITIVE_X + GLenum(face), texture_.id(), level, s, s),
        3);
#else
    std::vector<float> texels(size_t(s) * size_t(s) * 3);
    glBindTexture(GL_TEXTURE_CUBE_MAP, texture_.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X + GLenum(face), level, GL_RGB, GL_FLOAT,
                  texels.data());
    return texels;
#endif
}

void TextureCube::writeFace(int face, int level, const std::vector<float>& rgb) {
    const int s = std::max(1, size_ >> level);
    if (rgb.size() != size_t(s) * size_t(s) * 3) throw Error("TextureCube::writeFace: wrong size");
    // OpenGL ES uploads in the texture's own format
    const bool rgba = pixelFormatOf(internalFormat_) == GL_RGBA;
    const std::vector<float> expanded = rgba ? withOpaqueAlpha(rgb) : std::vector<float>();
    bind(0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + GLenum(face), level, 0, 0, s, s,
                    rgba ? GL_RGBA : GL_RGB, GL_FLOAT, rgba ? expanded.data() : rgb.data());
}

namespace {
std::vector<std::uint8_t> floatBytes(const std::vector<float>& values) {
    std::vector<std::uint8_t> bytes(values.size() * sizeof(float));
    std::memcpy(bytes.data(), values.data(), bytes.size());
    return bytes;
}

std::vector<std::uint8_t> toHalfBytes(const std::vector<float>& values) {
    std::vector<std::uint8_t> bytes(values.size() * 2);
    for (size_t i = 0; i < values.size(); ++i) {
        const std::uint16_t half = floatToHalf(values[i]);
        std::memcpy(&bytes[i * 2], &half, 2);
    }
    return bytes;
}

struct GlPixelFormat {
    GLenum internalFormat, format, type;
};
GlPixelFormat glPixelFormat(KtxFormat format) {
    switch (format) {
        case KtxFormat::RG16F:
            return {GL_RG16F, GL_RG, GL_HALF_FLOAT};
        case KtxFormat::RGB16F:
            return {GL_RGB16F, GL_RGB, GL_HALF_FLOAT};
        case KtxFormat::RGBA16F:
            return {GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT};
        case KtxFormat::RGBA32F:
            return {GL_RGBA32F, GL_RGBA, GL_FLOAT};
    }
    throw Error("unknown KTX format");
}
}  // namespace

KtxImage Texture2D::toKtx(KtxFormat format) const {
    KtxImage image{.format = format, .width = width_, .height = height_};
    std::vector<float> texels = readFloats(image.channels());
    image.images.push_back(image.bytesPerChannel() == 2 ? toHalfBytes(texels) : floatBytes(texels));
    return image;
}

Texture2D Texture2D::fromKtx(const KtxImage& image) {
    if (const auto problem = ktxShapeError(image, false)) throw Error(*problem);
    const GlPixelFormat gl = glPixelFormat(image.format);
    Texture2D texture(image.width, image.height, gl.internalFormat);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, gl.format, gl.type,
                    image.images[0].data());
    startGlWork();
    return texture;
}

KtxImage TextureCube::toKtx() const {
    const bool wide = internalFormat_ == kFloatRgb;
    KtxImage image{.format = wide ? KtxFormat::RGBA32F : KtxFormat::RGBA16F,
                   .width = size_,
                   .height = size_,
                   .faces = 6,
                   .levels = levels_};
    for (int level = 0; level < levels_; ++level) {
        for (int face = 0; face < 6; ++face) {
            const std::vector<float> rgba = withOpaqueAlpha(readFace(face, level));
            image.images.push_back(wide ? floatBytes(rgba) : toHalfBytes(rgba));
        }
    }
    return image;
}

TextureCube TextureCube::fromKtx(const KtxImage& image) {
    if (const auto problem = ktxShapeError(image, true)) throw Error(*problem);
    const GlPixelFormat gl = glPixelFormat(image.format);
    TextureCube cube(image.width, image.levels,
                     image.format == KtxFormat::RGBA32F ? kFloatRgb : kHalfFloatRgb);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int level = 0; level < image.levels; ++level) {
        const int s = std::max(1, image.width >> level);
        for (int face = 0; face < 6; ++face) {
            glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + GLenum(face), level, 0, 0, s, s,
                            gl.format, gl.type, image.images[size_t(level * 6 + face)].data());
        }
    }
    startGlWork();
    return cube;
}

Texture2D Texture2D::load(const std::filesystem::path& path, ColorSpace colorSpace,
                          TextureFilter filter) {
    return Texture2D(readImage(path), colorSpace, filter);
}

PbrTextures loadPbrTextures(const std::filesystem::path& dir, TextureFilter filter) {
    const MaterialFiles files = findMaterialFiles(dir);
    Image normal = readImage(files.normal);
    if (files.normalConvention == NormalConvention::DirectX && normal.channels >= 3) {
        // DirectX normal maps point green down: turn them into the OpenGL convention.
        for (size_t i = 1; i < normal.pixels.size(); i += size_t(normal.channels))
            normal.pixels[i] = std::uint8_t(255 - normal.pixels[i]);
    }
    Texture2D albedo = Texture2D::load(files.albedo, ColorSpace::Srgb, filter);
    Texture2D normalMap(normal, ColorSpace::Linear, filter);
    Texture2D metallic = Texture2D::load(files.metallic, ColorSpace::Linear, filter);
    Texture2D roughness = Texture2D::load(files.roughness, ColorSpace::Linear, filter);
    Texture2D ao = files.ao ? Texture2D::load(*files.ao, ColorSpace::Linear, filter)
                            : Texture2D(Image{1, 1, 1, {255}}, ColorSpace::Linear, filter);
    return {std::move(albedo), std::move(normalMap), std::move(metallic), std::move(roughness),
            std::move(ao)};
}

void PbrTextures::bind() const {
    albedo.bind(0);
    normal.bind(1);
    metallic.bind(2);
    roughness.bind(3);
    ao.bind(4);
}

void PbrTextures::setSamplers(Shader& shader) {
    shader.set("albedoMap", 0);
    shader.set("normalMap", 1);
    shader.set("metallicMap", 2);
    shader.set("roughnessMap", 3);
    shader.set("aoMap", 4);
}

void Texture2D::bind(int unit) const {
    glActiveTexture(GL_TEXTURE0 + GLenum(unit));
    glBindTexture(GL_TEXTURE_2D, texture_.id());
}

}  // namespace pbr
