#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "math/camera.h"

namespace pbr {
namespace {

constexpr float kEps = 1e-5f;

void expectNear(const glm::vec3& a, const glm::vec3& b, float eps = kEps) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

TEST(Camera, DefaultsAreTheTutorials) {
    const FlyCamera camera;
    expectNear(camera.position(), {0, 0, 3});
    EXPECT_FLOAT_EQ(camera.yaw(), -90.0f);
    EXPECT_FLOAT_EQ(camera.pitch(), 0.0f);
    EXPECT_FLOAT_EQ(camera.zoom(), 45.0f);
    expectNear(camera.front(), {0, 0, -1});  // yaw -90 looks down -Z
    expectNear(camera.right(), {1, 0, 0});
    expectNear(camera.up(), {0, 1, 0});
}

TEST(Camera, KeyboardMovesAtSpeedTimesTime) {
    FlyCamera camera({0, 0, 3});
    camera.processKeyboard(CameraMove::Forward, 0.5f);  // 2.5 units/s for half a second
    expectNear(camera.position(), {0, 0, 1.75f});
    camera.processKeyboard(CameraMove::Right, 1.0f);
    expectNear(camera.position(), {2.5f, 0, 1.75f});
    camera.processKeyboard(CameraMove::Backward, 0.5f);
    camera.processKeyboard(CameraMove::Left, 1.0f);
    expectNear(camera.position(), {0, 0, 3});
}

TEST(Camera, MouseTurnsBySensitivityAndClampsPitch) {
    FlyCamera camera;
    camera.processMouseMovement(900.0f, 0.0f);  // 0.1 degree a pixel: +90 degrees of yaw
    EXPECT_NEAR(camera.yaw(), 0.0f, 1e-4f);
    expectNear(camera.front(), {1, 0, 0});  // yaw 0 looks down +X
    camera.processMouseMovement(0.0f, 5000.0f);
    EXPECT_FLOAT_EQ(camera.pitch(), 89.0f);
    camera.processMouseMovement(0.0f, -10000.0f);
    EXPECT_FLOAT_EQ(camera.pitch(), -89.0f);
    EXPECT_NEAR(glm::length(camera.front()), 1.0f, kEps);
    EXPECT_NEAR(glm::dot(camera.front(), camera.up()), 0.0f, kEps);
}

TEST(Camera, ScrollZoomStaysBetween1And45) {
    FlyCamera camera;
    camera.processMouseScroll(10.0f);
    EXPECT_FLOAT_EQ(camera.zoom(), 35.0f);
    camera.processMouseScroll(100.0f);
    EXPECT_FLOAT_EQ(camera.zoom(), 1.0f);
    camera.processMouseScroll(-100.0f);
    EXPECT_FLOAT_EQ(camera.zoom(), 45.0f);
}

TEST(Camera, ViewPutsTheCameraAtTheOriginLookingDownMinusZ) {
    const FlyCamera camera({1, 2, 3}, 0.0f, 0.0f);  // looking down +X
    const glm::mat4 view = camera.viewMatrix();
    const glm::vec4 eye = view * glm::vec4(1, 2, 3, 1);
    expectNear(glm::vec3(eye), {0, 0, 0});
    const glm::vec4 ahead = view * glm::vec4(6, 2, 3, 1);  // 5 units in front
    expectNear(glm::vec3(ahead), {0, 0, -5});
}

TEST(Camera, ProjectionFieldOfViewIsTheZoomInDegrees) {
    const FlyCamera camera;
    const float aspect = 16.0f / 9.0f;
    const glm::mat4 projection = camera.projectionMatrix(aspect);
    // A point on the top edge of a 45 degree frustum, 10 units away, lands on NDC y = 1; one on
    // the right edge on NDC x = 1.
    const float half = std::tan(glm::radians(22.5f)) * 10.0f;
    const glm::vec4 top = projection * glm::vec4(0, half, -10, 1);
    EXPECT_NEAR(top.y / top.w, 1.0f, 1e-5f);
    const glm::vec4 right = projection * glm::vec4(half * aspect, 0, -10, 1);
    EXPECT_NEAR(right.x / right.w, 1.0f, 1e-5f);
    // near 0.1 and far 100 map to depth -1 and 1
    const glm::vec4 nearPoint = projection * glm::vec4(0, 0, -0.1f, 1);
    const glm::vec4 farPoint = projection * glm::vec4(0, 0, -100.0f, 1);
    EXPECT_NEAR(nearPoint.z / nearPoint.w, -1.0f, 1e-4f);
    EXPECT_NEAR(farPoint.z / farPoint.w, 1.0f, 1e-4f);
}

// The default camera of the grid samples, (0,0,23), shows all 49 spheres with a margin at 16:9.
TEST(Camera, GridCameraSeesTheWholeGrid) {
    const FlyCamera camera({0, 0, 23});
    const glm::mat4 clip = camera.projectionMatrix(16.0f / 9.0f) * camera.viewMatrix();
    for (float x : {-8.5f, 8.5f}) {
        for (float y : {-8.5f, 8.5f}) {  // outer sphere edges: 3 * 2.5 + radius 1
            const glm::vec4 p = clip * glm::vec4(x, y, 0, 1);
            EXPECT_LT(std::abs(p.x / p.w), 0.95f);
            EXPECT_LT(std::abs(p.y / p.w), 0.95f);
        }
    }
}

// ---- Frustum
// -------------------------------------------------------------------------------------

// A 90-degree square frustum from the origin down -Z, near 1, far 10: its planes are |x| = -z,
// |y| = -z, z = -1 and z = -10, so where a sphere stands is plain geometry.
Frustum squareFrustum() {
    return Frustum(glm::perspective(glm::radians(90.0f), 1.0f, 1.0f, 10.0f));
}

TEST(Frustum, SpheresAgainstTheKnownPlanes) {
    const Frustum frustum = squareFrustum();
    EXPECT_TRUE(frustum.mayContain({0, 0, -5}, 1));
    // x = 7 at z = -5: 2 / sqrt(2) = 1.41 past the side plane x = -z, more than the radius
    EXPECT_FALSE(frustum.mayContain({7, 0, -5}, 1));
    EXPECT_FALSE(frustum.mayContain({0, -7, -5}, 1));
    // x = 5.5: 0.35 past it, less than the radius: part of the sphere is inside
    EXPECT_TRUE(frustum.mayContain({5.5f, 0, -5}, 1));
    EXPECT_TRUE(frustum.mayContain({-5.5f, 0, -5}, 1));
    EXPECT_FALSE(frustum.mayContain({0, 0, 2}, 1));       // behind the near plane
    EXPECT_TRUE(frustum.mayContain({0, 0, -0.5f}, 1));     // straddling it
    EXPECT_FALSE(frustum.mayContain({0, 0, -12}, 1));     // past the far plane
    EXPECT_TRUE(frustum.mayContain({0, 0, -10.5f}, 1));   // straddling it
}

// Never a false "outside": of random spheres around a tilted camera, every one that mayContain
// rejects has all of its surface points outside the clip volume (checked in double precision).
TEST(Frustum, NeverRejectsASphereThatReachesTheView) {
    const FlyCamera camera({1.0f, -2.0f, 6.0f}, -70.0f, 15.0f);
    const glm::mat4 projectionView = camera.projectionMatrix(16.0f / 9.0f) * camera.viewMatrix();
    const Frustum frustum(projectionView);
    const glm::dmat4 clip(projectionView);
    std::uint32_t state = 12345;
    auto random = [&state](double low, double high) {
        state = state * 1664525u + 1013904223u;
        return low + (high - low) * double(state >> 8) / double(1u << 24);
    };
    int rejected = 0, kept = 0;
    for (int i = 0; i < 4000; ++i) {
        const glm::vec3 centre(random(-30, 30), random(-30, 30), random(-30, 30));
        const float radius = float(random(0.1, 4.0));
        if (frustum.mayContain(centre, radius)) {
            ++kept;
            continue;
        }
        ++rejected;
        for (int k = 0; k < 200; ++k) {
            const double y = 1.0 - 2.0 * (k + 0.5) / 200.0, ring = std::sqrt(1.0 - y * y);
            const double a = 2.399963229728653 * k;
            const glm::dvec3 p = glm::dvec3(centre) + double(radius) * glm::dvec3(ring * std::cos(a), y,
                                                                                ring * std::sin(a));
            const glm::dvec4 c = clip * glm::dvec4(p, 1.0);
            const bool inside = std::abs(c.x) <= c.w && std::abs(c.y) <= c.w && std::abs(c.z) <= c.w;
            ASSERT_FALSE(inside) << "sphere " << i << " rejected, yet its point (" << p.x << ", "
                                 << p.y << ", " << p.z << ") is in view";
        }
    }
    // the camera sees a real part of the volume, and leaves most of it out
    EXPECT_GT(kept, 100);
    EXPECT_GT(rejected, 2000);
}

// ---- OrbitCamera -------------------------------------------------------------------------------

// Points spread evenly over the unit sphere (a Fibonacci spiral), plus its centre.
std::vector<glm::dvec3> unitSpherePoints(int count = 2000) {
    std::vector<glm::dvec3> points{{0.0, 0.0, 0.0}};
    const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / count;
        const double ring = std::sqrt(1.0 - y * y);
        points.push_back({ring * std::cos(golden * i), y, ring * std::sin(golden * i)});
    }
    return points;
}

// Clip coordinates in double, from the camera's float matrices: the tests judge the planes, not
// the rounding of this arithmetic.
glm::dvec4 toClip(const OrbitCamera& camera, float aspect, const glm::dvec3& point) {
    const glm::dmat4 clip =
        glm::dmat4(camera.projectionMatrix(aspect)) * glm::dmat4(camera.viewMatrix());
    return clip * glm::dvec4(point, 1.0);
}

glm::dvec3 toNdc(const OrbitCamera& camera, float aspect, const glm::dvec3& point) {
    const glm::dvec4 clip = toClip(camera, aspect, point);
    return glm::dvec3(clip) / clip.w;
}

struct Bounds {
    glm::vec3 min, max;
    glm::dvec3 centre() const { return 0.5 * (glm::dvec3(min) + glm::dvec3(max)); }
    double radius() const { return 0.5 * glm::length(glm::dvec3(max) - glm::dvec3(min)); }
};

// A box off the origin, not a cube, times `scale`: 1 mm to 1 km for scales 1e-3 to 1e3.
Bounds scaledBounds(float scale) {
    return {glm::vec3(-1.0f, 0.5f, -2.0f) * scale, glm::vec3(3.0f, 2.0f, 1.0f) * scale};
}

constexpr float kScales[] = {1e-3f, 1.0f, 1e3f};

// The default view: on the +Z side of the centre looking down -Z, and the bounding sphere fills
// the narrower field of view to 1/1.1 of its half angle's sine: the largest NDC coordinate of the
// sphere on that axis is tan(asin(sin(h) / 1.1)) / tan(h), h the half field of view.
TEST(OrbitCamera, FramingFitsTheBoundingSphereAtAnyScaleAndAspect) {
    for (const float scale : kScales) {
        const Bounds bounds = scaledBounds(scale);
        for (const float aspect : {16.0f / 9.0f, 1.0f, 9.0f / 16.0f, 3.0f, 0.25f}) {
            const OrbitCamera camera = OrbitCamera::framing(bounds.min, bounds.max, aspect);
            const glm::dvec3 eye(camera.position());
            const glm::dvec3 centre = bounds.centre();
            EXPECT_NEAR(eye.x, centre.x, 1e-5 * scale);
            EXPECT_NEAR(eye.y, centre.y, 1e-5 * scale);
            EXPECT_GT(eye.z, centre.z);
            EXPECT_FLOAT_EQ(camera.yaw(), 0.0f);
            EXPECT_FLOAT_EQ(camera.pitch(), 0.0f);
            expectNear(camera.target(), glm::vec3(centre), 1e-6f * scale);

            const double halfY = glm::radians(22.5);
            const double halfX = std::atan(std::tan(halfY) * aspect);
            const double half = std::min(halfX, halfY);
            const double edge = std::tan(std::asin(std::sin(half) / 1.1)) / std::tan(half);
            double largest = 0.0;
            for (const glm::dvec3& unit : unitSpherePoints()) {
                const glm::dvec3 ndc = toNdc(camera, aspect, centre + bounds.radius() * unit);
                const double onAxis = std::abs(halfX < halfY ? ndc.x : ndc.y);
                EXPECT_LE(onAxis, edge + 1e-4) << "scale " << scale << ", aspect " << aspect;
                EXPECT_LT(std::abs(ndc.x), 1.0);
                EXPECT_LT(std::abs(ndc.y), 1.0);
                EXPECT_GT(ndc.z, -1.0);
                EXPECT_LT(ndc.z, 1.0);
                largest = std::max(largest, onAxis);
            }
            EXPECT_GT(largest, edge - 0.01) << "scale " << scale << ", aspect " << aspect;
        }
    }
}

// The model stays in its own units, and a model 1000 times larger looks exactly the same, after
// the same drags and scrolls too.
TEST(OrbitCamera, AModelOfAnySizeLooksTheSame) {
    const Bounds unit = scaledBounds(1.0f);
    for (const float scale : {1e-3f, 1e3f}) {
        const Bounds scaled = scaledBounds(scale);
        OrbitCamera a = OrbitCamera::framing(unit.min, unit.max, 1.5f);
        OrbitCamera b = OrbitCamera::framing(scaled.min, scaled.max, 1.5f);
        for (int step = 0; step < 3; ++step) {
            for (const glm::dvec3& point : unitSpherePoints(200)) {
                const glm::dvec3 p = unit.centre() + unit.radius() * point;
                const glm::dvec3 ndcA = toNdc(a, 1.5f, p);
                const glm::dvec3 ndcB = toNdc(b, 1.5f, p * double(scale));
                EXPECT_NEAR(ndcA.x, ndcB.x, 1e-4);
                EXPECT_NEAR(ndcA.y, ndcB.y, 1e-4);
                EXPECT_NEAR(ndcA.z, ndcB.z, 1e-4);
            }
            a.orbit(37.0f, -12.0f);
            b.orbit(37.0f, -12.0f);
            a.dolly(2.0f);
            b.dolly(2.0f);
        }
    }
}

// Near and far follow the distance: at every dolly distance from 0.05 r to 50 r and any scale,
// nothing of the bounding sphere beyond 1 % of the eye's distance is clipped (nothing at all from
// outside the sphere), and a 24-bit depth buffer still tells apart two surfaces 0.1 % of r apart
// at the sphere's far side, where its resolution is worst.
TEST(OrbitCamera, NothingClippedAndDepthResolvedAtAnyDistance) {
    for (const float scale : kScales) {
        const Bounds bounds = scaledBounds(scale);
        const double r = bounds.radius();
        OrbitCamera camera = OrbitCamera::framing(bounds.min, bounds.max, 16.0f / 9.0f);
        camera.orbit(100.0f, 40.0f);
        camera.dolly(1000.0f);  // all the way in
        EXPECT_NEAR(camera.distance(), 0.05 * r, 1e-5 * r);
        std::vector<double> distances;
        for (;;) {
            const double d = camera.distance();
            distances.push_back(d / r);
            const glm::dmat4 view(camera.viewMatrix());
            for (const glm::dvec3& unit : unitSpherePoints(500)) {
                const glm::dvec3 p = bounds.centre() + r * unit;
                const double depth = -(view * glm::dvec4(p, 1.0)).z;
                if (depth < 0.01 * d && d < 1.07 * r) continue;  // at the eye, inside the sphere
                const glm::dvec4 clip = toClip(camera, 1.0f, p);
                EXPECT_GE(clip.z, -clip.w) << "clipped by near at distance " << d / r << " r";
                EXPECT_LE(clip.z, clip.w) << "clipped by far at distance " << d / r << " r";
            }
            // Window depth of two points on the view axis at d + r and d + 1.001 r.
            const glm::dmat4 projection(camera.projectionMatrix(1.0f));
            auto windowDepth = [&](double z) {
                const glm::dvec4 clip = projection * glm::dvec4(0.0, 0.0, -z, 1.0);
                return 0.5 * clip.z / clip.w + 0.5;
            };
            const double steps = (windowDepth(d + 1.001 * r) - windowDepth(d + r)) * 16777216.0;
            EXPECT_GE(steps, 4.0) << "depth steps between surfaces 0.1 % of r apart at distance "
                                  << d / r << " r, scale " << scale;
            if (d >= 50.0 * r * 0.9999) break;
            camera.dolly(-2.0f);
        }
        EXPECT_NEAR(distances.back(), 50.0, 1e-3);
        EXPECT_GT(distances.size(), 20u);
    }
}

// Dragging right moves the eye to its left around the target, dragging up moves it down: a point
// on the model's front follows the cursor. 0.25 degrees a pixel; pitch stops at +-89 degrees.
TEST(OrbitCamera, TheModelFollowsTheCursor) {
    const Bounds bounds = scaledBounds(1.0f);
    const glm::dvec3 front = bounds.centre() + glm::dvec3(0.0, 0.0, bounds.radius());
    OrbitCamera camera = OrbitCamera::framing(bounds.min, bounds.max, 1.0f);
    camera.orbit(40.0f, 0.0f);  // right
    EXPECT_FLOAT_EQ(camera.yaw(), -10.0f);
    EXPECT_LT(camera.position().x, float(bounds.centre().x));  // the eye went to its left (-X)
    EXPECT_GT(toNdc(camera, 1.0f, front).x, 0.05);             // the front point went right
    EXPECT_NEAR(toNdc(camera, 1.0f, front).y, 0.0, 1e-5);

    camera = OrbitCamera::framing(bounds.min, bounds.max, 1.0f);
    camera.orbit(0.0f, 40.0f);  // up (y up, as InputFrame gives it)
    EXPECT_FLOAT_EQ(camera.pitch(), -10.0f);
    EXPECT_LT(camera.position().y, float(bounds.centre().y));  // the eye went down
    EXPECT_GT(toNdc(camera, 1.0f, front).y, 0.05);             // the front point went up

    camera.orbit(1440.0f, 0.0f);  // a whole turn
    EXPECT_NEAR(camera.yaw(), 0.0f, 1e-4f);
    camera.orbit(720.0f, 0.0f);  // half a turn: yaw stays within [-180, 180)
    EXPECT_FLOAT_EQ(camera.yaw(), -180.0f);
    camera.orbit(0.0f, -10000.0f);
    EXPECT_FLOAT_EQ(camera.pitch(), 89.0f);
    camera.orbit(0.0f, 10000.0f);
    EXPECT_FLOAT_EQ(camera.pitch(), -89.0f);
    // Still looking at the target from the same distance.
    const glm::vec3 seen = glm::vec3(camera.viewMatrix() * glm::vec4(camera.target(), 1.0f));
    expectNear(seen, {0.0f, 0.0f, -camera.distance()}, 1e-5f);
}

// Scroll up (positive) comes closer: x 0.9 a step, within [0.05 r, 50 r].
TEST(OrbitCamera, DollyIsMultiplicativeAndClamped) {
    const Bounds bounds = scaledBounds(1e3f);
    const float r = float(bounds.radius());
    OrbitCamera camera = OrbitCamera::framing(bounds.min, bounds.max, 1.0f);
    const float start = camera.distance();
    camera.dolly(1.0f);
    EXPECT_NEAR(camera.distance(), 0.9f * start, 1e-5f * start);
    camera.dolly(-3.0f);
    EXPECT_NEAR(camera.distance(), start / (0.9f * 0.9f), 1e-5f * start);
    camera.dolly(0.5f);
    EXPECT_NEAR(camera.distance(), start / (0.9f * 0.9f) * std::sqrt(0.9f), 1e-5f * start);
    camera.dolly(1000.0f);
    EXPECT_NEAR(camera.distance(), 0.05f * r, 1e-5f * r);
    camera.dolly(-1000.0f);
    EXPECT_NEAR(camera.distance(), 50.0f * r, 1e-5f * r);
    const glm::vec3 seen = glm::vec3(camera.viewMatrix() * glm::vec4(camera.target(), 1.0f));
    expectNear(seen / r, {0.0f, 0.0f, -50.0f}, 1e-4f);

    // An explicit start beyond 50 r is kept, and scrolling out does not push it further.
    const glm::vec3 centre(bounds.centre());
    camera = OrbitCamera::fromPosition(bounds.min, bounds.max, centre + glm::vec3(0, 0, 80 * r));
    camera.dolly(-1.0f);
    EXPECT_NEAR(camera.distance(), 80.0f * r, 1e-4f * r);
    camera.dolly(1.0f);
    EXPECT_NEAR(camera.distance(), 72.0f * r, 1e-4f * r);
}

// --camera x,y,z for an orbit sample: the eye where asked, looking at the bounds' centre.
TEST(OrbitCamera, FromPositionLooksAtTheCentreFromThere) {
    const glm::vec3 min(0.0f), max(2.0f);   // centre (1,1,1)
    const glm::vec3 eye(3.0f, 4.0f, 5.0f);  // offset (2,3,4)
    const OrbitCamera camera = OrbitCamera::fromPosition(min, max, eye);
    expectNear(camera.position(), eye, 1e-5f);
    expectNear(camera.target(), {1, 1, 1});
    EXPECT_NEAR(camera.distance(), std::sqrt(29.0f), 1e-5f);
    EXPECT_NEAR(camera.yaw(), glm::degrees(std::atan2(2.0f, 4.0f)), 1e-4f);
    EXPECT_NEAR(camera.pitch(), glm::degrees(std::asin(3.0f / std::sqrt(29.0f))), 1e-4f);
    const glm::vec3 seen = glm::vec3(camera.viewMatrix() * glm::vec4(1, 1, 1, 1));
    expectNear(seen, {0.0f, 0.0f, -std::sqrt(29.0f)}, 1e-5f);

    // Straight above: pitch 89, the distance kept.
    const OrbitCamera above = OrbitCamera::fromPosition(min, max, {1.0f, 9.0f, 1.0f});
    EXPECT_FLOAT_EQ(above.pitch(), 89.0f);
    EXPECT_NEAR(above.distance(), 8.0f, 1e-5f);
    EXPECT_GT(above.position().y, 8.99f);

    // At the centre itself: the least distance, on the +Z side.
    const OrbitCamera inside = OrbitCamera::fromPosition(min, max, {1.0f, 1.0f, 1.0f});
    EXPECT_NEAR(inside.distance(), 0.05f * std::sqrt(3.0f), 1e-6f);
    expectNear(inside.position(), {1.0f, 1.0f, 1.0f + 0.05f * std::sqrt(3.0f)}, 1e-5f);
}

// A flat or point-sized model still gets a camera that works.
TEST(OrbitCamera, DegenerateBoundsStillGiveAView) {
    const OrbitCamera flat = OrbitCamera::framing({-1, -1, 0}, {1, 1, 0}, 1.0f);
    EXPECT_GT(flat.nearPlane(), 0.0f);
    EXPECT_GT(flat.farPlane(), flat.nearPlane());
    const OrbitCamera point = OrbitCamera::framing({2, 3, 4}, {2, 3, 4}, 1.0f);
    EXPECT_GT(point.radius(), 0.0f);
    EXPECT_GT(point.distance(), 0.0f);
    EXPECT_GT(point.farPlane(), point.nearPlane());
    const glm::mat4 clip = point.projectionMatrix(1.0f) * point.viewMatrix();
    const glm::vec4 centre = clip * glm::vec4(2, 3, 4, 1);
    EXPECT_TRUE(std::isfinite(centre.z / centre.w));
    EXPECT_NEAR(centre.x / centre.w, 0.0f, 1e-3f);
}

}  // namespace
}  // namespace pbr
