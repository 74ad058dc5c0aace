#pragma once
// The tutorial's grid of spheres: nrRows x nrColumns, `spacing` apart, centred on the origin,
// row 0 at the bottom, in the plane z (0 for the direct-light samples, -2 for the IBL ones);
// and the point lights in front of it. Plain numbers:
// setPointLights (common/gl/shader.h) hands the lights to a shader.
#include <array>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace pbr {

struct SphereGrid {
    int nrRows = 7;
    int nrColumns = 7;
    float spacing = 2.5f;
    float z = 0.0f;

    glm::vec3 position(int row, int col) const {
        return {float(col - nrColumns / 2) * spacing, float(row - nrRows / 2) * spacing, z};
    }
    glm::mat4 model(int row, int col) const {
        return glm::translate(glm::mat4(1.0f), position(row, col));
    }
};

// The four point lights of the text's grid samples (01, 04, 05), at the corners of a square in
// front of the grid.
inline constexpr std::array<glm::vec3, 4> kGridLightPositions = {
    glm::vec3(-10.0f, 10.0f, 10.0f),
    glm::vec3(10.0f, 10.0f, 10.0f),
    glm::vec3(-10.0f, -10.0f, 10.0f),
    glm::vec3(10.0f, -10.0f, 10.0f),
};

}  // namespace pbr
