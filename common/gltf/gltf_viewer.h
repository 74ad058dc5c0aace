#pragma once
// The glTF samples' whole program (07 metallic-roughness, 08 specular-glossiness): a glTF file
// drawn by GltfRenderer under 05's image-based light and the file's punctual lights, through an
// orbit camera and a tone mapper, with the flags both samples share (--model, --hdr, --no-cache,
// --tonemap, --exposure, --no-ibl, --no-punctual, --single-scattering). A sample names itself and
// its default asset.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace pbr {

struct GltfViewerConfig {
    std::string name;                     // "07_gltf_metallic_roughness": messages, --help
    std::string title;                    // the window's
    std::filesystem::path defaultModel;   // drawn without --model
    std::string defaultModelDescription;  // for --help: "the project's PBR showcase"
    // Labels over the default model, in a window (and with --panel): each at a point given as
    // fractions of the model's bounds ({0.5, 1, 0.5}: above the middle).
    struct Label {
        glm::vec3 atBounds;
        std::string text;
    };
    std::vector<Label> defaultModelLabels{};
    // Where the orbit camera starts on the default model (without --camera); unset: it frames
    // the model's bounds.
    std::optional<glm::vec3> defaultModelCamera{};
    // Draws the advanced material's layers (sample 10: KHR_materials_clearcoat, _sheen,
    // _transmission, _volume, _ior, _specular, _emissive_strength); 07 and 08 draw the core
    // material alone.
    bool extensions = false;
};

// Runs the sample to its end; returns the exit code. Throws Error for bad input (the caller's
// catch reports it, as every sample's main does).
int runGltfViewer(int argc, char** argv, const GltfViewerConfig& config);

}  // namespace pbr
