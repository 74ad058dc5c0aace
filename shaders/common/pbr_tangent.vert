#version 330 core
// The vertex stage of the textured samples (02, 05 --textured): pbr.vert plus the tangent frame.
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec2 aTexCoords;
layout (location = 2) in vec3 aNormal;
layout (location = 3) in vec4 aTangent;

out vec2 TexCoords;
out vec3 WorldPos;
out vec3 Normal;
out vec4 Tangent;

uniform mat4 projection;
uniform mat4 view;
uniform mat4 model;
uniform mat3 normalMatrix;

void main()
{
    TexCoords = aTexCoords;
    WorldPos = vec3(model * vec4(aPos, 1.0));
    Normal = normalMatrix * aNormal;
    Tangent = vec4(mat3(model) * aTangent.xyz, aTangent.w);  // tangents follow the surface
    gl_Position = projection * view * vec4(WorldPos, 1.0);
}
