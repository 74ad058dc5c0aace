#pragma once
// The framebuffer every frame is drawn into, windowed or headless: a multisampled one when MSAA
// is on (resolved by a blit), and a single-sample RGBA8 one that is read back or shown. Both
// paths resolve the same way, so a window's F12 screenshot matches a headless render.
//
// Most samples encode sRGB in their shaders, as the texts do, into plain RGBA8. A target made with
// `srgb` stores sRGB8_ALPHA8 instead and draws with GL_FRAMEBUFFER_SRGB on: the shader writes
// linear values, and the GL encodes them and blends in linear light (03's BLEND materials). The
// resolve, the read-back and the blit run with the conversion off, so the stored bytes travel as
// they are, the same way as for every other sample. In a browser the blit cannot keep them (WebGL 2
// decodes an sRGB source into the canvas), so there an sRGB target is shown by a draw that
// encodes again (shaders/common/present_srgb.frag).
#include <memory>

#include "files/image.h"
#include "gl/gl.h"

namespace pbr {

class RenderTarget {
public:
    // samples 0: no multisampling. Throws Error naming the status when incomplete.
    RenderTarget(int width, int height, int samples, bool srgb = false);
    ~RenderTarget();

    void bind() const;     // the framebuffer to draw into, with the viewport set
    void resolve() const;  // multisampled -> single-sample (no-op without MSAA)
    // The resolved picture to draw over (the live panel), its bytes as they are (no sRGB
    // encoding), with the viewport set.
    void bindResolved() const;
    void blitToDefault(int width, int height) const;  // the resolved picture to the window
    Image readPixels() const;                         // the resolved picture, RGB, top row first

    int width() const { return width_; }
    int height() const { return height_; }
    int samples() const { return samples_; }
    bool srgb() const { return srgb_; }

private:
    int width_, height_, samples_;
    bool srgb_;
    GlFramebuffer resolved_;
    GlRenderbuffer resolvedColor_, resolvedDepth_;
    GlFramebuffer multisampled_;
    GlRenderbuffer multisampledColor_, multisampledDepth_;
    struct SrgbPresenter;  // a browser's sRGB target: its picture as a texture, and the draw
    std::unique_ptr<SrgbPresenter> presenter_;
};

// Throws Error("<what>: framebuffer incomplete (<status>)") unless the bound draw framebuffer is
// complete.
void requireCompleteFramebuffer(const char* what);

}  // namespace pbr
