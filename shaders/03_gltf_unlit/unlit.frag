#version 330 core
// KHR_materials_unlit: colour = baseColorFactor x vertex colour x baseColorTexture, no lighting.
out vec4 FragColor;
in vec2 TexCoords;
in vec4 VertexColor;

uniform sampler2D baseColorTexture;  // sRGB texture (white 1x1 when the material has none)
uniform int alphaMode;               // 0 opaque, 1 mask, 2 blend
uniform float alphaCutoff;

#include "srgb.glsl"

void main()
{
    vec4 color = texture(baseColorTexture, TexCoords) * VertexColor;  // linear
    if (alphaMode == 1 && color.a < alphaCutoff)
        discard;
    // our framebuffer stores sRGB-encoded values, as the swapchain of the cookbook does
    FragColor = vec4(linearToSrgb(color.rgb), alphaMode == 2 ? color.a : 1.0);
}
