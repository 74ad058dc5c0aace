#version 330 core
// A quad over the whole viewport; TexCoords (0,0) at the bottom left, texel centres at (i+0.5)/N.
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec2 aTexCoords;

out vec2 TexCoords;

void main()
{
    TexCoords = aTexCoords;
    gl_Position = vec4(aPos, 1.0);
}
