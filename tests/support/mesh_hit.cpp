#include "support/mesh_hit.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pbr::test {

namespace {

struct TriangleHit {
    double t, u, v;  // distance along the (local) ray; barycentric weights of corners 1 and 2
};

// Moller-Trumbore, in double precision.
std::optional<TriangleHit> hitTriangle(const glm::dvec3& o, const glm::dvec3& d,
                                       const glm::dvec3& a, const glm::dvec3& b,
                                       const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-14) return std::nullopt;
    const glm::dvec3 s = o - a;
    const double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) return std::nullopt;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) / det;
    if (v < 0.0 || u + v > 1.0) return std::nullopt;
    const double t = glm::dot(e2, q) / det;
    if (t <= 0.0) return std::nullopt;
    return TriangleHit{t, u, v};
}

}  // namespace

std::optional<MeshHit> hitUvSphere(const MeshData& sphere, int xSegments, int ySegments,
                                   const glm::dmat4& model, const glm::dvec3& origin,
                                   const glm::dvec3& direction) {
    // In the sphere's own space it is the unit sphere; the ray is mapped there unnormalised, so
    // that the distance t means the same in both spaces.
    const glm::dmat4 inverse = glm::inverse(model);
    const glm::dvec3 o = glm::dvec3(inverse * glm::dvec4(origin, 1.0));
    const glm::dvec3 d = glm::dvec3(inverse * glm::dvec4(direction, 0.0));
    // The analytic sphere holds the tessellated one: its hit says where to look.
    const double a = glm::dot(d, d), b = glm::dot(o, d), c = glm::dot(o, o) - 1.0;
    const double disc = b * b - a * c;
    if (disc <= 0.0) return std::nullopt;
    const glm::dvec3 p = o + d * ((-b - std::sqrt(disc)) / a);
    constexpr double pi = std::numbers::pi;
    double phi = std::atan2(p.z, p.x);
    if (phi < 0.0) phi += 2.0 * pi;
    const double theta = std::acos(std::clamp(p.y, -1.0, 1.0));
    const int cx = int(phi / (2.0 * pi) * xSegments), cy = int(theta / pi * ySegments);

    const int rowLength = xSegments + 1;
    auto vertex = [&](int x, int y) { return size_t(y * rowLength + x); };
    std::optional<MeshHit> best;
    for (int dy = -3; dy <= 3; ++dy) {
        const int y = cy + dy;
        if (y < 0 || y >= ySegments) continue;
        for (int dx = -3; dx <= 3; ++dx) {
            const int x = ((cx + dx) % xSegments + xSegments) % xSegments;
            // The quad's two triangles: (top x, bottom x, top x+1), (bottom x, top x+1, bottom
            // x+1).
            const size_t corners[2][3] = {
                {vertex(x, y), vertex(x, y + 1), vertex(x + 1, y)},
                {vertex(x, y + 1), vertex(x + 1, y), vertex(x + 1, y + 1)},
            };
            for (const auto& tri : corners) {
                const auto hit = hitTriangle(o, d, glm::dvec3(sphere.positions[tri[0]]),
                                             glm::dvec3(sphere.positions[tri[1]]),
                                             glm::dvec3(sphere.positions[tri[2]]));
                if (!hit || (best && hit->t >= best->distance)) continue;
                const double w0 = 1.0 - hit->u - hit->v;
                const glm::dvec3 local = w0 * glm::dvec3(sphere.normals[tri[0]]) +
                                         hit->u * glm::dvec3(sphere.normals[tri[1]]) +
                                         hit->v * glm::dvec3(sphere.normals[tri[2]]);
                const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(model)));
                best = MeshHit{origin + direction * hit->t, glm::normalize(normalMatrix * local),
                               hit->t, std::min({w0, hit->u, hit->v})};
            }
        }
    }
    return best;
}

glm::dvec3 cameraRay(const glm::dvec3& front, double fovY, int width, int height, double x,
                     double y) {
    const glm::dvec3 right = glm::normalize(glm::cross(front, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 up = glm::cross(right, front);
    const double t = std::tan(fovY / 2.0), aspect = double(width) / height;
    return glm::normalize(front + right * ((2.0 * x / width - 1.0) * t * aspect) +
                          up * ((1.0 - 2.0 * y / height) * t));
}

}  // namespace pbr::test
