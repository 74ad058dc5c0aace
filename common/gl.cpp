#include "gl.h"

namespace pbr {

namespace {
int liveObjects = 0;
}

int liveGlObjects() { return liveObjects; }

namespace detail {

void countGlObject(int delta) { liveObjects += delta; }

GLuint TextureKind::create() {
    GLuint id = 0;
    glGenTextures(1, &id);
    return id;
}
void TextureKind::destroy(GLuint id) { glDeleteTextures(1, &id); }

GLuint BufferKind::create() {
    GLuint id = 0;
    glGenBuffers(1, &id);
    return id;
}
void BufferKind::destroy(GLuint id) { glDeleteBuffers(1, &id); }

GLuint VertexArrayKind::create() {
    GLuint id = 0;
    glGenVertexArrays(1, &id);
    return id;
}
void VertexArrayKind::destroy(GLuint id) { glDeleteVertexArrays(1, &id); }

GLuint FramebufferKind::create() {
    GLuint id = 0;
    glGenFramebuffers(1, &id);
    return id;
}
void FramebufferKind::destroy(GLuint id) { glDeleteFramebuffers(1, &id); }

GLuint RenderbufferKind::create() {
    GLuint id = 0;
    glGenRenderbuffers(1, &id);
    return id;
}
void RenderbufferKind::destroy(GLuint id) { glDeleteRenderbuffers(1, &id); }

GLuint ProgramKind::create() { return glCreateProgram(); }
void ProgramKind::destroy(GLuint id) { glDeleteProgram(id); }

}  // namespace detail

std::string glErrorName(GLenum error) {
    switch (error) {
        case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
        case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
        default: return "GL error " + std::to_string(error);
    }
}

}  // namespace pbr
