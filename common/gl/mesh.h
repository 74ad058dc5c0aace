#pragma once
// Geometry as plain data (MeshData: built and tested without a GL context) and the GPU mesh that
// uploads it (GpuMesh: one VAO, one interleaved VBO, one index buffer).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "gl/gl.h"

namespace pbr {

enum class Primitive { Triangles, TriangleStrip };

struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    // xyz: unit tangent along +u (dP/du). w: handedness, chosen so that the bitangent
    // B = w * cross(normal, tangent) points to the top of the texture image as it lies on the
    // surface, the way the green channel of an OpenGL-convention (+Y) normal map points. The suite
    // uploads images top row first (row 0 at v = 0), as the tutorial does.
    std::vector<glm::vec4> tangents;
    std::vector<glm::vec4> colors;  // linear RGBA per vertex; empty means white
    std::vector<glm::vec2> uvs1;    // a second texture coordinate set (glTF TEXCOORD_1); may be empty
    std::vector<std::uint32_t> indices;
    Primitive primitive = Primitive::Triangles;
};

// The tutorial's UV sphere: unit radius, (xSegments+1) x (ySegments+1) vertices, uv = (x/X, y/Y),
// normal = position, y = cos(v * pi) (v = 0 at the north pole), one indexed triangle strip that
// snakes row by row: the text's 2 * (X+1) * Y indices (8,320 for 64 x 64) after one more, the
// first vertex repeated, which makes every triangle counter-clockwise seen from outside (the
// text's are clockwise, drawn without culling) while the quads keep the text's diagonals, so the
// pictures stay the same and back faces can be culled.
MeshData uvSphere(int xSegments = 64, int ySegments = 64);
// The same sphere as an indexed triangle list (6 * X * Y indices), counter-clockwise seen from
// outside; the degenerate triangles at the poles are kept so the count stays regular.
MeshData uvSphereTriangles(int xSegments = 64, int ySegments = 64);
// Axis-aligned cube from -1 to 1, 24 vertices (flat normals), counter-clockwise outside; each
// face shows a texture upright (v = 0 along its top edge).
MeshData cube();
// A quad in the XY plane from -1 to 1 facing +Z, uv (0,0) at the bottom left: for full-screen
// passes.
MeshData quad();

// Vertex attribute locations every shader of the suite uses.
enum VertexAttribute : GLuint {
    kAttribPosition = 0,
    kAttribUv = 1,
    kAttribNormal = 2,
    kAttribTangent = 3,
    kAttribColor = 4,
    kAttribUv1 = 5,
};

class GpuMesh {
public:
    explicit GpuMesh(const MeshData& data);
    void draw() const;
    GLsizei indexCount() const { return indexCount_; }

private:
    GlVertexArray vao_;
    GlBuffer vertices_;
    GlBuffer indices_;
    GLsizei indexCount_ = 0;
    GLenum mode_ = GL_TRIANGLES;
    bool hasColors_ = false;
    bool hasUv1_ = false;
};

}  // namespace pbr
