#include "gl/mesh.h"

#include <cmath>
#include <numbers>

#include "base/error.h"

namespace pbr {

namespace {

// Vertices shared by both sphere topologies.
MeshData sphereVertices(int xSegments, int ySegments) {
    if (xSegments < 3 || ySegments < 2) throw Error("uvSphere: needs at least 3 x 2 segments");
    constexpr float pi = std::numbers::pi_v<float>;
    MeshData mesh;
    const size_t count = size_t(xSegments + 1) * size_t(ySegments + 1);
    mesh.positions.reserve(count);
    mesh.normals.reserve(count);
    mesh.uvs.reserve(count);
    mesh.tangents.reserve(count);
    for (int y = 0; y <= ySegments; ++y) {
        for (int x = 0; x <= xSegments; ++x) {
            const float u = float(x) / float(xSegments);
            const float v = float(y) / float(ySegments);
            const float phi = u * 2.0f * pi;
            const float theta = v * pi;
            const glm::vec3 p(std::cos(phi) * std::sin(theta), std::cos(theta),
                              std::sin(phi) * std::sin(theta));
            mesh.positions.push_back(p);
            mesh.normals.push_back(p);
            mesh.uvs.push_back({u, v});
            // dP/du without the sin(theta) factor, so it stays defined at the poles.
            const glm::vec3 tangent(-std::sin(phi), 0.0f, std::cos(phi));
            // The image's top row lies at v = 0, the north pole; cross(N, T) points south: w = -1.
            mesh.tangents.push_back(glm::vec4(tangent, -1.0f));
        }
    }
    return mesh;
}

}  // namespace

MeshData uvSphere(int xSegments, int ySegments) {
    MeshData mesh = sphereVertices(xSegments, ySegments);
    mesh.primitive = Primitive::TriangleStrip;
    const std::uint32_t rowLength = std::uint32_t(xSegments) + 1;
    mesh.indices.reserve(1 + size_t(2) * rowLength * size_t(ySegments));
    // Even rows run left to right, odd rows right to left, so one strip covers the sphere, and
    // each quad is split along the same diagonal as in the text's strip. The text's strip is
    // clockwise seen from outside; this one opens with its first vertex twice (one empty
    // triangle), which shifts GL's alternation by one, so every triangle after it is
    // counter-clockwise (GL's default front face) and the samples may cull back faces.
    mesh.indices.push_back(0);
    for (int y = 0; y < ySegments; ++y) {
        const std::uint32_t top = std::uint32_t(y) * rowLength;
        const std::uint32_t bottom = top + rowLength;
        if (y % 2 == 0) {
            for (int x = 0; x <= xSegments; ++x) {
                mesh.indices.push_back(top + std::uint32_t(x));
                mesh.indices.push_back(bottom + std::uint32_t(x));
            }
        } else {
            for (int x = xSegments; x >= 0; --x) {
                mesh.indices.push_back(bottom + std::uint32_t(x));
                mesh.indices.push_back(top + std::uint32_t(x));
            }
        }
    }
    return mesh;
}

MeshData uvSphereTriangles(int xSegments, int ySegments) {
    MeshData mesh = sphereVertices(xSegments, ySegments);
    mesh.primitive = Primitive::Triangles;
    const std::uint32_t rowLength = std::uint32_t(xSegments) + 1;
    for (int y = 0; y < ySegments; ++y) {
        for (int x = 0; x < xSegments; ++x) {
            const std::uint32_t a = std::uint32_t(y) * rowLength + std::uint32_t(x);
            const std::uint32_t b = a + rowLength;
            // Counter-clockwise seen from outside, so back-face culling works on the list.
            mesh.indices.insert(mesh.indices.end(), {a, a + 1, b, a + 1, b + 1, b});
        }
    }
    return mesh;
}

MeshData cube() {
    MeshData mesh;
    struct Face {
        glm::vec3 normal, tangent;
    };
    const Face faces[] = {
        {{0, 0, 1}, {1, 0, 0}},  {{0, 0, -1}, {-1, 0, 0}}, {{1, 0, 0}, {0, 0, -1}},
        {{-1, 0, 0}, {0, 0, 1}}, {{0, 1, 0}, {1, 0, 0}},   {{0, -1, 0}, {1, 0, 0}},
    };
    for (const Face& face : faces) {
        const glm::vec3 bitangent = glm::cross(face.normal, face.tangent);
        const std::uint32_t base = std::uint32_t(mesh.positions.size());
        // corners in face space (-1..1), counter-clockwise seen from outside
        const glm::vec2 corners[] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const glm::vec2& s : corners) {
            mesh.positions.push_back(face.normal + face.tangent * s.x + bitangent * s.y);
            mesh.normals.push_back(face.normal);
            mesh.uvs.push_back({s.x * 0.5f + 0.5f, 0.5f - s.y * 0.5f});  // v = 0 along the top edge
            mesh.tangents.push_back(glm::vec4(face.tangent, 1.0f));  // cross(N, T) points up: w = 1
        }
        mesh.indices.insert(mesh.indices.end(),
                            {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return mesh;
}

MeshData quad() {
    MeshData mesh;
    mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    mesh.normals.assign(4, {0, 0, 1});
    mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    mesh.tangents.assign(4, {1, 0, 0, 1});
    mesh.indices = {0, 1, 2, 0, 2, 3};
    return mesh;
}

GpuMesh::GpuMesh(const MeshData& data)
    : indexCount_(GLsizei(data.indices.size())),
      mode_(data.primitive == Primitive::TriangleStrip ? GL_TRIANGLE_STRIP : GL_TRIANGLES) {
    const size_t count = data.positions.size();
    if (data.normals.size() != count || data.uvs.size() != count || data.tangents.size() != count ||
        (!data.colors.empty() && data.colors.size() != count) ||
        (!data.uvs1.empty() && data.uvs1.size() != count)) {
        throw Error("GpuMesh: attribute arrays differ in length");
    }
    for (std::uint32_t index : data.indices) {
        if (index >= count) throw Error("GpuMesh: index out of range");
    }
    // Interleaved: position, uv, normal, tangent (12 floats a vertex), then the colour (4 more)
    // and the second uv set (2 more) only when the mesh has them: the grid samples are
    // vertex-bound, every byte counts.
    hasColors_ = !data.colors.empty();
    hasUv1_ = !data.uvs1.empty();
    const size_t stride = 12 + (hasColors_ ? 4 : 0) + (hasUv1_ ? 2 : 0);
    std::vector<float> vertices;
    vertices.reserve(count * stride);
    for (size_t i = 0; i < count; ++i) {
        const glm::vec3& p = data.positions[i];
        const glm::vec2& uv = data.uvs[i];
        const glm::vec3& n = data.normals[i];
        const glm::vec4& t = data.tangents[i];
        vertices.insert(vertices.end(),
                        {p.x, p.y, p.z, uv.x, uv.y, n.x, n.y, n.z, t.x, t.y, t.z, t.w});
        if (hasColors_) {
            const glm::vec4& c = data.colors[i];
            vertices.insert(vertices.end(), {c.r, c.g, c.b, c.a});
        }
        if (hasUv1_) vertices.insert(vertices.end(), {data.uvs1[i].x, data.uvs1[i].y});
    }
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(float)), vertices.data(),
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(data.indices.size() * sizeof(std::uint32_t)),
                 data.indices.data(), GL_STATIC_DRAW);
    auto attribute = [stride](GLuint location, GLint size, size_t offset) {
        glEnableVertexAttribArray(location);
        glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, GLsizei(stride * sizeof(float)),
                              reinterpret_cast<const void*>(offset * sizeof(float)));
    };
    attribute(kAttribPosition, 3, 0);
    attribute(kAttribUv, 2, 3);
    attribute(kAttribNormal, 3, 5);
    attribute(kAttribTangent, 4, 8);
    if (hasColors_) attribute(kAttribColor, 4, 12);
    if (hasUv1_) attribute(kAttribUv1, 2, hasColors_ ? 16 : 12);
    glBindVertexArray(0);
}

void GpuMesh::draw() const {
    // Without a colour array the shader reads the current generic value: make it white.
    if (!hasColors_) glVertexAttrib4f(kAttribColor, 1.0f, 1.0f, 1.0f, 1.0f);
    if (!hasUv1_) glVertexAttrib2f(kAttribUv1, 0.0f, 0.0f);  // glTF: a missing set reads (0, 0)
    glBindVertexArray(vao_.id());
    glDrawElements(mode_, indexCount_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace pbr
