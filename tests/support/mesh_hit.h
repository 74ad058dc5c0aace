#pragma once
// A ray against the very triangles the GPU draws, for reference tests that must agree with it at
// grazing angles: the tessellated sphere parts from the analytic one towards its rim, where the
// GPU shades with the vertex normals interpolated over a triangle. Here the ray meets the
// sphere's triangles (uvSphere's data, under any model matrix) and the normal is interpolated
// with the hit's barycentric weights, as perspective-correct interpolation does; the world
// normal is the CPU's own inverse transpose of the model matrix times that, normalised.
#include <optional>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "gl/mesh.h"
#include "gltf/model.h"

namespace pbr::test {

struct MeshHit {
    glm::dvec3 position;          // world space
    glm::dvec3 normal;            // world space, unit
    double distance = 0.0;        // along the ray
    double minBarycentric = 0.0;  // how far inside its triangle (0 on an edge)
};

// The nearest hit of the ray (origin, unit direction) with `sphere` (a uvSphere, whose triangles
// split each quad from its top right to its bottom left corner) placed by `model`.
std::optional<MeshHit> hitUvSphere(const MeshData& sphere, int xSegments, int ySegments,
                                   const glm::dmat4& model, const glm::dvec3& origin,
                                   const glm::dvec3& direction);

// A ray against every triangle of a loaded model, each primitive placed by `world` x its node
// transform: the nearest hit, with the vertex attributes interpolated by its barycentric
// weights (the normal through the CPU's own inverse transpose, normalised).
struct ModelHit {
    glm::dvec3 position;
    glm::dvec3 normal;  // world space, unit, interpolated (the geometric side it was hit from
                        // is frontFacing)
    glm::dvec2 uv0, uv1;
    glm::dvec4 color;  // COLOR_0, white when the mesh has none
    int primitive = -1;
    double distance = 0.0;
    double minBarycentric = 0.0;
    bool frontFacing = true;  // the triangle is counter-clockwise seen from the ray's origin
};
// The model prepared once for many rays: each primitive's matrices and a bounding volume
// hierarchy over its triangles (so a ray visits a few dozen triangles, not every one; the hit is
// the same as testing all of them). Keeps a reference to `model`, which must outlive it.
class ModelRayCaster {
public:
    ModelRayCaster(const Model& model, const glm::dmat4& world);
    std::optional<ModelHit> hit(const glm::dvec3& origin, const glm::dvec3& direction) const;

    struct Node {  // a box; leaves hold triangles [first, first + count) of `order`
        glm::dvec3 low, high;
        int left = -1, right = -1, first = 0, count = 0;
    };
    struct Primitive {
        glm::dmat4 matrix, inverse;
        glm::dmat3 normalMatrix;
        bool mirrored = false;      // negative determinant: the winding flips
        std::vector<Node> nodes;    // nodes[0] is the root (empty: no triangles)
        std::vector<int> order;     // triangle indices (index / 3), leaf by leaf
    };

private:
    const Model& model_;
    std::vector<Primitive> primitives_;
};

// The ray (origin on the near plane, unit direction) through the centre of pixel (px, py) of a
// width x height image (y down), given `toWorld` = inverse(projection x view).
std::pair<glm::dvec3, glm::dvec3> pixelRay(const glm::dmat4& toWorld, int width, int height,
                                           int px, int py);

// The unit direction through image point (x right, y down, in pixels) of a camera at `position`
// looking along `front` (world up +Y), `fovY` radians, `width` x `height` pixels.
glm::dvec3 cameraRay(const glm::dvec3& front, double fovY, int width, int height, double x,
                     double y);

}  // namespace pbr::test
