#version 330 core
// The environment behind everything: the cube follows the camera's rotation only, and its depth
// is forced to 1 (xyww) so it passes LEQUAL exactly where nothing else was drawn.
layout (location = 0) in vec3 aPos;

out vec3 WorldPos;

uniform mat4 projection;
uniform mat4 view;

void main()
{
    WorldPos = aPos;
    vec4 clipPos = projection * mat4(mat3(view)) * vec4(aPos, 1.0);
    gl_Position = clipPos.xyww;
}
