#pragma once
// The term views (--view NAME): instead of its picture a sample shows one input or one term of
// the lesson's equation, so that a learner sees D, G, F, ... one at a time. The view code is
// written once, in shaders/include/views.glsl, and compiled in only when a view is asked for (the
// shaders are built with TERM_VIEWS defined): the picture's program is the lesson's own, to the
// instruction, and costs what it always did. Which view is the `termView` uniform: the numbers
// below, which views.glsl holds as VIEW_D = 7, ... (a unit test holds the two together). Each
// view's formula and encoding is defined in the README of every sample that has it.
//
//     const pbr::View view = pbr::viewNamed(app.flagChoice("--view"));
//     pbr::Shader& shader = app.shader("common/pbr.vert", "01_lighting/pbr.frag",
//                                      pbr::viewDefines(view));
//     pbr::selectView(shader, view);
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/options.h"
#include "gl/shader.h"

namespace pbr {

enum class View {
    Final = 0,  // the picture, as without --view
    // the inputs
    Albedo = 1,
    Normal = 2,
    Metallic = 3,
    Roughness = 4,
    Ao = 5,
    F0 = 6,
    // the direct light's terms
    D = 7,
    G = 8,
    F = 9,
    Specular = 10,
    Diffuse = 11,
    NdotL = 12,
    Direct = 13,
    // the image-based light's reads and terms
    Irradiance = 14,
    Prefiltered = 15,
    Lut = 16,
    AmbientDiffuse = 17,
    AmbientSpecular = 18,
    Ambient = 19,
    // the glTF samples' names for their inputs: base colour, occlusion, and emission
    BaseColor = 20,
    Occlusion = 21,
    Emissive = 22,
    // 09's lesson: the point and spot lights' distance attenuation, and the spot's cone
    Attenuation = 23,
    Cone = 24,
    // the ambient light's weights (04, 05): kS, kD, and the specular part's factor
    Ks = 25,
    Kd = 26,
    FScaleBias = 27,
    // 07's and 08's: the BRDF's visibility term, and the image-based light's multiple scattering
    Visibility = 28,
    MultipleScattering = 29,
    // sample 10's layers: the coat's share, the sheen's light and what it leaves the base, the
    // transmission's share and the light that comes through the surface
    Clearcoat = 30,
    Sheen = 31,
    SheenScaling = 32,
    Transmission = 33,
    Transmitted = 34,
    ClearcoatNormal = 35,
    VolumeAttenuation = 36,
};

// The views of each sample, in the order --help lists them.
// clang-format off
// 07's and 08's: the glTF material's inputs, the punctual lights' terms, the split sum's.
inline constexpr View kGltfViews[] = {
    View::Final, View::BaseColor, View::Normal, View::Metallic, View::Roughness, View::Occlusion,
    View::Emissive, View::F0, View::D, View::G, View::F, View::Specular, View::Diffuse,
    View::NdotL, View::Direct, View::Irradiance, View::Prefiltered, View::Lut,
    View::AmbientDiffuse, View::AmbientSpecular, View::Ambient, View::Visibility,
    View::MultipleScattering};
// 10's: 07's, and its layers' (the core material's terms are the core material's, without them).
inline constexpr View kLayerViews[] = {
    View::Final, View::BaseColor, View::Normal, View::Metallic, View::Roughness, View::Occlusion,
    View::Emissive, View::F0, View::D, View::G, View::F, View::Specular, View::Diffuse,
    View::NdotL, View::Direct, View::Irradiance, View::Prefiltered, View::Lut,
    View::AmbientDiffuse, View::AmbientSpecular, View::Ambient, View::Visibility,
    View::MultipleScattering, View::Clearcoat, View::ClearcoatNormal, View::Sheen,
    View::SheenScaling, View::Transmission, View::Transmitted, View::VolumeAttenuation};
// Whether 10 draws a view with its layers' programs: the layers' views, and f0 (the F0 that ior
// and KHR_materials_specular give).
constexpr bool isLayerView(View view) {
    return view >= View::Clearcoat || view == View::F0;
}
// The direct-light samples' (01, 02): the text's constant ambient term among them.
inline constexpr View kDirectLightViews[] = {
    View::Final, View::Albedo, View::Normal, View::Metallic, View::Roughness, View::Ao, View::F0,
    View::D, View::G, View::F, View::Specular, View::Diffuse, View::NdotL, View::Direct,
    View::Ambient};
// 09's: those, its ambient volumes' light alone, and its lesson's two factors (--only picks the
// light types).
inline constexpr View kLightTypeViews[] = {
    View::Final, View::Albedo, View::Normal, View::Metallic, View::Roughness, View::Ao, View::F0,
    View::D, View::G, View::F, View::Specular, View::Diffuse, View::NdotL, View::Direct,
    View::Ambient, View::Attenuation, View::Cone};
// 04's: the direct-light views and its image-based light, the irradiance alone, and the weights.
inline constexpr View kIrradianceViews[] = {
    View::Final, View::Albedo, View::Normal, View::Metallic, View::Roughness, View::Ao, View::F0,
    View::D, View::G, View::F, View::Specular, View::Diffuse, View::NdotL, View::Direct,
    View::Irradiance, View::AmbientDiffuse, View::Ambient, View::Ks, View::Kd};
// 05's: the direct-light views and every read, term and weight of the split sum.
inline constexpr View kSplitSumViews[] = {
    View::Final, View::Albedo, View::Normal, View::Metallic, View::Roughness, View::Ao, View::F0,
    View::D, View::G, View::F, View::Specular, View::Diffuse, View::NdotL, View::Direct,
    View::Irradiance, View::Prefiltered, View::Lut, View::AmbientDiffuse, View::AmbientSpecular,
    View::Ambient, View::Ks, View::Kd, View::FScaleBias};
// clang-format on

// "final", "albedo", "normal", ..., "d", "g", "f", "specular", "diffuse", "ndotl", "direct",
// "irradiance", "prefiltered", "lut", "ambient-diffuse", "ambient-specular", "ambient",
// "base-color", "occlusion", "emissive".
std::string_view viewName(View view);
// What a view's picture says beside it, one line: its name, what it shows (in the READMEs'
// words, shortened) and its encoding ("d: the GGX distribution D, summed over the lights that
// reach the point; x / (1 + x)"); "" for the picture itself. The READMEs define each exactly.
std::string viewCaption(View view);
// How a view's values map to the picture's levels, for a scale bar under its caption: none (a
// normal, or a tone-mapped light), as they are (0 to 1), or x / (1 + x) (0 to infinity).
enum class ViewScale { None, AsItIs, Compressed };
ViewScale viewScale(View view);
// A tick of a scale bar: where on the bar (0 to 1, the picture's levels 0 to 255) a value lands,
// and the value's text.
struct ScaleTick {
    float at;
    std::string value;
};
// The ticks of a view's scale bar (none for ViewScale::None): 0, 0.5 and 1 as they are, or x of
// x / (1 + x) at 0, 0.25, 1 and 4, each divided by the gain (--gain) that scaled it.
std::vector<ScaleTick> viewScaleTicks(ViewScale scale, float gain);
// The shaders' VIEW_ constant of a view: "VIEW_NDOTL", "VIEW_AMBIENT_DIFFUSE".
std::string viewConstant(View view);
// --view NAME, a choice of `views` (the first is the default).
FlagSpec viewFlag(std::span<const View> views);
// Every view there is, in the order of their numbers.
std::vector<View> allViews();
// The view a --view word names (one viewFlag accepted).
View viewNamed(std::string_view name);
// What the sample's shaders are built with: nothing for the picture, TERM_VIEWS for a view.
std::vector<std::string> viewDefines(View view);
// --gain G, read every frame: a view's values shown through x / (1 + x) are multiplied by G first
// (1, the default: as they are), so that a dark term can be read; its caption says so.
FlagSpec viewGainFlag();
// Sets `termView` and `viewGain` for a view (nothing for the picture, whose program has neither).
void selectView(Shader& shader, View view, float gain = 1.0f);
// The caption with its gain said ("...; x / (1 + x) of 4 x", for a gain of 4).
std::string viewCaption(View view, float gain);

}  // namespace pbr
