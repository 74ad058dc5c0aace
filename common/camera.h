#pragma once
// The fly camera of LearnOpenGL's text, with its semantics kept: yaw -90 looks down -Z, pitch is
// clamped to +-89 degrees, the zoom is the vertical field of view (45, scroll narrows it to 1),
// WASD moves at 2.5 units a second, mouse sensitivity 0.1. Pure math: no OpenGL.
#include <glm/glm.hpp>

namespace pbr {

enum class CameraMove { Forward, Backward, Left, Right };

class FlyCamera {
public:
    static constexpr float kDefaultYaw = -90.0f;
    static constexpr float kDefaultPitch = 0.0f;
    static constexpr float kDefaultZoom = 45.0f;
    static constexpr float kNear = 0.1f;
    static constexpr float kFar = 100.0f;

    explicit FlyCamera(glm::vec3 position = {0.0f, 0.0f, 3.0f}, float yaw = kDefaultYaw,
                       float pitch = kDefaultPitch);

    void processKeyboard(CameraMove direction, float deltaTime);
    void processMouseMovement(float xOffset, float yOffset, bool constrainPitch = true);
    void processMouseScroll(float yOffset);

    glm::mat4 viewMatrix() const;
    // perspective(radians(zoom), aspect, 0.1, 100): the field of view in radians, as it must be.
    glm::mat4 projectionMatrix(float aspect) const;

    glm::vec3 position() const { return position_; }
    glm::vec3 front() const { return front_; }
    glm::vec3 right() const { return right_; }
    glm::vec3 up() const { return up_; }
    float yaw() const { return yaw_; }
    float pitch() const { return pitch_; }
    float zoom() const { return zoom_; }

    float movementSpeed = 2.5f;
    float mouseSensitivity = 0.1f;

private:
    void updateVectors();

    glm::vec3 position_;
    glm::vec3 front_{0.0f, 0.0f, -1.0f};
    glm::vec3 right_{1.0f, 0.0f, 0.0f};
    glm::vec3 up_{0.0f, 1.0f, 0.0f};
    glm::vec3 worldUp_{0.0f, 1.0f, 0.0f};
    float yaw_;
    float pitch_;
    float zoom_ = kDefaultZoom;
};

// Frames a model: `normalize` moves its bounding box's centre to the origin and scales its
// bounding sphere to radius 1; a camera at `cameraPosition` (yaw -90, pitch 0) then sees the whole
// sphere with a margin, at any aspect, within the fly camera's near and far planes.
struct Framing {
    glm::mat4 normalize;
    glm::vec3 cameraPosition;
};
Framing frameBounds(const glm::vec3& boundsMin, const glm::vec3& boundsMax, float fovYDegrees,
                    float aspect);

}  // namespace pbr
