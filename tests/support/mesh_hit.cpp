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

namespace {

constexpr int kLeafTriangles = 4;

// Splits triangles [first, first + count) of `order` at the median of their centroids along the
// box's longest axis, until leaves of kLeafTriangles.
int buildNode(ModelRayCaster::Primitive& primitive, const MeshData& mesh,
              const std::vector<glm::dvec3>& centroids, int first, int count) {
    ModelRayCaster::Node node;
    node.low = glm::dvec3(INFINITY);
    node.high = glm::dvec3(-INFINITY);
    for (int k = first; k < first + count; ++k) {
        const size_t triangle = size_t(primitive.order[size_t(k)]);
        for (int corner = 0; corner < 3; ++corner) {
            const glm::dvec3 p(mesh.positions[mesh.indices[3 * triangle + size_t(corner)]]);
            node.low = glm::min(node.low, p);
            node.high = glm::max(node.high, p);
        }
    }
    const int index = int(primitive.nodes.size());
    primitive.nodes.push_back(node);
    if (count <= kLeafTriangles) {
        primitive.nodes[size_t(index)].first = first;
        primitive.nodes[size_t(index)].count = count;
        return index;
    }
    const glm::dvec3 extent = node.high - node.low;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                     : extent.y >= extent.z                       ? 1
                                                                  : 2;
    const auto begin = primitive.order.begin() + first;
    std::nth_element(begin, begin + count / 2, begin + count, [&](int a, int b) {
        return centroids[size_t(a)][axis] < centroids[size_t(b)][axis];
    });
    const int left = buildNode(primitive, mesh, centroids, first, count / 2);
    const int right = buildNode(primitive, mesh, centroids, first + count / 2, count - count / 2);
    primitive.nodes[size_t(index)].left = left;
    primitive.nodes[size_t(index)].right = right;
    return index;
}

// Whether the ray (o + t d, t > 0) meets the box before `limit` (slab test; a little slack so
// a hit on a face shared with a neighbour box is never lost to rounding).
bool hitsBox(const glm::dvec3& o, const glm::dvec3& inverseD, const glm::dvec3& low,
             const glm::dvec3& high, double limit) {
    const glm::dvec3 slack = 1e-9 * (glm::abs(low) + glm::abs(high) + 1.0);
    const glm::dvec3 t0 = (low - slack - o) * inverseD, t1 = (high + slack - o) * inverseD;
    const glm::dvec3 near = glm::min(t0, t1), far = glm::max(t0, t1);
    const double enter = std::max({near.x, near.y, near.z, 0.0});
    const double leave = std::min({far.x, far.y, far.z, limit});
    return enter <= leave;
}

}  // namespace

ModelRayCaster::ModelRayCaster(const Model& model, const glm::dmat4& world) : model_(model) {
    for (const ModelPrimitive& source : model.primitives) {
        Primitive& primitive = primitives_.emplace_back();
        primitive.matrix = world * glm::dmat4(source.transform);
        primitive.inverse = glm::inverse(primitive.matrix);
        primitive.normalMatrix = glm::transpose(glm::inverse(glm::dmat3(primitive.matrix)));
        primitive.mirrored = glm::determinant(glm::dmat3(primitive.matrix)) < 0.0;
        const MeshData& mesh = source.mesh;
        const int triangles = int(mesh.indices.size() / 3);
        if (triangles == 0) continue;
        std::vector<glm::dvec3> centroids(static_cast<size_t>(triangles));
        for (int t = 0; t < triangles; ++t) {
            for (int corner = 0; corner < 3; ++corner)
                centroids[size_t(t)] +=
                    glm::dvec3(mesh.positions[mesh.indices[3 * size_t(t) + size_t(corner)]]) / 3.0;
            primitive.order.push_back(t);
        }
        buildNode(primitive, mesh, centroids, 0, triangles);
    }
}

std::optional<ModelHit> ModelRayCaster::hit(const glm::dvec3& origin,
                                            const glm::dvec3& direction) const {
    std::optional<ModelHit> best;
    for (size_t index = 0; index < primitives_.size(); ++index) {
        const Primitive& primitive = primitives_[index];
        if (primitive.nodes.empty()) continue;
        const MeshData& mesh = model_.primitives[index].mesh;
        // in the primitive's own space, the ray unnormalised so distances agree
        const glm::dvec3 o = glm::dvec3(primitive.inverse * glm::dvec4(origin, 1.0));
        const glm::dvec3 d = glm::dvec3(primitive.inverse * glm::dvec4(direction, 0.0));
        const glm::dvec3 inverseD = 1.0 / d;  // infinities for axis-parallel rays: the slabs cope
        std::vector<int> stack = {0};
        while (!stack.empty()) {
            const Node& node = primitive.nodes[size_t(stack.back())];
            stack.pop_back();
            if (!hitsBox(o, inverseD, node.low, node.high, best ? best->distance : INFINITY))
                continue;
            if (node.left >= 0) {
                stack.push_back(node.left);
                stack.push_back(node.right);
                continue;
            }
            for (int k = node.first; k < node.first + node.count; ++k) {
                const size_t i = 3 * size_t(primitive.order[size_t(k)]);
                const std::uint32_t v[3] = {mesh.indices[i], mesh.indices[i + 1],
                                            mesh.indices[i + 2]};
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
                for (int c = 0; c < 3; ++c) {
                    normal += w[c] * glm::dvec3(mesh.normals[v[c]]);
                    out.uv0 += w[c] * glm::dvec2(mesh.uvs[v[c]]);
                    if (!mesh.uvs1.empty()) out.uv1 += w[c] * glm::dvec2(mesh.uvs1[v[c]]);
                    out.color += w[c] * (mesh.colors.empty() ? glm::dvec4(1.0)
                                                             : glm::dvec4(mesh.colors[v[c]]));
                }
                out.normal = glm::normalize(primitive.normalMatrix * normal);
                out.primitive = int(index);
                out.distance = hit->t;
                out.minBarycentric = std::min({w[0], w[1], w[2]});
                out.frontFacing = glm::dot(glm::cross(p1 - p0, p2 - p0), d) < 0.0;
                if (primitive.mirrored) out.frontFacing = !out.frontFacing;
                best = out;
            }
        }
    }
    return best;
}

std::pair<glm::dvec3, glm::dvec3> pixelRay(const glm::dmat4& toWorld, int width, int height, int px,
                                           int py) {
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
