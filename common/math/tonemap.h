#pragma once
// The tone mappers of sample 07 on the CPU: the same formulas, constants and order as toneMap() in
// shaders/include/tonemap.glsl (a GL test holds the two together within 1/255), and the one
// table of their names for the --tonemap flag. GLM only, no GL.
//
// toneMap(color, mapper, exposure): c = max(color * exposure, 0), then
//   None            clamp(c, 0, 1)
//   Reinhard        c / (1 + c), per channel
//   Aces            Stephen Hill's fit of the ACES RRT + sRGB ODT (BakingLab's ACES.hlsl, as in
//                   Khronos' glTF Sample Viewer): c / 0.6 (the Sample Viewer's "exposure boost",
//                   three.js' ACESFilmicToneMapping), into AP1 with the RRT's saturation, the
//                   rational fit (c (c + 0.0245786) - 0.000090537) /
//                   (c (0.983729 c + 0.4329510) + 0.238081), back to linear sRGB, clamped to [0,1]
//   KhronosNeutral  Khronos PBR Neutral (Khronos' reference GLSL): the toe offset
//                   (x - 6.25 x^2 for x = min channel < 0.08, else 0.04) subtracted; a peak
//                   (max channel) below 0.8 - 0.04 is left so; above, the peak is compressed to
//                   1 - 0.24^2 / (peak + 0.24 - 0.76) with the hue kept, then mixed towards white
//                   by 1 - 1 / (0.15 (peak - newPeak) + 1)
// The result is linear display light in [0, 1]: the caller's sRGB render target encodes it.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace pbr::cpu {

// The values are those of the GLSL constants TONEMAP_NONE ... TONEMAP_KHRONOS_NEUTRAL: pass
// int(mapper) to the shader.
enum class ToneMapper { None = 0, Reinhard = 1, Aces = 2, KhronosNeutral = 3 };

struct ToneMapperName {
    ToneMapper mapper;
    std::string_view name;
};
inline constexpr std::array<ToneMapperName, 4> kToneMapperNames{{
    {ToneMapper::None, "none"},
    {ToneMapper::Reinhard, "reinhard"},
    {ToneMapper::Aces, "aces"},
    {ToneMapper::KhronosNeutral, "khronos-neutral"},
}};

std::string_view toneMapperName(ToneMapper mapper);
// nullopt for a word that is no mapper's name.
std::optional<ToneMapper> toneMapperFromName(std::string_view name);
// Every name, `first` first, the others in the table's order: the list for
// FlagSpec::choice("--tonemap", toneMapperChoices(default), ...), whose first word is the default.
std::vector<std::string> toneMapperChoices(ToneMapper first);

glm::vec3 toneMap(glm::vec3 color, ToneMapper mapper, float exposure);

}  // namespace pbr::cpu
