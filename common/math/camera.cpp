#include "math/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace pbr {

FlyCamera::FlyCamera(glm::vec3 position, float yaw, float pitch)
    : position_(position), yaw_(yaw), pitch_(std::clamp(pitch, -89.0f, 89.0f)) {
    updateVectors();
}

void FlyCamera::processKeyboard(CameraMove direction, float deltaTime) {
    const float distance = movementSpeed * deltaTime;
    switch (direction) {
        case CameraMove::Forward:
            position_ += front_ * distance;
            break;
        case CameraMove::Backward:
            position_ -= front_ * distance;
            break;
        case CameraMove::Left:
            position_ -= right_ * distance;
            break;
        case CameraMove::Right:
            position_ += right_ * distance;
            break;
    }
}

void FlyCamera::processMouseMovement(float xOffset, float yOffset, bool constrainPitch) {
    yaw_ += xOffset * mouseSensitivity;
    pitch_ += yOffset * mouseSensitivity;
    if (constrainPitch) pitch_ = std::clamp(pitch_, -89.0f, 89.0f);
    updateVectors();
}

void FlyCamera::processMouseScroll(float yOffset) {
    zoom_ = std::clamp(zoom_ - yOffset, 1.0f, kDefaultZoom);
}

void FlyCamera::setZoom(float degrees) {
    zoom_ = std::clamp(degrees, 1.0f, kDefaultZoom);
}

glm::mat4 FlyCamera::viewMatrix() const {
    return glm::lookAt(position_, position_ + front_, up_);
}

glm::mat4 FlyCamera::projectionMatrix(float aspect) const {
    return glm::perspective(glm::radians(zoom_), aspect, kNear, kFar);
}

void FlyCamera::updateVectors() {
    const float yaw = glm::radians(yaw_);
    const float pitch = glm::radians(pitch_);
    front_ = glm::normalize(glm::vec3(std::cos(yaw) * std::cos(pitch), std::sin(pitch),
                                      std::sin(yaw) * std::cos(pitch)));
    right_ = glm::normalize(glm::cross(front_, worldUp_));
    up_ = glm::normalize(glm::cross(right_, front_));
}

Framing frameBounds(const glm::vec3& boundsMin, const glm::vec3& boundsMax, float fovYDegrees,
                    float aspect) {
    const glm::vec3 centre = 0.5f * (boundsMin + boundsMax);
    const float radius = std::max(0.5f * glm::length(boundsMax - boundsMin), 1e-6f);
    // the narrower of the two fields of view decides; 10 % margin
    const float halfFovY = glm::radians(fovYDegrees) * 0.5f;
    const float halfFovX = std::atan(std::tan(halfFovY) * aspect);
    const float distance = 1.1f / std::sin(std::min(halfFovY, halfFovX));
    Framing framing;
    framing.normalize = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f / radius)) *
                        glm::translate(glm::mat4(1.0f), -centre);
    framing.cameraPosition = {0.0f, 0.0f, distance};
    return framing;
}

namespace {

constexpr float kClipMargin = 1.05f;     // the planes stand 5 % of r off the bounding sphere
constexpr float kNearFloor = 0.01f;      // near never closer than 1 % of the distance
constexpr float kCentreEpsilon = 1e-6f;  // an eye this close to the centre (x r) is at it

// Centred on the bounds, their bounding sphere's radius (floored by the constructor); distance 1.
OrbitCamera aroundBounds(const glm::vec3& boundsMin, const glm::vec3& boundsMax) {
    return {0.5f * (boundsMin + boundsMax), 0.5f * glm::length(boundsMax - boundsMin), 1.0f, 0.0f,
            0.0f};
}

// Degrees into [-180, 180).
float wrapDegrees(float degrees) {
    const float wrapped = std::fmod(degrees + 180.0f, 360.0f);
    return (wrapped < 0.0f ? wrapped + 360.0f : wrapped) - 180.0f;
}

}  // namespace

