#version 330 core
// KHR_materials_unlit: colour = baseColorFactor x vertex colour x baseColorTexture, no lighting.
out vec4 FragColor;
in vec2 TexCoords;
in vec4 VertexColor;

uniform sampler2D baseColorTexture;  // sRGB texture (white 1x1 when the material has none)
uniform int alphaMode;               // 0 opaque, 1 mask, 2 blend
uniform float alphaCutoff;

void main()
{
    vec4 color = texture(baseColorTexture, TexCoords) * VertexColor;  // linear
    if (alphaMode == 1 && color.a < alphaCutoff)
        discard;
    // Linear out: the render target is sRGB (as the cookbook's swapchain is), so the GL encodes,
    // and blends BLEND materials in linear light before it does.
    FragColor = vec4(color.rgb, alphaMode == 2 ? color.a : 1.0);
}
