#include "app/views.h"

#include <algorithm>
#include <cctype>
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
};
}  // namespace

std::string_view viewName(View view) {
    for (const Named& named : kNames) {
        if (named.view == view) return named.name;
    }
    throw Error("view " + std::to_string(int(view)) + " has no name");
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

void selectView(Shader& shader, View view) {
    if (view != View::Final) shader.set("termView", int(view));
}

}  // namespace pbr
