#include "math/tonemap.h"

#include <algorithm>

namespace pbr::cpu {

namespace {

// GLM's mat3 takes columns, as GLSL's does: these are the shader's matrices letter for letter.
// sRGB -> XYZ -> D65 to D60 -> AP1 -> the RRT's saturation.
const glm::mat3 kAcesInput(0.59719f, 0.07600f, 0.02840f,   //
                           0.35458f, 0.90834f, 0.13383f,   //
                           0.04823f, 0.01566f, 0.83777f);  //
// The ODT's saturation -> XYZ -> D60 to D65 -> sRGB.
const glm::mat3 kAcesOutput(1.60475f, -0.10208f, -0.00327f,   //
                            -0.53108f, 1.10813f, -0.07276f,   //
                            -0.07367f, -0.00605f, 1.07602f);  //
constexpr float kAcesExposureBoost = 1.0f / 0.6f;

glm::vec3 acesRrtOdtFit(const glm::vec3& v) {
    const glm::vec3 a = v * (v + 0.0245786f) - 0.000090537f;
    const glm::vec3 b = v * (0.983729f * v + 0.4329510f) + 0.238081f;
    return a / b;
}

glm::vec3 aces(const glm::vec3& color) {
    const glm::vec3 fitted = acesRrtOdtFit(kAcesInput * (color * kAcesExposureBoost));
    return glm::clamp(kAcesOutput * fitted, 0.0f, 1.0f);
}

glm::vec3 khronosNeutral(glm::vec3 color) {
    constexpr float startCompression = 0.8f - 0.04f;
    constexpr float desaturation = 0.15f;
    const float x = std::min({color.r, color.g, color.b});
    const float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
    color -= offset;
    const float peak = std::max({color.r, color.g, color.b});
    if (peak < startCompression) return color;
    constexpr float d = 1.0f - startCompression;
    const float newPeak = 1.0f - d * d / (peak + d - startCompression);
    color *= newPeak / peak;
    const float g = 1.0f - 1.0f / (desaturation * (peak - newPeak) + 1.0f);
    return glm::mix(color, glm::vec3(newPeak), g);
}

}  // namespace

std::string_view toneMapperName(ToneMapper mapper) {
    for (const ToneMapperName& entry : kToneMapperNames) {
        if (entry.mapper == mapper) return entry.name;
    }
    return "unknown";
}

std::optional<ToneMapper> toneMapperFromName(std::string_view name) {
    for (const ToneMapperName& entry : kToneMapperNames) {
        if (entry.name == name) return entry.mapper;
    }
    return std::nullopt;
}

std::vector<std::string> toneMapperChoices(ToneMapper first) {
    std::vector<std::string> names{std::string(toneMapperName(first))};
    for (const ToneMapperName& entry : kToneMapperNames) {
        if (entry.mapper != first) names.emplace_back(entry.name);
    }
    return names;
}

glm::vec3 toneMap(glm::vec3 color, ToneMapper mapper, float exposure) {
    color = glm::max(color * exposure, glm::vec3(0.0f));
    switch (mapper) {
        case ToneMapper::Reinhard:
            color = color / (color + 1.0f);
            break;
        case ToneMapper::Aces:
            color = aces(color);
            break;
        case ToneMapper::KhronosNeutral:
            color = khronosNeutral(color);
            break;
        case ToneMapper::None:
            break;
    }
    return glm::clamp(color, 0.0f, 1.0f);
}

}  // namespace pbr::cpu
