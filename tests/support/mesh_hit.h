#pragma once
// A ray against the very triangles the GPU draws, for reference tests that must agree with it at
// grazing angles: the tessellated sphere parts from the analytic one towards its rim, where the
// GPU shades with the vertex normals interpolated over a triangle. Here the ray meets the
// sphere's triangles (uvSphere's data, under any model matrix) and the normal is interpolated
// with the hit's barycentric weights, as perspective-correct interpolation does; the world
// normal is the CPU's own inverse transpose of the model matrix times that, normalised.
#include <optional>

#include <glm/glm.hpp>

#include "mesh.h"

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

// The unit direction through image point (x right, y down, in pixels) of a camera at `position`
// looking along `front` (world up +Y), `fovY` radians, `width` x `height` pixels.
glm::dvec3 cameraRay(const glm::dvec3& front, double fovY, int width, int height, double x,
                     double y);

}  // namespace pbr::test