OrbitCamera::OrbitCamera(glm::vec3 target, float radius, float distance, float yawDegrees,
                         float pitchDegrees)
    : target_(target),
      distance_(distance),
      yaw_(wrapDegrees(yawDegrees)),
      pitch_(std::clamp(pitchDegrees, -kMaxPitch, kMaxPitch)) {
    const glm::vec3 magnitude = glm::abs(target);
    const float largest = std::max({magnitude.x, magnitude.y, magnitude.z});
    radius_ = std::max({radius, largest * 1e-6f, 1e-12f});
    if (!(distance_ > 0.0f)) distance_ = kMinDistance * radius_;
}

OrbitCamera OrbitCamera::framing(const glm::vec3& boundsMin, const glm::vec3& boundsMax,
                                 float aspect) {
    const OrbitCamera unit = aroundBounds(boundsMin, boundsMax);
    // The narrower of the two fields of view decides.
    const float halfFovY = glm::radians(kFovYDegrees) * 0.5f;
    const float halfFovX = std::atan(std::tan(halfFovY) * aspect);
    const float distance = kFramingMargin * unit.radius() / std::sin(std::min(halfFovY, halfFovX));
    return {unit.target(), unit.radius(), distance, 0.0f, 0.0f};
}

OrbitCamera OrbitCamera::fromPosition(const glm::vec3& boundsMin, const glm::vec3& boundsMax,
                                      const glm::vec3& eye) {
    const OrbitCamera unit = aroundBounds(boundsMin, boundsMax);
    const glm::vec3 offset = eye - unit.target();
    const float distance = glm::length(offset);
    if (!(distance > kCentreEpsilon * unit.radius())) {
        return {unit.target(), unit.radius(), kMinDistance * unit.radius(), 0.0f, 0.0f};
    }
    const float yaw = glm::degrees(std::atan2(offset.x, offset.z));
    const float pitch = glm::degrees(std::asin(std::clamp(offset.y / distance, -1.0f, 1.0f)));
    return {unit.target(), unit.radius(), distance, yaw, pitch};
}

void OrbitCamera::orbit(float dxPixels, float dyPixels) {
    yaw_ = wrapDegrees(yaw_ - dxPixels * kDegreesPerPixel);
    pitch_ = std::clamp(pitch_ - dyPixels * kDegreesPerPixel, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::dolly(float scrollSteps) {
    const float lowest = std::min(kMinDistance * radius_, distance_);
    const float highest = std::max(kMaxDistance * radius_, distance_);
    distance_ = std::clamp(distance_ * std::pow(kDollyPerStep, scrollSteps), lowest, highest);
}

// From the target towards the eye, unit length.
glm::vec3 OrbitCamera::direction() const {
    const float yaw = glm::radians(yaw_), pitch = glm::radians(pitch_);
    return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
}

glm::vec3 OrbitCamera::position() const {
    return target_ + distance_ * direction();
}

float OrbitCamera::nearPlane() const {
    return std::max(distance_ - kClipMargin * radius_, kNearFloor * distance_);
}

float OrbitCamera::farPlane() const {
    return distance_ + kClipMargin * radius_;
}

glm::mat4 OrbitCamera::viewMatrix() const {
    // Rotation from the direction itself, not from position() - target: a small model far from
    // the origin would lose its view direction to the rounding of that difference.
    return glm::lookAt(distance_ * direction(), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f)) *
           glm::translate(glm::mat4(1.0f), -target_);
}

glm::mat4 OrbitCamera::projectionMatrix(float aspect) const {
    return glm::perspective(glm::radians(kFovYDegrees), aspect, nearPlane(), farPlane());
}

Frustum::Frustum(const glm::mat4& m) {
    // Clip space keeps -w <= x, y, z <= w: each bound is a row of m added to or taken from the
    // last row (glm is column-major: m[column][row]).
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            glm::vec4 plane;
            for (int column = 0; column < 4; ++column) {
                plane[column] = m[column][3] + (side == 0 ? m[column][axis] : -m[column][axis]);
            }
            planes_[size_t(2 * axis + side)] = plane / glm::length(glm::vec3(plane));
        }
    }
}

bool Frustum::mayContain(const glm::vec3& centre, float radius) const {
    const float margin = radius * 1.001f + 1e-5f;
    for (const glm::vec4& plane : planes_) {
        if (glm::dot(glm::vec3(plane), centre) + plane.w < -margin) return false;
    }
    return true;
}

}  // namespace pbr
