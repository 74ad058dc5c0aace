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

}  // namespace pbr
