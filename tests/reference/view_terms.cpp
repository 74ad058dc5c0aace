#include "reference/view_terms.h"

#include <numbers>

namespace pbr::test {

std::optional<glm::dvec3> inputView(const std::string& view, const cpu::SurfacePoint& s) {
    if (view == "albedo") return glm::dvec3(s.albedo);
    if (view == "normal") return 0.5 + 0.5 * glm::dvec3(s.normal);
    if (view == "metallic") return glm::dvec3(s.metallic);
    if (view == "roughness") return glm::dvec3(s.roughness);
    if (view == "ao") return glm::dvec3(s.ao);
    if (view == "f0") return glm::dvec3(glm::mix(glm::vec3(0.04f), s.albedo, s.metallic));
    return std::nullopt;
}

void addTermView(const std::string& view, const cpu::CookTorrance& t, const glm::vec3& albedo,
                 glm::dvec3& sum) {
    if (view == "d") sum += glm::dvec3(t.D);
    if (view == "g") sum += glm::dvec3(t.G);
    if (view == "f") sum += glm::dvec3(t.F);
    if (view == "specular") sum += glm::dvec3(t.specular);
    if (view == "diffuse") sum += glm::dvec3(t.kD * albedo / std::numbers::pi_v<float>);
    if (view == "ndotl") sum += glm::dvec3(t.NdotL);
}

}  // namespace pbr::test
