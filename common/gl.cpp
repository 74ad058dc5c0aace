#include "gl.h"

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
    return text;
}

namespace detail {

GLuint ProgramKind::create() {
    return glCreateProgram();
}
void ProgramKind::destroy(GLuint id) {
    glDeleteProgram(id);
}

}  // namespace detail

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
