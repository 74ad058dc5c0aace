#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>
#include <numbers>

#include "base/paths.h"
#include "gl/mesh.h"
#include "gltf/model.h"

namespace pbr {
namespace {

TEST(Sphere, CountsAreTheTutorials) {
    const MeshData sphere = uvSphere(64, 64);
    EXPECT_EQ(sphere.primitive, Primitive::TriangleStrip);
    EXPECT_EQ(sphere.positions.size(), 65u * 65u);
    EXPECT_EQ(sphere.normals.size(), sphere.positions.size());
    EXPECT_EQ(sphere.uvs.size(), sphere.positions.size());
    EXPECT_EQ(sphere.tangents.size(), sphere.positions.size());
    EXPECT_EQ(sphere.indices.size(), 8321u);  // the first vertex, then 64 rows of 2 * 65
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
    // Vertex 0 twice (GL's alternation shifted by one: counter-clockwise triangles), then row 0
    // left to right: 0, 65, 1, 66, ...; row 1 right to left: 64 + 130, 64 + 65, ...: the text's
    // strip, so the quads keep the text's diagonals.
    EXPECT_EQ(sphere.indices[0], 0u);
    EXPECT_EQ(sphere.indices[1], 0u);
    EXPECT_EQ(sphere.indices[2], 65u);
    EXPECT_EQ(sphere.indices[3], 1u);
    EXPECT_EQ(sphere.indices[131], 2u * 65u + 64u);
    EXPECT_EQ(sphere.indices[132], 65u + 64u);
}

// The triangles GL draws from a mesh, by the rules of its primitive: a list in threes; a strip's
// triangle i is (i, i+1, i+2) for even i and (i+1, i, i+2) for odd i, so that all of a strip's
// triangles keep the winding of its first (OpenGL 3.3 core, section 2.6.1).
std::vector<std::array<std::uint32_t, 3>> trianglesAsDrawn(const MeshData& mesh) {
    std::vector<std::array<std::uint32_t, 3>> triangles;
    const std::vector<std::uint32_t>& i = mesh.indices;
    if (mesh.primitive == Primitive::Triangles) {
        for (size_t k = 0; k + 2 < i.size(); k += 3) triangles.push_back({i[k], i[k + 1], i[k + 2]});
    } else {
        for (size_t k = 0; k + 2 < i.size(); ++k) {
            if (k % 2 == 0) triangles.push_back({i[k], i[k + 1], i[k + 2]});
            else triangles.push_back({i[k + 1], i[k], i[k + 2]});
        }
    }
    return triangles;
}

struct WindingCount {
    int front = 0, back = 0;
    int degenerate = 0;  // no area: nothing is drawn
    int edgeOn = 0;      // across the surface, not on it
    double frontArea = 0.0;
};

// Counts a mesh's drawn triangles by the side they show: front when counter-clockwise seen from
// the side its vertex normals point to (GL's default front face), back when clockwise.
// Triangles with no area (the sphere's poles, a strip's repeated index) and triangles standing
// edge-on to their normals (where a strip turns to the next row, its three vertices lie on one
// meridian: a sliver inside the sphere, in the meridian's plane) are counted apart.
WindingCount countWinding(const MeshData& mesh) {
    WindingCount count;
    for (const auto& t : trianglesAsDrawn(mesh)) {
        const glm::vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
        const glm::vec3 geometric = glm::cross(b - a, c - a);
        // no area: two corners in one place (twice the area under 1e-5 of the longest edge
        // squared; the south pole's vertices differ by float rounding, about 1e-7)
        const float longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
        if (glm::length(geometric) <= 1e-5f * longest * longest) {
            ++count.degenerate;
            continue;
        }
        const glm::vec3 shading = mesh.normals[t[0]] + mesh.normals[t[1]] + mesh.normals[t[2]];
        if (std::abs(glm::dot(glm::normalize(geometric), glm::normalize(shading))) < 0.01f) {
            ++count.edgeOn;
            continue;
        }
        if (glm::dot(geometric, shading) > 0.0f) {
            ++count.front;
            count.frontArea += 0.5 * double(glm::length(geometric));
        } else {
            ++count.back;
        }
    }
    return count;
}

// Every mesh the suite generates is counter-clockwise seen from outside, so the samples may cull
// back faces (glEnable(GL_CULL_FACE)) and lose nothing: checked triangle by triangle as GL
// assembles them, for the sphere strip at the sizes the samples use and at odd ones.
TEST(Winding, EveryGeneratedMeshIsCounterClockwiseSeenFromOutside) {
    for (const auto& [x, y] : {std::pair{64, 64}, std::pair{64, 32}, std::pair{3, 2}, std::pair{7, 5}}) {
        SCOPED_TRACE("uvSphere(" + std::to_string(x) + ", " + std::to_string(y) + ")");
        const WindingCount strip = countWinding(uvSphere(x, y));
        EXPECT_EQ(strip.back, 0);
        // every quad of the grid is two drawn triangles, except one per quad at the two poles
        EXPECT_EQ(strip.front, 2 * x * y - 2 * x);
        // each of the y - 1 turns from one row to the next adds one empty and one edge-on triangle
        EXPECT_EQ(strip.edgeOn, y - 1);
        EXPECT_EQ(strip.degenerate, 1 + 2 * x + (y - 1));  // and the one at the start
        const WindingCount list = countWinding(uvSphereTriangles(x, y));
        EXPECT_EQ(list.back, 0);
        EXPECT_EQ(list.front, strip.front);
        EXPECT_NEAR(list.frontArea, strip.frontArea, 1e-4 * strip.frontArea);
    }
    // The 64 x 64 sphere's front triangles cover it: within 1 % of 4 pi, from below.
    const WindingCount sphere = countWinding(uvSphere(64, 64));
    EXPECT_NEAR(sphere.frontArea, 4.0 * std::numbers::pi, 0.01 * 4.0 * std::numbers::pi);
    const WindingCount box = countWinding(cube());
    EXPECT_EQ(box.front, 12);
    EXPECT_EQ(box.back, 0);
    EXPECT_DOUBLE_EQ(box.frontArea, 24.0);
    const WindingCount q = countWinding(quad());
    EXPECT_EQ(q.front, 2);
    EXPECT_EQ(q.back, 0);
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

// The glTF files the build generates (resources/models) are wound the same way, as the glTF
// specification asks: the renderer culls back faces of every primitive whose material is not
// doubleSided (common/gltf/gltf_renderer.cpp), so none of those may show its back.
TEST(Winding, EveryGeneratedGltfPrimitiveThatIsNotDoubleSidedFacesItsNormals) {
    int files = 0, culled = 0;
    for (const auto& entry : std::filesystem::directory_iterator(modelDir())) {
        if (entry.path().extension() != ".gltf") continue;
        ++files;
        const Model model = loadModel(entry.path());
        for (size_t p = 0; p < model.primitives.size(); ++p) {
            const ModelPrimitive& primitive = model.primitives[p];
            if (model.materials[size_t(primitive.material)].doubleSided) continue;
            SCOPED_TRACE(entry.path().filename().string() + " primitive " + std::to_string(p));
            const WindingCount count = countWinding(primitive.mesh);
            EXPECT_EQ(count.back, 0);
            EXPECT_GT(count.front, 0);
            ++culled;
        }
    }
    // unlit_showcase, pbr_showcase and pbr_workflows in its four forms
    EXPECT_GE(files, 6);
    EXPECT_GT(culled, 20);
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
