#include "gl.h"

namespace pbr {

namespace {
int liveObjects = 0;
}

int liveGlObjects() {
    return liveObjects;
}

namespace detail {

void countGlObject(int delta) {
    liveObjects += delta;
}

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
