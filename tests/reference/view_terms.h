#pragma once
// The CPU side of the term views every reference test of them shares, by their definitions in
// 01's README: the inputs as they are (the normal as 0.5 + 0.5 N), and each light-dependent term
// of one light (cpu::cookTorrance), to be summed over the lights that reach the point.
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "math/brdf.h"

namespace pbr::test {

// An input's view at `s` (albedo, normal, metallic, roughness, ao, f0); nullopt for other views.
std::optional<glm::dvec3> inputView(const std::string& view, const cpu::SurfacePoint& s);

// Adds to `sum` the term `view` names (d, g, f, specular, diffuse, ndotl) of one light's terms
// `t` at a surface of `albedo`; nothing for other views.
void addTermView(const std::string& view, const cpu::CookTorrance& t, const glm::vec3& albedo,
                 glm::dvec3& sum);

}  // namespace pbr::test
