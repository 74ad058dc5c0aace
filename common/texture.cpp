#include "texture.h"

#include "error.h"

namespace pbr {

Texture2D::Texture2D(const Image& image, ColorSpace colorSpace)
    : width_(image.width), height_(image.height) {
    static constexpr GLenum kFormats[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
    if (image.channels < 1 || image.channels > 4)
        throw Error("Texture2D: unsupported channel count");
    const GLenum format = kFormats[image.channels - 1];
    GLenum internalFormat = format == GL_RED   ? GL_R8
                            : format == GL_RG  ? GL_RG8
                            : format == GL_RGB ? GL_RGB8
                                               : GL_RGBA8;
    if (colorSpace == ColorSpace::Srgb) {
        if (image.channels < 3) throw Error("Texture2D: sRGB needs an RGB or RGBA image");
        internalFormat = image.channels == 3 ? GL_SRGB8 : GL_SRGB8_ALPHA8;
    }
    glBindTexture(GL_TEXTURE_2D, texture_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internalFormat), image.width, image.height, 0, format,
                 GL_UNSIGNED_BYTE, image.pixels.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

Texture2D Texture2D::load(const std::filesystem::path& path, ColorSpace colorSpace) {
    return Texture2D(readImage(path), colorSpace);
}

void Texture2D::bind(int unit) const {
    glActiveTexture(GL_TEXTURE0 + GLenum(unit));
    glBindTexture(GL_TEXTURE_2D, texture_.id());
}

}  // namespace pbr
