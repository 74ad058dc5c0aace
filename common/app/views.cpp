#include "app/views.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <utility>
#include <vector>

#include "base/error.h"

namespace pbr {

namespace {
struct Named {
    View view;
    std::string_view name;
};
constexpr Named kNames[] = {
    {View::Final, "final"},
    {View::Albedo, "albedo"},
    {View::Normal, "normal"},
    {View::Metallic, "metallic"},
    {View::Roughness, "roughness"},
    {View::Ao, "ao"},
    {View::F0, "f0"},
    {View::D, "d"},
    {View::G, "g"},
    {View::F, "f"},
    {View::Specular, "specular"},
    {View::Diffuse, "diffuse"},
    {View::NdotL, "ndotl"},
    {View::Direct, "direct"},
    {View::Irradiance, "irradiance"},
    {View::Prefiltered, "prefiltered"},
    {View::Lut, "lut"},
    {View::AmbientDiffuse, "ambient-diffuse"},
    {View::AmbientSpecular, "ambient-specular"},
    {View::Ambient, "ambient"},
    {View::BaseColor, "base-color"},
    {View::Occlusion, "occlusion"},
    {View::Emissive, "emissive"},
    {View::Attenuation, "attenuation"},
    {View::Cone, "cone"},
    {View::Ks, "ks"},
    {View::Kd, "kd"},
    {View::FScaleBias, "f-scale-bias"},
    {View::Visibility, "visibility"},
    {View::MultipleScattering, "multiple-scattering"},
    {View::Clearcoat, "clearcoat"},
    {View::Sheen, "sheen"},
    {View::SheenScaling, "sheen-scaling"},
    {View::Transmission, "transmission"},
    {View::Transmitted, "transmitted"},
    {View::ClearcoatNormal, "clearcoat-normal"},
    {View::VolumeAttenuation, "volume-attenuation"},
};
}  // namespace

std::string_view viewName(View view) {
    for (const Named& named : kNames) {
        if (named.view == view) return named.name;
    }
    throw Error("view " + std::to_string(int(view)) + " has no name");
}

namespace {
// What each view shows, and its encoding (the scale bar follows from the encoding).
struct Caption {
    View view;
    const char* shows;
    ViewScale scale;
};
constexpr const char* kCompressed = "x / (1 + x)";
constexpr Caption kCaptions[] = {
    {View::Albedo, "the material's albedo, linear", ViewScale::AsItIs},
    {View::BaseColor, "factor x vertex colour x texture, linear", ViewScale::AsItIs},
    {View::Normal, "the world-space shading normal N, as 0.5 + 0.5 N", ViewScale::None},
    {View::Metallic, "the material's metallic", ViewScale::AsItIs},
    {View::Roughness, "the material's roughness", ViewScale::AsItIs},
    {View::Ao, "the ambient occlusion", ViewScale::AsItIs},
    {View::Occlusion, "1 + strength (texture's R - 1)", ViewScale::AsItIs},
    {View::Emissive, "factor x texture, linear", ViewScale::AsItIs},
    {View::F0, "the reflectance at normal incidence, mix(0.04, albedo, metallic)",
     ViewScale::AsItIs},
    {View::D, "the GGX distribution D, summed over the lights that reach the point",
     ViewScale::Compressed},
    {View::G, "the Smith masking-shadowing G, summed likewise", ViewScale::Compressed},
    {View::Visibility, "the visibility G / (4 NdotL NdotV), summed likewise",
     ViewScale::Compressed},
    {View::F, "Fresnel F, summed likewise", ViewScale::Compressed},
    {View::Specular, "the specular term, summed likewise", ViewScale::Compressed},
    {View::Diffuse, "the diffuse term, summed likewise", ViewScale::Compressed},
    {View::NdotL, "NdotL, summed likewise", ViewScale::Compressed},
    {View::Direct, "the direct light alone, tone-mapped as the picture", ViewScale::None},
    {View::Ambient, "the ambient light alone, tone-mapped as the picture", ViewScale::None},
    {View::Irradiance, "the irradiance map at N", ViewScale::Compressed},
    {View::Prefiltered, "the prefiltered map along R at the roughness's level",
     ViewScale::Compressed},
    {View::Lut, "the BRDF LUT's scale (red) and bias (green) at (NdotV, roughness)",
     ViewScale::AsItIs},
    {View::AmbientDiffuse, "the ambient light's diffuse part x ao", ViewScale::Compressed},
    {View::AmbientSpecular, "the ambient light's specular part x ao", ViewScale::Compressed},
    {View::Attenuation, "1 / (c + l d + q d^2), summed over the point and spot lights",
     ViewScale::Compressed},
    {View::Cone, "the spot's cone factor", ViewScale::AsItIs},
    {View::Ks, "kS, what the ambient light's specular part takes", ViewScale::AsItIs},
    {View::Kd, "kD, what its diffuse part gets", ViewScale::AsItIs},
    {View::FScaleBias, "F x scale + bias, the factor on the prefiltered radiance",
     ViewScale::AsItIs},
    {View::MultipleScattering, "the share multiple scattering adds to the lobes",
     ViewScale::Compressed},
    {View::Clearcoat, "the coat's share, clearcoat x Fc(N_coat . V)", ViewScale::AsItIs},
    {View::Sheen, "the sheen's light, its lobe summed over the lights plus its image-based part",
     ViewScale::Compressed},
    {View::SheenScaling, "what the base keeps under the sheen, 1 - max(sheenColor) E(NdotV)",
     ViewScale::AsItIs},
    {View::Transmission, "transmission x texture, the diffuse's share light through replaces",
     ViewScale::AsItIs},
    {View::Transmitted, "the light through the surface alone, tone-mapped as the picture",
     ViewScale::None},
    {View::ClearcoatNormal, "the clear coat's world-space normal N_coat, as 0.5 + 0.5 N_coat",
     ViewScale::None},
    {View::VolumeAttenuation,
     "what the volume leaves along the refracted ray, attenuationColor^(d / attenuationDistance)",
     ViewScale::AsItIs},
};

const Caption* captionOf(View view) {
    for (const Caption& caption : kCaptions) {
        if (caption.view == view) return &caption;
    }
    return nullptr;
}
}  // namespace

std::string viewCaption(View view) {
    const Caption* caption = captionOf(view);
    if (!caption) return "";
    const char* encoding = caption->scale == ViewScale::Compressed ? kCompressed
                           : caption->scale == ViewScale::AsItIs   ? "as it is"
                                                                   : "";
    return std::string(viewName(view)) + ": " + caption->shows +
           (*encoding ? std::string("; ") + encoding : std::string());
}

ViewScale viewScale(View view) {
    const Caption* caption = captionOf(view);
    return caption ? caption->scale : ViewScale::None;
}

std::string viewConstant(View view) {
    std::string constant = "VIEW_";
    for (char c : viewName(view))
        constant += c == '-' ? '_' : char(std::toupper(static_cast<unsigned char>(c)));
    return constant;
}

FlagSpec viewFlag(std::span<const View> views) {
    std::vector<std::string> names;
    for (View view : views) names.emplace_back(viewName(view));
    // LearnOpenGL's albedo and ao are the glTF texts' base colour and occlusion: a sample takes
    // the other text's word too, so that a view keeps its name from one sample to the next.
    std::vector<std::pair<std::string, std::string>> aliases;
    const auto has = [&](View view) {
        return std::find(views.begin(), views.end(), view) != views.end();
    };
    constexpr std::pair<View, View> kSameInput[] = {{View::Albedo, View::BaseColor},
                                                    {View::Ao, View::Occlusion}};
    for (const auto& [ours, theirs] : kSameInput) {
        if (has(ours) && !has(theirs)) aliases.emplace_back(viewName(theirs), viewName(ours));
        if (has(theirs) && !has(ours)) aliases.emplace_back(viewName(ours), viewName(theirs));
    }
    return FlagSpec::choice("--view", std::move(names),
                            "show one input or term of the equation instead of the picture "
                            "(default final: the picture; see README.md, \"Term views\")")
        .withAliases(std::move(aliases));
}

std::vector<View> allViews() {
    std::vector<View> views;
    for (const Named& named : kNames) views.push_back(named.view);
    return views;
}

View viewNamed(std::string_view name) {
    for (const Named& named : kNames) {
        if (named.name == name) return named.view;
    }
    throw Error("no view is named '" + std::string(name) + "'");
}

std::vector<std::string> viewDefines(View view) {
    if (view == View::Final) return {};
    return {"TERM_VIEWS"};
}

std::vector<ScaleTick> viewScaleTicks(ViewScale scale, float gain) {
    if (scale == ViewScale::None) return {};
    if (scale == ViewScale::AsItIs) return {{0.0f, "0"}, {0.5f, "0.5"}, {1.0f, "1"}};
    // x / (1 + x): x = 0, 0.25, 1, 4 at 0, 0.2, 0.5, 0.8; x is the value times the gain
    std::vector<ScaleTick> ticks = {{0.0f, "0"}};
    for (const auto& [at, x] : {std::pair{0.2f, 0.25f}, {0.5f, 1.0f}, {0.8f, 4.0f}}) {
        char text[16];
        std::snprintf(text, sizeof text, "%.3g", double(x / gain));
        ticks.push_back({at, text});
    }
    return ticks;
}

FlagSpec viewGainFlag() {
    return FlagSpec::number("--gain", "G",
                            "multiply a view's values by G before x / (1 + x), to read a dark "
                            "term",
                            0.01, 1000.0, 1.0)
        .asLive();
}

void selectView(Shader& shader, View view, float gain) {
    if (view == View::Final) return;
    shader.set("termView", int(view));
    shader.set("viewGain", gain);
}

std::string viewCaption(View view, float gain) {
    std::string caption = viewCaption(view);
    if (gain != 1.0f && viewScale(view) == ViewScale::Compressed) {
        caption.replace(caption.size() - std::string_view(kCompressed).size(),
                        std::string_view(kCompressed).size(),
                        "x / (1 + x) of " + flagNumberText(gain) + " x");
    }
    return caption;
}

}  // namespace pbr
