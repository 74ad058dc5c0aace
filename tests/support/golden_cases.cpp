#include "support/golden_cases.h"

#include <algorithm>
#include <filesystem>

#include "base/paths.h"

namespace pbr::test {

namespace {
const std::filesystem::path kAssimpGltf = "/usr/share/assimp/models/glTF2";

}  // namespace

std::vector<GoldenCase> goldenCases() {
    std::vector<GoldenCase> cases = {
        {"01_lighting", "01_lighting", {}, 0.15},  // 49 spheres cover about a quarter
        {"02_lighting_textured", "02_lighting_textured", {}, 0.1},  // dark iron near the background
        {"03_gltf_unlit", "03_gltf_unlit", {}, 0.05},
        // BoxTextured as .gltf with a .bin and a .png beside it, as .glb, and with everything
        // embedded in base64: one picture, one golden.
        {"03_box_textured",
         "03_gltf_unlit",
         {"--model", (kAssimpGltf / "BoxTextured-glTF/BoxTextured.gltf").string(), "--size",
          "480x270"},
         0.1,
         {{"--model", (kAssimpGltf / "BoxTextured-glTF-Binary/BoxTextured.glb").string(), "--size",
           "480x270"},
          {"--model", (kAssimpGltf / "BoxTextured-glTF-Embedded/BoxTextured.gltf").string(),
           "--size", "480x270"}},
         true},
        // Half a turn on (time pi): the squares' backs, each picture the right way round.
        {"03_gltf_unlit_back", "03_gltf_unlit", {"--time", "3.14159", "--size", "480x270"}, 0.03},
        {"04_ibl_irradiance", "04_ibl_irradiance"},
        {"05_ibl_specular", "05_ibl_specular"},
        {"05_ibl_specular_textured", "05_ibl_specular", {"--textured"}},
        {"06_brdf_lut", "06_brdf_lut", {}, 0.3},
        {"07_gltf_metallic_roughness", "07_gltf_metallic_roughness"},
        {"07_box_textured",
         "07_gltf_metallic_roughness",
         {"--model", (kAssimpGltf / "BoxTextured-glTF/BoxTextured.gltf").string(), "--size",
          "480x270", "--camera", "1.2,0.9,1.6"},
         0.1,
         {},
         true},
        // 08: the two workflows side by side; the copy that lists the extension as required
        // draws the same bytes.
        {"08_gltf_specular_glossiness",
         "08_gltf_specular_glossiness",
         {},
         0.05,
         {{"--model", (modelDir() / "pbr_workflows_required.gltf").string()}}},
        {"08_box_textured_spec_gloss",
         "08_gltf_specular_glossiness",
         {"--model",
          (kAssimpGltf / "BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf").string(),
          "--size", "480x270", "--camera", "1.2,0.9,1.6"},
         0.1,
         {},
         true},
        // 10: the advanced material's layers, a row each, on the project's showcase
        {"10_gltf_advanced_materials", "10_gltf_advanced_materials", {}, 0.2},
    };
    // The live panel drawn into the picture (--panel), over 01's grid: the controls made from
    // 01's flag declarations, the command line of the view.
    cases.push_back({"01_panel", "01_lighting", {"--panel", "--size", "960x540"}, 0.15});
    // A view's caption in the picture (--caption): its name, formula and encoding, the scale bar
    // of x / (1 + x), over 01's d; and 07's base colour, whose scale is as it is.
    cases.push_back({"01_view_d_caption",
                     "01_lighting",
                     {"--view", "d", "--caption", "--size", "960x540"},
                     0.1});
    cases.push_back({"07_view_base_color_caption",
                     "07_gltf_metallic_roughness",
                     {"--view", "base-color", "--caption", "--size", "960x540"},
                     0.1});
    // 01's term views that teach most (01's README, "Term views"), at a small size.
    for (const char* view : {"d", "g", "f", "diffuse", "normal"}) {
        cases.push_back({std::string("01_view_") + view,
                         "01_lighting",
                         {"--view", view, "--size", "480x270"},
                         0.1});
    }
    // 02's views of the rusted iron, on the tutorial's close-up view (02's README).
    for (const char* view : {"albedo", "normal", "metallic", "roughness", "d"}) {
        cases.push_back({std::string("02_view_") + view,
                         "02_lighting_textured",
                         {"--view", view, "--size", "480x270", "--camera", "0,0,3"},
                         0.3});
    }
    // The image-based light's views (05's README, "Term views"), and 04's parts of the light each
    // alone (04's README).
    for (const char* view :
         {"irradiance", "prefiltered", "lut", "ambient-diffuse", "ambient-specular"}) {
        std::string name = std::string("05_view_") + view;
        std::replace(name.begin(), name.end(), '-', '_');
        cases.push_back({name, "05_ibl_specular", {"--view", view, "--size", "480x270"}, 0.1});
    }
    cases.push_back({"04_view_irradiance",
                     "04_ibl_irradiance",
                     {"--view", "irradiance", "--size", "480x270"},
                     0.1});
    cases.push_back(
        {"04_lights_0", "04_ibl_irradiance", {"--lights", "0", "--size", "480x270"}, 0.1});
    cases.push_back({"04_no_ibl", "04_ibl_irradiance", {"--no-ibl", "--size", "480x270"}, 0.1});
    // 09's plain material seen through its metallic view: the metallic factors, 0 to 1 (09's
    // README).
    cases.push_back({"09_view_metallic",
                     "09_light_types",
                     {"--untextured", "--view", "metallic", "--size", "480x270"},
                     0.02});
    // 09: the whole scene, and each kind of light alone.
    cases.push_back({"09_light_types", "09_light_types", {}, 0.1});
    for (const char* only : {"point", "directional", "spot", "ambient-box", "ambient-sphere"}) {
        std::string name = std::string("09_only_") + only;
        std::replace(name.begin(), name.end(), '-', '_');
        cases.push_back({name, "09_light_types", {"--only", only, "--size", "480x270"}, 0.02});
    }
    // The four tone mappers on the showcase, side by side in 07's README.
    for (const char* mapper : {"khronos-neutral", "aces", "reinhard", "none"}) {
        std::string name = std::string("07_tonemap_") + mapper;
        std::replace(name.begin(), name.end(), '-', '_');
        cases.push_back({name,
                         "07_gltf_metallic_roughness",
                         {"--tonemap", mapper, "--size", "480x270", "--camera", "0,2.2,5.5"}});
    }
    // 07's views of the glTF material's inputs on the showcase, and 08's of the two workflows'
    // halves (07's and 08's READMEs, "Term views").
    for (const char* view : {"base-color", "metallic", "roughness", "occlusion", "emissive"}) {
        std::string name = std::string("07_view_") + view;
        std::replace(name.begin(), name.end(), '-', '_');
        cases.push_back({name,
                         "07_gltf_metallic_roughness",
                         {"--view", view, "--size", "480x270", "--camera", "0,2.2,5.5"}});
    }
    // 10's views of its layers on its showcase (10's README, "Term views")
    for (const char* view : {"clearcoat", "sheen", "sheen-scaling", "transmission", "transmitted",
                             "clearcoat-normal", "volume-attenuation", "f0"}) {
        std::string name = std::string("10_view_") + view;
        std::replace(name.begin(), name.end(), '-', '_');
        cases.push_back({name, "10_gltf_advanced_materials", {"--view", view, "--size", "480x270"}});
    }
    for (const char* view : {"f0", "roughness"}) {
        cases.push_back({std::string("08_view_") + view,
                         "08_gltf_specular_glossiness",
                         {"--view", view, "--size", "480x270"},
                         0.05});
    }
    // Beside the default (07_tonemap_khronos_neutral, multiple scattering): single scattering,
    // where rough metals darken (07's README shows both).
    cases.push_back({"07_single_scattering",
                     "07_gltf_metallic_roughness",
                     {"--single-scattering", "--size", "480x270", "--camera", "0,2.2,5.5"}});
    // The other four material sets, each on the tutorial's close-up view, at a small size.
    for (const char* set : {"gold", "grass", "plastic", "wall"}) {
        cases.push_back({std::string("02_") + set,
                         "02_lighting_textured",
                         {"--material-dir", (materialDir() / set).string(), "--size", "480x270",
                          "--camera", "0,0,3"},
                         0.3});
    }
    return cases;
}

std::vector<GoldenCase> webGoldenCases() {
    return {
        {"01_lighting", "01_lighting", {}, 0.15},
        {"02_lighting_textured", "02_lighting_textured", {}, 0.1},
        {"04_ibl_irradiance", "04_ibl_irradiance"},
        {"05_ibl_specular", "05_ibl_specular"},
        {"05_ibl_specular_textured", "05_ibl_specular", {"--textured"}},
        {"06_brdf_lut", "06_brdf_lut", {}, 0.3},
        {"09_light_types", "09_light_types", {}, 0.1},
        // the glTF samples, from the compact form of the model the native loader made
        {"03_gltf_unlit", "03_gltf_unlit", {}, 0.05},
        {"07_gltf_metallic_roughness", "07_gltf_metallic_roughness"},
        {"08_gltf_specular_glossiness", "08_gltf_specular_glossiness"},
        {"10_gltf_advanced_materials", "10_gltf_advanced_materials", {}, 0.2},
    };
}

GoldenFolder goldenFolder(const std::filesystem::path& dir, const std::vector<GoldenCase>& cases) {
    GoldenFolder folder;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const std::string extension = entry.path().extension().string();
        if (extension == ".png") folder.pictures.insert(entry.path().stem().string());
        if (extension == ".json") folder.metadata.insert(entry.path().stem().string());
    }
    for (const GoldenCase& golden : cases) folder.cases.insert(golden.golden);
    return folder;
}

}  // namespace pbr::test
