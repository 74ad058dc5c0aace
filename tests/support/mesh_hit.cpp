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

std::optional<ModelHit> hitModel(const Model& model, const glm::dmat4& world,
                                 const glm::dvec3& origin, const glm::dvec3& direction) {
    std::optional<ModelHit> best;
    for (size_t index = 0; index < model.primitives.size(); ++index) {
        const ModelPrimitive& primitive = model.primitives[index];
        const MeshData& mesh = primitive.mesh;
        const glm::dmat4 m = world * glm::dmat4(primitive.transform);
        // in the primitive's own space, the ray unnormalised so distances agree
        const glm::dmat4 inverse = glm::inverse(m);
        const glm::dvec3 o = glm::dvec3(inverse * glm::dvec4(origin, 1.0));
        const glm::dvec3 d = glm::dvec3(inverse * glm::dvec4(direction, 0.0));
        // a bounding sphere first
        glm::dvec3 low(INFINITY), high(-INFINITY);
        for (const glm::vec3& p : mesh.positions) {
            low = glm::min(low, glm::dvec3(p));
            high = glm::max(high, glm::dvec3(p));
        }
        const glm::dvec3 centre = 0.5 * (low + high);
        const double radius = 0.5 * glm::length(high - low) * 1.001 + 1e-9;
        const glm::dvec3 oc = o - centre;
        const double b = glm::dot(oc, d), a = glm::dot(d, d);
        if (b * b - a * (glm::dot(oc, oc) - radius * radius) < 0.0) continue;
        const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(m)));
        for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const std::uint32_t v[3] = {mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]};
            const glm::dvec3 p0(mesh.positions[v[0]]), p1(mesh.positions[v[1]]),
                p2(mesh.positions[v[2]]);
            const auto hit = hitTriangle(o, d, p0, p1, p2);
            if (!hit || (best && hit->t >= best->distance)) continue;
            const double w[3] = {1.0 - hit->u - hit->v, hit->u, hit->v};
            ModelHit out;
            out.position = origin + direction * hit->t;
            glm::dvec3 normal(0.0);
            out.uv0 = out.uv1 = glm::dvec2(0.0);
            out.color = glm::dvec4(0.0);
            for (int k = 0; k < 3; ++k) {
                normal += w[k] * glm::dvec3(mesh.normals[v[k]]);
                out.uv0 += w[k] * glm::dvec2(mesh.uvs[v[k]]);
                if (!mesh.uvs1.empty()) out.uv1 += w[k] * glm::dvec2(mesh.uvs1[v[k]]);
                out.color += w[k] * (mesh.colors.empty() ? glm::dvec4(1.0)
                                                         : glm::dvec4(mesh.colors[v[k]]));
            }
            out.normal = glm::normalize(normalMatrix * normal);
            out.primitive = int(index);
            out.distance = hit->t;
            out.minBarycentric = std::min({w[0], w[1], w[2]});
            out.frontFacing = glm::dot(glm::cross(p1 - p0, p2 - p0), d) < 0.0;
            if (glm::determinant(glm::dmat3(m)) < 0.0) out.frontFacing = !out.frontFacing;
            best = out;
        }
    }
    return best;
}

std::pair<glm::dvec3, glm::dvec3> pixelRay(const glm::dmat4& toWorld, int width, int height,
                                           int px, int py) {
    const glm::dvec2 ndc(2.0 * (px + 0.5) / width - 1.0, 1.0 - 2.0 * (py + 0.5) / height);
    const glm::dvec4 nearPoint = toWorld * glm::dvec4(ndc, -1.0, 1.0);
    const glm::dvec4 farPoint = toWorld * glm::dvec4(ndc, 1.0, 1.0);
    const glm::dvec3 origin = glm::dvec3(nearPoint) / nearPoint.w;
    return {origin, glm::normalize(glm::dvec3(farPoint) / farPoint.w - origin)};
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
