#include "gl/light_buffer.h"

#include <cstddef>
#include <string>

#include "base/error.h"

namespace pbr {

LightBuffer::LightBuffer() {
    glBindBuffer(GL_UNIFORM_BUFFER, buffer_.id());
    glBufferData(GL_UNIFORM_BUFFER, sizeof(LightBlock), nullptr, GL_DYNAMIC_DRAW);
    glBindBufferBase(GL_UNIFORM_BUFFER, kBinding, buffer_.id());
}

void LightBuffer::upload(std::span<const PackedLight> lights) {
    if (lights.size() > size_t(LightBlock::kMaxLights)) {
        throw Error(std::to_string(lights.size()) + " lights: the light block holds at most " +
                    std::to_string(LightBlock::kMaxLights));
    }
    // the count, then only the lights in use
    const std::int32_t header[4] = {std::int32_t(lights.size()), 0, 0, 0};
    glBindBuffer(GL_UNIFORM_BUFFER, buffer_.id());
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof header, header);
    if (!lights.empty()) {
        glBufferSubData(GL_UNIFORM_BUFFER, GLintptr(offsetof(LightBlock, lights)),
                        GLsizeiptr(lights.size_bytes()), lights.data());
    }
    glBindBufferBase(GL_UNIFORM_BUFFER, kBinding, buffer_.id());
}

void LightBuffer::attach(GLuint program) {
    const GLuint index = glGetUniformBlockIndex(program, "LightBlock");
    if (index == GL_INVALID_INDEX) throw Error("the shader has no uniform block LightBlock");
    glUniformBlockBinding(program, index, kBinding);
}

}  // namespace pbr
