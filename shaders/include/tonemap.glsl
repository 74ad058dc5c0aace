// The output transform of the direct-light samples: Reinhard, then gamma 1/2.2.
// Mirrored on the CPU by pbr::cpu::reinhardGamma.

vec3 reinhard(vec3 color)
{
    return color / (color + vec3(1.0));
}

vec3 gammaCorrect(vec3 color)
{
    return pow(color, vec3(1.0 / 2.2));
}

// The tone mappers of sample 07 (mirrored on the CPU by pbr::cpu::toneMap, common/math/tonemap.h,
// which documents the formulas and their sources). toneMap multiplies by the exposure, maps, and
// returns linear display values in [0, 1] for an sRGB render target to encode; negative input
// counts as 0, and an unknown mapper as TONEMAP_NONE. LINEAR_RADIANCE is no tone mapper: the
// radiance itself, without exposure or clamping, for a float render target (sample 10's
// transmission backdrop, pbr::GltfRenderer::kLinearRadiance).
const int LINEAR_RADIANCE = -2;
const int TONEMAP_NONE = 0;
const int TONEMAP_REINHARD = 1;
const int TONEMAP_ACES = 2;
const int TONEMAP_KHRONOS_NEUTRAL = 3;

// ACES, Stephen Hill's fit of the RRT + sRGB ODT (as in Khronos' glTF Sample Viewer).
// sRGB -> XYZ -> D65 to D60 -> AP1 -> the RRT's saturation (columns, as GLSL takes them)
const mat3 ACES_INPUT = mat3(0.59719, 0.07600, 0.02840,
                             0.35458, 0.90834, 0.13383,
                             0.04823, 0.01566, 0.83777);
// the ODT's saturation -> XYZ -> D60 to D65 -> sRGB
const mat3 ACES_OUTPUT = mat3( 1.60475, -0.10208, -0.00327,
                              -0.53108,  1.10813, -0.07276,
                              -0.07367, -0.00605,  1.07602);

vec3 acesRrtOdtFit(vec3 v)
{
    vec3 a = v * (v + 0.0245786) - 0.000090537;
    vec3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
    return a / b;
}

// With the Sample Viewer's "exposure boost" (color / 0.6, three.js' ACESFilmicToneMapping): the
// fit alone maps mid grey 0.18 to 0.11; boosted, to 0.21, near the other mappers at exposure 1.
vec3 toneMapAces(vec3 color)
{
    color = acesRrtOdtFit(ACES_INPUT * (color / 0.6));
    return clamp(ACES_OUTPUT * color, 0.0, 1.0);
}

// Khronos PBR Neutral, Khronos' reference formula.
vec3 toneMapKhronosNeutral(vec3 color)
{
    const float startCompression = 0.8 - 0.04;
    const float desaturation = 0.15;
    float x = min(color.r, min(color.g, color.b));
    float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    color -= offset;
    float peak = max(color.r, max(color.g, color.b));
    if (peak < startCompression) return color;
    const float d = 1.0 - startCompression;
    float newPeak = 1.0 - d * d / (peak + d - startCompression);
    color *= newPeak / peak;
    float g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    return mix(color, vec3(newPeak), g);
}

vec3 toneMap(vec3 color, int mapper, float exposure)
{
    if (mapper == LINEAR_RADIANCE)
        return color;
    color = max(color * exposure, vec3(0.0));
    if (mapper == TONEMAP_REINHARD) color = reinhard(color);
    else if (mapper == TONEMAP_ACES) color = toneMapAces(color);
    else if (mapper == TONEMAP_KHRONOS_NEUTRAL) color = toneMapKhronosNeutral(color);
    return clamp(color, 0.0, 1.0);
}
