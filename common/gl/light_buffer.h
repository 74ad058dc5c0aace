#pragma once
// The GL side of sample 09's light block (common/math/light_block.h): one uniform buffer.
#include <span>

#include "gl/gl.h"
#include "math/light_block.h"

namespace pbr {

// The block's GL buffer: `upload` copies the lights (throws Error beyond kMaxLights) and binds
// the buffer to binding point `binding`, which `attach` ties to a program's "LightBlock".
class LightBuffer {
public:
    static constexpr GLuint kBinding = 0;
    LightBuffer();
    void upload(std::span<const PackedLight> lights);
    static void attach(GLuint program);

private:
    GlBuffer buffer_;
};

}  // namespace pbr
