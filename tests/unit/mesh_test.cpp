#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesh.h"

namespace pbr {
namespace {

TEST(Sphere, CountsAreTheTutorials) {
    const MeshData sphere = uvSphere(64, 64);
    EXPECT_EQ(sphere.primitive, Primitive::TriangleStrip);
    EXPECT_EQ(sphere.positions.size(), 65u * 65u);
    EXPECT_EQ(sphere.normals.size(), sphere.positions.size());
    EXPECT_EQ(sphere.uvs.size(), sphere.positions.size());
    EXPECT_EQ(sphere.tangents.size(), sphere.positions.size());
    EXPECT_EQ(sphere.indices.size(), 8320u);  // 64 rows of 2 * 65
}

TEST(Sphere, VerticesAreOnTheUnitSphereWithOutwardUnitNormals) {
    const MeshData sphere = uvSphere(64, 64);
    for (size_t i = 0; i < sphere.positions.size(); ++i) {
        EXPECT_NEAR(glm::length(sphere.positions[i]), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::length(sphere.normals[i]), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::distance(sphere.normals[i], sphere.positions[i]), 0.0f, 1e-6f);
    }
    // v = 0 is the north pole, v = 1 the south pole
    EXPECT_NEAR(sphere.positions.front().y, 1.0f, 1e-6f);
    EXPECT_NEAR(sphere.positions.back().y, -1.0f, 1e-6f);
}

TEST(Sphere, UvsAreXOver64AndYOver64) {
    const MeshData sphere = uvSphere(64, 64);
    for (int y = 0; y <= 64; ++y) {
        for (int x = 0; x <= 64; ++x) {
            const glm::vec2 uv = sphere.uvs[size_t(y * 65 + x)];
            EXPECT_FLOAT_EQ(uv.x, float(x) / 64.0f);
            EXPECT_FLOAT_EQ(uv.y, float(y) / 64.0f);
            EXPECT_GE(uv.x, 0.0f);
            EXPECT_LE(uv.y, 1.0f);
        }
    }
}

TEST(Sphere, TangentsAreUnitOrthogonalAndFollowTheUvs) {
    const MeshData sphere = uvSphere(64, 64);
    for (int y = 0; y <= 64; ++y) {
        for (int x = 0; x <= 64; ++x) {
            const size_t i = size_t(y * 65 + x);
            const glm::vec3 t(sphere.tangents[i]);
            const glm::vec3 n = sphere.normals[i];
            EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
            EXPECT_NEAR(glm::dot(t, n), 0.0f, 1e-5f);
            EXPECT_EQ(std::abs(sphere.tangents[i].w), 1.0f);
            if (y == 0 || y == 64 || x == 64) continue;  // finite differences need neighbours
            // The tangent points the way u grows; w * cross(N, T) to the image's top, which is
            // the way v shrinks (row 0 of the image lies at v = 0).
            const glm::vec3 dPdu = sphere.positions[i + 1] - sphere.positions[i];
            const glm::vec3 dPdv = sphere.positions[i + 65] - sphere.positions[i];
            EXPECT_GT(glm::dot(t, glm::normalize(dPdu)), 0.99f);
            const glm::vec3 bitangent = sphere.tangents[i].w * glm::cross(n, t);
            EXPECT_GT(glm::dot(bitangent, -glm::normalize(dPdv)), 0.99f);
        }
    }
}

TEST(Sphere, IndicesAreInRangeAndTheStripSnakesRowByRow) {
    const MeshData sphere = uvSphere(64, 64);
    for (std::uint32_t index : sphere.indices) EXPECT_LT(index, sphere.positions.size());
    // Row 0 runs left to right: 0, 65, 1, 66, ...; row 1 right to left: 64 + 130, 64 + 65, ...
    EXPECT_EQ(sphere.indices[0], 0u);
    EXPECT_EQ(sphere.indices[1], 65u);
    EXPECT_EQ(sphere.indices[2], 1u);
    EXPECT_EQ(sphere.indices[130], 2u * 65u + 64u);
    EXPECT_EQ(sphere.indices[131], 65u + 64u);
}

// Every non-degenerate triangle of the list variant faces outwards (counter-clockwise seen from
// outside), and together they cover the sphere's area.
TEST(Sphere, TriangleListFacesOutwardAndCoversTheSphere) {
    const MeshData sphere = uvSphereTriangles(64, 64);
    EXPECT_EQ(sphere.primitive, Primitive::Triangles);
    ASSERT_EQ(sphere.indices.size(), 6u * 64u * 64u);
    double area = 0.0;
    for (size_t i = 0; i < sphere.indices.size(); i += 3) {
        const glm::vec3 a = sphere.positions[sphere.indices[i]];
        const glm::vec3 b = sphere.positions[sphere.indices[i + 1]];
        const glm::vec3 c = sphere.positions[sphere.indices[i + 2]];
        const glm::vec3 n = glm::cross(b - a, c - a);
        area += 0.5 * glm::length(n);
        if (glm::length(n) < 1e-7f) continue;  // the pole rows hold degenerate triangles
        EXPECT_GT(glm::dot(n, a + b + c), 0.0f) << "triangle " << i / 3 << " faces inwards";
    }
    // A 64 x 64 tessellation falls short of 4 pi by well under 1 %.
    EXPECT_NEAR(area, 4.0 * std::numbers::pi, 0.01 * 4.0 * std::numbers::pi);
    EXPECT_LT(area, 4.0 * std::numbers::pi);
}

void expectClosedOutwardMesh(const MeshData& mesh) {
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        const glm::vec3 a = mesh.positions[mesh.indices[i]];
        const glm::vec3 b = mesh.positions[mesh.indices[i + 1]];
        const glm::vec3 c = mesh.positions[mesh.indices[i + 2]];
        const glm::vec3 faceNormal = glm::normalize(glm::cross(b - a, c - a));
        EXPECT_NEAR(glm::dot(faceNormal, mesh.normals[mesh.indices[i]]), 1.0f, 1e-5f);
    }
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        EXPECT_NEAR(glm::dot(glm::vec3(mesh.tangents[i]), mesh.normals[i]), 0.0f, 1e-6f);
    }
}

