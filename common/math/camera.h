#pragma once
// The cameras. Pure math: no OpenGL.
//
// FlyCamera (01-06): the fly camera of LearnOpenGL's text, with its semantics kept: yaw -90 looks
// down -Z, pitch is clamped to +-89 degrees, the zoom is the vertical field of view (45, scroll
// narrows it to 1), WASD moves at 2.5 units a second, mouse sensitivity 0.1.
//
// OrbitCamera (07 on): circles a model's centre, the way glTF viewers do, for a model of any size
// in its own units (see the class).
#include <array>

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
    // The field of view in degrees, kept in [1, kDefaultZoom] as scrolling keeps it (--fov).
    void setZoom(float degrees);

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

// An orbit camera around a model's bounding sphere (centre c, radius r), the model left in its
// own units, so a model 1 mm or 1 km across looks the same. The eye sits at
//     c + distance * (cos(pitch) sin(yaw), sin(pitch), cos(pitch) cos(yaw)),
// looking at c with +Y up: yaw 0, pitch 0 is on the +Z side looking down -Z; pitch is clamped to
// +-89 degrees. Vertical field of view 45 degrees.
//
// Near and far follow the distance d, so nothing of the model is clipped and its depth keeps its
// resolution at any dolly distance (a 24-bit depth buffer separates surfaces 0.1 % of r apart,
// unit tested):
//     far  = d + 1.05 r                          (just past the sphere's far side)
//     near = max(d - 1.05 r, 0.01 d)             (just before its near side; with the eye inside
//                                                 or at the sphere, 1 % of d: far / near <= 2200)
// The 5 % keeps the sphere's own surface off the planes; 0.01 d clips only what lies within 1 %
// of the eye's distance to the centre, and only when the eye is inside the bounding sphere.
class OrbitCamera {
public:
    static constexpr float kFovYDegrees = 45.0f;
    static constexpr float kMaxPitch = 89.0f;
    static constexpr float kDegreesPerPixel = 0.25f;  // orbit: a 360-degree turn is 1440 pixels
    static constexpr float kDollyPerStep = 0.9f;      // dolly: distance x 0.9 a scroll step in
    static constexpr float kMinDistance = 0.05f;      // dolly range, in bounding radii
    static constexpr float kMaxDistance = 50.0f;
    static constexpr float kFramingMargin = 1.1f;  // the framed sphere fills 1 / 1.1 of the view

    // The default view of a model: on the +Z side of the bounds' centre looking down -Z, pitch 0,
    // at the distance where the whole bounding sphere fits the narrower field of view (vertical,
    // or horizontal when aspect < 1) with a 10 % margin: d = 1.1 r / sin(half that field).
    static OrbitCamera framing(const glm::vec3& boundsMin, const glm::vec3& boundsMax,
                               float aspect);
    // From an explicit eye position, looking at the bounds' centre: yaw and pitch are derived
    // from the position (pitch clamped to +-89 degrees, so a position straight above or below
    // the centre moves by that 1 degree) and the distance kept as given. An eye at the centre
    // itself (closer than 1e-6 r) starts at the least distance on the +Z side.
    static OrbitCamera fromPosition(const glm::vec3& boundsMin, const glm::vec3& boundsMax,
                                    const glm::vec3& eye);

    // `radius` is floored at 1e-6 of the target's largest coordinate (and 1e-12): a point-sized
    // model still gets planes float can tell apart.
    OrbitCamera(glm::vec3 target, float radius, float distance, float yawDegrees,
                float pitchDegrees);

    // A drag of (dx, dy) pixels, y up (as InputFrame gives them): the model follows the cursor.
    // Dragging right moves the eye to its left around the target (yaw decreases); dragging up
    // moves it down (pitch decreases), 0.25 degrees a pixel.
    void orbit(float dxPixels, float dyPixels);
    // Scroll steps, positive (scroll up) closer: distance x 0.9^steps, kept within
    // [0.05 r, 50 r]. A distance already outside that range (an explicit start) is never pushed
    // further out, nor snapped into it.
    void dolly(float scrollSteps);

    glm::mat4 viewMatrix() const;
    glm::mat4 projectionMatrix(float aspect) const;  // perspective(45 deg, aspect, near, far)

    glm::vec3 position() const;
    glm::vec3 target() const { return target_; }
    float radius() const { return radius_; }
    float distance() const { return distance_; }
    float yaw() const { return yaw_; }      // degrees, in [-180, 180)
    float pitch() const { return pitch_; }  // degrees, in [-89, 89]
    float nearPlane() const;
    float farPlane() const;

private:
    glm::vec3 direction() const;

    glm::vec3 target_;
    float radius_;
    float distance_;
    float yaw_;
    float pitch_;
};

// The view volume of a projection x view matrix as its six planes (Gribb and Hartmann's
// extraction), to skip a draw that cannot reach the screen: a sphere wholly outside one plane
// makes no fragment, so leaving it out changes no pixel and saves its vertices.
class Frustum {
public:
    explicit Frustum(const glm::mat4& projectionView);
    // False only when the sphere lies wholly outside the volume, past one of its planes (with a
    // margin of a thousandth of the radius for rounding); true may still draw nothing.
    bool mayContain(const glm::vec3& centre, float radius) const;

private:
    std::array<glm::vec4, 6> planes_;  // xyz: unit inward normal, w: offset (inside: >= 0)
};

}  // namespace pbr
