#include "gl/framebuffer.h"

#include <string>

#include "base/error.h"
#include "gl/mesh.h"
#include "gl/shader.h"

namespace pbr {

namespace {
// GL 3.3 turns sRGB encoding on and off (GL_FRAMEBUFFER_SRGB); OpenGL ES always encodes into an
// sRGB target, so there is nothing to switch.
void srgbEncoding(bool on) {
#ifdef PBR_WEBGL
    (void)on;
#else
    (on ? glEnable : glDisable)(GL_FRAMEBUFFER_SRGB);
#endif
}

std::string statusName(GLenum status) {
    switch (status) {
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
            return "incomplete attachment";
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
            return "missing attachment";
        case GL_FRAMEBUFFER_UNSUPPORTED:
            return "unsupported format combination";
        case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
            return "sample counts differ";
        default:
            return "status " + std::to_string(status);
    }
}

void attachStorage(GLuint framebuffer, GLuint color, GLuint depth, int samples, int width,
                   int height, bool srgb) {
    glBindRenderbuffer(GL_RENDERBUFFER, color);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8,
                                     width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH24_STENCIL8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth);
}
}  // namespace

void requireCompleteFramebuffer(const char* what) {
    const GLenum status = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        throw Error(std::string(what) + ": framebuffer incomplete (" + statusName(status) + ")");
    }
}

// In a browser, the resolved picture of an sRGB target is a texture (sampling it decodes), drawn to
// the canvas by present_srgb.frag, which encodes again.
struct RenderTarget::SrgbPresenter {
    GlTexture picture;
    Shader shader{"ibl/fullscreen.vert", "common/present_srgb.frag"};
    GpuMesh quad{pbr::quad()};
};

RenderTarget::~RenderTarget() = default;

RenderTarget::RenderTarget(int width, int height, int samples, bool srgb)
    : width_(width), height_(height), samples_(samples), srgb_(srgb) {
    GLint maxSamples = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    if (samples > maxSamples) {
        throw Error("--msaa " + std::to_string(samples) + ": this GL allows at most " +
                    std::to_string(maxSamples) + " samples");
    }
    attachStorage(resolved_.id(), resolvedColor_.id(), resolvedDepth_.id(), 0, width, height, srgb);
#ifdef PBR_WEBGL
    if (srgb) {
        presenter_ = std::make_unique<SrgbPresenter>();
        glBindTexture(GL_TEXTURE_2D, presenter_->picture.id());
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_SRGB8_ALPHA8, width, height);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glBindTexture(GL_TEXTURE_2D, 0);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                               presenter_->picture.id(), 0);
        presenter_->shader.set("picture", 0);
    }
#endif
    requireCompleteFramebuffer("render target");
    if (samples_ > 0) {
        attachStorage(multisampled_.id(), multisampledColor_.id(), multisampledDepth_.id(), samples,
                      width, height, srgb);
        requireCompleteFramebuffer("multisampled render target");
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void RenderTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, samples_ > 0 ? multisampled_.id() : resolved_.id());
    glViewport(0, 0, width_, height_);
    if (srgb_) srgbEncoding(true);  // on only while an sRGB target is drawn into
}

void RenderTarget::resolve() const {
    if (srgb_) srgbEncoding(false);  // the stored bytes, as they are
    if (samples_ == 0) return;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled_.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_.id());
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
}

void RenderTarget::bindResolved() const {
    if (srgb_) srgbEncoding(false);
    glBindFramebuffer(GL_FRAMEBUFFER, resolved_.id());
    glViewport(0, 0, width_, height_);
}

void RenderTarget::blitToDefault(int width, int height) const {
    if (presenter_) {
        const SavedGlState saved;
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, width, height);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        glDisable(GL_BLEND);
        presenter_->shader.use();
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, presenter_->picture.id());
        presenter_->quad.draw();
        return;
    }
    if (srgb_) srgbEncoding(false);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved_.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

Image RenderTarget::readPixels() const {
    // Read as RGBA, the one format every GL (OpenGL ES included) reads an RGBA8 buffer in.
    std::vector<std::uint8_t> rgba(size_t(width_) * size_t(height_) * 4);
    if (srgb_) srgbEncoding(false);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved_.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    // RGB, each row moved to its place: GL's rows are bottom-up, PNG's top-down
    Image image{width_, height_, 3, std::vector<std::uint8_t>(rgba.size() / 4 * 3)};
    for (int y = 0; y < height_; ++y) {
        const std::uint8_t* from = rgba.data() + size_t(height_ - 1 - y) * size_t(width_) * 4;
        std::uint8_t* to = image.pixels.data() + size_t(y) * size_t(width_) * 3;
        for (int x = 0; x < width_; ++x, from += 4, to += 3) {
            to[0] = from[0];
            to[1] = from[1];
            to[2] = from[2];
        }
    }
    return image;
}

}  // namespace pbr
