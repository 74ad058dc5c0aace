#version 330 core
// glTF unlit: the vertex colour is multiplied by the base colour factor here, once per vertex,
// as the cookbook does.
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec2 aTexCoords;
layout (location = 4) in vec4 aColor;  // COLOR_0; white when the file has none

out vec2 TexCoords;
out vec4 VertexColor;

uniform mat4 projection;
uniform mat4 view;
uniform mat4 model;
uniform vec4 baseColorFactor;

void main()
{
    TexCoords = aTexCoords;
    VertexColor = aColor * baseColorFactor;
    gl_Position = projection * view * model * vec4(aPos, 1.0);
}
