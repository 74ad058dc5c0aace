#version 330 core
// Draws the unit cube around a capture camera: the direction to each fragment is its position.
layout (location = 0) in vec3 aPos;

out vec3 WorldPos;

uniform mat4 projection;
uniform mat4 view;

void main()
{
    WorldPos = aPos;
    gl_Position = projection * view * vec4(aPos, 1.0);
}
