#pragma once
// Cube map geometry in GL's convention, on the CPU: the direction through a point of a face, a
// texel's centre and its exact solid angle. For the IBL precomputation's bright texels
// (ibl.cpp) and the accuracy tool's references (tools/ibl_accuracy.cpp).
#include <glm/glm.hpp>

namespace pbr {

// The unit direction through face coordinates (s, t) in [-1, 1] of `face` (+X, -X, +Y, -Y, +Z,
// -Z): GL's cube map texture selection (spec table 8.19) run backwards. Row 0 of a face as GL
// stores it is at t = -1.
glm::dvec3 cubeFaceDirection(int face, double s, double t);

// The face coordinate of texel centre k of n, in [-1, 1] (columns and rows alike).
double cubeTexelCentre(int k, int n);

// The solid angle texel (i, j) of an n^2 face covers, exact (the integral of the area element
// dx dy / (1 + x^2 + y^2)^(3/2) over it), so texels near the face corners are right too.
double cubeTexelSolidAngle(int i, int j, int n);

}  // namespace pbr
