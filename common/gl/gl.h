#pragma once
// The OpenGL loader (glad 2, generated at configure time) and move-only owners for GL objects.
// No sample calls glGen*/glDelete* by hand: it holds one of these and the destructor deletes.
//
// PBR_WEBGL is the one switch between the two GLs the suite runs on: desktop OpenGL 3.3 core,
// and WebGL 2 (OpenGL ES 3.0) in the browser build (cmake/Web.cmake). Only common/ looks at it;
// what WebGL 2 lacks (glGetTexImage, KHR_debug, seamless-cube and sRGB-framebuffer switches, RGB
// float render targets) is handled beside each use.
#ifdef __EMSCRIPTEN__
#define PBR_WEBGL 1
#include <glad/gles2.h>
#else
#include <glad/gl.h>
#endif

#include <string>
#include <utility>

namespace pbr {

#ifdef PBR_WEBGL
inline constexpr bool kWebGl = true;
#else
inline constexpr bool kWebGl = false;
#endif

// The float formats of the IBL maps' render targets: RGB on desktop GL; RGBA on WebGL 2, where
// the RGB float formats cannot be rendered into (nor their mip chains made).
inline constexpr GLenum kHalfFloatRgb = kWebGl ? GL_RGBA16F : GL_RGB16F;
inline constexpr GLenum kFloatRgb = kWebGl ? GL_RGBA32F : GL_RGB32F;

// The format (GL_RED, GL_RG, GL_RGB, GL_RGBA) that goes with an internal format in uploads and
// read-backs (OpenGL ES requires the match).
GLenum pixelFormatOf(GLenum internalFormat);

// The GL objects alive in the current context, found by asking GL about every name up to a
// bound (glIsTexture, glIsBuffer, ...): independent of how they were made, so a leak through a
// raw glGen* call shows too.
struct GlObjectCensus {
    int textures = 0, buffers = 0, vertexArrays = 0, framebuffers = 0, renderbuffers = 0,
        programs = 0, shaders = 0, samplers = 0;
    int total() const {
        return textures + buffers + vertexArrays + framebuffers + renderbuffers + programs +
               shaders + samplers;
    }
    std::string describe() const;  // "2 textures, 1 buffer"; empty when none
};
GlObjectCensus takeGlObjectCensus();

namespace detail {

// Objects made and deleted in the glGen*(n, ids) / glDelete*(n, ids) style; the template
// arguments are glad's function pointers.
template <auto& generate, auto& remove>
struct NamedKind {
    static GLuint create() {
        GLuint id = 0;
        generate(1, &id);
        return id;
    }
    static void destroy(GLuint id) { remove(1, &id); }
};
struct ProgramKind {
    static GLuint create();
    static void destroy(GLuint id);
};
GLuint& currentProgram();  // what useProgram() last made current
}  // namespace detail

// Owns one GL object name; created on construction, deleted on destruction, moved, never copied.
template <class Kind>
class GlObject {
public:
    GlObject() : id_(Kind::create()) {}
    ~GlObject() { reset(); }
    GlObject(GlObject&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    GlObject& operator=(GlObject&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;

    GLuint id() const { return id_; }

private:
    void reset() {
        if (id_ != 0) {
            Kind::destroy(id_);
            id_ = 0;
        }
    }
    GLuint id_ = 0;
};

using GlTexture = GlObject<detail::NamedKind<glGenTextures, glDeleteTextures>>;
using GlBuffer = GlObject<detail::NamedKind<glGenBuffers, glDeleteBuffers>>;
using GlVertexArray = GlObject<detail::NamedKind<glGenVertexArrays, glDeleteVertexArrays>>;
using GlFramebuffer = GlObject<detail::NamedKind<glGenFramebuffers, glDeleteFramebuffers>>;
using GlRenderbuffer = GlObject<detail::NamedKind<glGenRenderbuffers, glDeleteRenderbuffers>>;
using GlSampler = GlObject<detail::NamedKind<glGenSamplers, glDeleteSamplers>>;
using GlProgram = GlObject<detail::ProgramKind>;

// Returns once the GL has done all the work given to it: glFinish, and in a browser (whose
// glFinish waits for nothing) a pixel read back as well, for the timings of --benchmark.
void finishGl();

// In a browser, hands the GL what it was given so far (glFlush), without waiting for it: there
// the GL runs in another process and leaves uploads for the first draw, so a page that decodes
// textures one after the other has each uploaded (and its mipmaps made) while it decodes the
// next. 09's first frame came 0.2-0.3 s sooner (1.39-1.51 s against 1.61-1.81 s, 2026-12-05).
// Natively it does nothing: the GL runs in the program's own process there.
void startGlWork();

// "GL_INVALID_OPERATION" for 0x0502, and so on.
std::string glErrorName(GLenum error);

// Makes `program` the current one, skipping the call when it already is (a uniform upload binds
// its program every time). Every glUseProgram of the suite goes through here, so the record of the
// current program is right; a new context starts with forgetCurrentProgram().
void useProgram(GLuint program);
void forgetCurrentProgram();

// Saves the GL state a pass changes and restores it when it goes out of scope: the draw and read
// framebuffers, the viewport, depth test and depth function, face culling, blending, the program,
// the active texture unit and unit 0's 2D and cube-map bindings. The IBL precomputation and the
// skybox leave the caller's state as they found it.
class SavedGlState {
public:
    SavedGlState();
    ~SavedGlState();
    SavedGlState(const SavedGlState&) = delete;
    SavedGlState& operator=(const SavedGlState&) = delete;

private:
    GLint drawFramebuffer_ = 0, readFramebuffer_ = 0, viewport_[4] = {}, depthFunc_ = 0,
          program_ = 0, activeTexture_ = 0, texture2D_ = 0, textureCube_ = 0;
    GLboolean depthTest_ = GL_FALSE, cullFace_ = GL_FALSE, blend_ = GL_FALSE;
};

}  // namespace pbr
