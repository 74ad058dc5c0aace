#include "gl/gl.h"

namespace pbr {

GlObjectCensus takeGlObjectCensus() {
    // GL hands out names counting up from 1; no sample comes near this many of one kind.
    constexpr GLuint kHighestName = 4096;
    GlObjectCensus census;
    for (GLuint name = 1; name <= kHighestName; ++name) {
        census.textures += glIsTexture(name) ? 1 : 0;
        census.buffers += glIsBuffer(name) ? 1 : 0;
        census.vertexArrays += glIsVertexArray(name) ? 1 : 0;
        census.framebuffers += glIsFramebuffer(name) ? 1 : 0;
        census.renderbuffers += glIsRenderbuffer(name) ? 1 : 0;
        census.programs += glIsProgram(name) ? 1 : 0;
        census.shaders += glIsShader(name) ? 1 : 0;
        census.samplers += glIsSampler(name) ? 1 : 0;
    }
    return census;
}

std::string GlObjectCensus::describe() const {
    std::string text;
    auto add = [&text](int count, const char* noun) {
        if (count == 0) return;
        text += (text.empty() ? "" : ", ") + std::to_string(count) + " " + noun +
                (count == 1 ? "" : "s");
    };
    add(textures, "texture");
    add(buffers, "buffer");
    add(vertexArrays, "vertex array");
    add(framebuffers, "framebuffer");
    add(renderbuffers, "renderbuffer");
    add(programs, "program");
    add(shaders, "shader");
    add(samplers, "sampler");
    return text;
}

namespace detail {

GLuint& currentProgram() {
    static GLuint current = 0;
    return current;
}

GLuint ProgramKind::create() {
    return glCreateProgram();
}
void ProgramKind::destroy(GLuint id) {
    // A deleted program lives on while it is current: make it not current, so that it goes.
    if (id == currentProgram()) useProgram(0);
    glDeleteProgram(id);
}

}  // namespace detail

void useProgram(GLuint program) {
    if (program == detail::currentProgram()) return;
    glUseProgram(program);
    detail::currentProgram() = program;
}

void forgetCurrentProgram() {
    detail::currentProgram() = 0;
    glUseProgram(0);
}

SavedGlState::SavedGlState() {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
    glGetIntegerv(GL_VIEWPORT, viewport_);
    glGetIntegerv(GL_DEPTH_FUNC, &depthFunc_);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture2D_);
    glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &textureCube_);
    glActiveTexture(GLenum(activeTexture_));
    depthTest_ = glIsEnabled(GL_DEPTH_TEST);
    cullFace_ = glIsEnabled(GL_CULL_FACE);
    blend_ = glIsEnabled(GL_BLEND);
}

SavedGlState::~SavedGlState() {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFramebuffer_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFramebuffer_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    glDepthFunc(GLenum(depthFunc_));
    (depthTest_ ? glEnable : glDisable)(GL_DEPTH_TEST);
    (cullFace_ ? glEnable : glDisable)(GL_CULL_FACE);
    (blend_ ? glEnable : glDisable)(GL_BLEND);
    useProgram(GLuint(program_));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, GLuint(texture2D_));
    glBindTexture(GL_TEXTURE_CUBE_MAP, GLuint(textureCube_));
    glActiveTexture(GLenum(activeTexture_));
}

GLenum pixelFormatOf(GLenum internalFormat) {
    switch (internalFormat) {
        case GL_R8:
            return GL_RED;
        case GL_RG8:
        case GL_RG16F:
            return GL_RG;
        case GL_RGB8:
        case GL_SRGB8:
        case GL_RGB16F:
        case GL_RGB32F:
            return GL_RGB;
        default:
            return GL_RGBA;
    }
}

void finishGl() {
    glFinish();
    if (kWebGl) {
        GLint read = 0;
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        GLubyte pixel[4];
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(read));
    }
}

void startGlWork() {
    if (kWebGl) glFlush();
}

std::string glErrorName(GLenum error) {
    switch (error) {
        case GL_INVALID_ENUM:
            return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE:
            return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION:
            return "GL_INVALID_OPERATION";
        case GL_INVALID_FRAMEBUFFER_OPERATION:
            return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_OUT_OF_MEMORY:
            return "GL_OUT_OF_MEMORY";
        default:
            return "GL error " + std::to_string(error);
    }
}

}  // namespace pbr
