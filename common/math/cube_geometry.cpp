#include "math/cube_geometry.h"

#include <cmath>

namespace pbr {

namespace {

// The solid angle of the face rectangle from (0, 0) to (x, y), signed.
double areaElement(double x, double y) {
    return std::atan2(x * y, std::sqrt(x * x + y * y + 1.0));
}

}  // namespace

glm::dvec3 cubeFaceDirection(int face, double s, double t) {
    switch (face) {
        case 0:
            return glm::normalize(glm::dvec3(1.0, -t, -s));
        case 1:
            return glm::normalize(glm::dvec3(-1.0, -t, s));
        case 2:
            return glm::normalize(glm::dvec3(s, 1.0, t));
        case 3:
            return glm::normalize(glm::dvec3(s, -1.0, -t));
        case 4:
            return glm::normalize(glm::dvec3(s, -t, 1.0));
        default:
            return glm::normalize(glm::dvec3(-s, -t, -1.0));
    }
}

double cubeTexelCentre(int k, int n) {
    return 2.0 * (double(k) + 0.5) / double(n) - 1.0;
}

double cubeTexelSolidAngle(int i, int j, int n) {
    const double x0 = 2.0 * i / n - 1.0, x1 = 2.0 * (i + 1) / n - 1.0;
    const double y0 = 2.0 * j / n - 1.0, y1 = 2.0 * (j + 1) / n - 1.0;
    return areaElement(x0, y0) - areaElement(x0, y1) - areaElement(x1, y0) + areaElement(x1, y1);
}

}  // namespace pbr
