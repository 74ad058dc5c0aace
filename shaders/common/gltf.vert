#version 330 core
// The vertex stage of the glTF samples (07, 08): every attribute a glTF primitive may carry.
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec2 aTexCoords0;
layout (location = 2) in vec3 aNormal;
layout (location = 3) in vec4 aTangent;
layout (location = 4) in vec4 aColor;       // COLOR_0; white when the mesh has none
layout (location = 5) in vec2 aTexCoords1;  // TEXCOORD_1; (0, 0) when the mesh has none

out vec3 WorldPos;
out vec3 Normal;
out vec4 Tangent;
out vec2 TexCoords0;
out vec2 TexCoords1;
out vec4 VertexColor;

uniform mat4 projection;
uniform mat4 view;
uniform mat4 model;
uniform mat3 normalMatrix;

void main()
{
    WorldPos = vec3(model * vec4(aPos, 1.0));
    Normal = normalMatrix * aNormal;
    // A mirroring transform (negative determinant) turns the bitangent cross(N, T) around:
    // the handedness turns with it, or a normal map's green would point the wrong way.
    float mirrored = determinant(mat3(model)) < 0.0 ? -1.0 : 1.0;
    Tangent = vec4(mat3(model) * aTangent.xyz, aTangent.w * mirrored);
    TexCoords0 = aTexCoords0;
    TexCoords1 = aTexCoords1;
    VertexColor = aColor;
    gl_Position = projection * view * vec4(WorldPos, 1.0);
}
