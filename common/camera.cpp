#include "camera.h"

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

}  // namespace pbr