TEST(Cube, TwentyFourVerticesFacingOutward) {
    const MeshData box = cube();
    EXPECT_EQ(box.positions.size(), 24u);
    EXPECT_EQ(box.indices.size(), 36u);
    expectClosedOutwardMesh(box);
    // Textures stand upright: on every face the bitangent points from v = 1 to v = 0.
    for (size_t face = 0; face < 6; ++face) {
        const size_t bottomLeft = face * 4, topLeft = face * 4 + 3;
        EXPECT_FLOAT_EQ(box.uvs[bottomLeft].y, 1.0f);
        EXPECT_FLOAT_EQ(box.uvs[topLeft].y, 0.0f);
        const glm::vec3 up = box.positions[topLeft] - box.positions[bottomLeft];
        const glm::vec3 bitangent =
            box.tangents[bottomLeft].w *
            glm::cross(box.normals[bottomLeft], glm::vec3(box.tangents[bottomLeft]));
        EXPECT_GT(glm::dot(glm::normalize(up), bitangent), 0.99f);
    }
    for (size_t i = 0; i < box.positions.size(); ++i) {
        // each vertex lies on the face its normal names
        EXPECT_FLOAT_EQ(glm::dot(box.positions[i], box.normals[i]), 1.0f);
    }
}

TEST(Quad, FacesPlusZWithUvOriginBottomLeft) {
    const MeshData q = quad();
    EXPECT_EQ(q.indices.size(), 6u);
    expectClosedOutwardMesh(q);
    EXPECT_EQ(q.uvs[0], glm::vec2(0, 0));
    EXPECT_EQ(q.positions[0], glm::vec3(-1, -1, 0));
}

}  // namespace
}  // namespace pbr
