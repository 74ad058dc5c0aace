#include <gtest/gtest.h>

#include <cmath>

#include "camera.h"

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

}  // namespace
}  // namespace pbr
