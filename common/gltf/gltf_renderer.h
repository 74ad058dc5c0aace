#pragma once
// Draws a GpuModel with the glTF shading path (shaders/include/gltf_material.glsl and
// punctual_lights.glsl): each primitive's material into the shader's uniforms, its textures with
// their samplers on units 0-4, and the order and state glTF asks for: opaque and masked
// primitives first, then the blended ones back to front without depth writes; back faces culled
// unless the material is double-sided; the winding flipped under a mirroring node transform.
// Shared by the glTF samples (07, 08, 10); the IBL maps (units 5-8) and the camera are the
// sample's, set on each program by the frame's callback.
//
// The core material (07, 08) is drawn by one program. The advanced material (sample 10) by one
// program a set of layers: a material's layers (materialLayers: GLTF_EXTENSIONS, and CLEARCOAT,
// SHEEN, SPECULAR, TRANSMISSION for those it uses) are #defines, so a layer's code and textures
// are compiled only into the programs of the materials that use it, and a material without
// extensions gets the core material's program. Each layer's textures take the units after the
// IBL maps', in that order (layerUnits).
//
// A transmissive primitive (KHR_materials_transmission, with KHR_materials_volume) shows what is
// behind it as the reference viewer and the cookbook draw it: the frame's backdrop first (the
// caller's background, then every primitive that is not transmissive, as linear radiance) into a
// float target of kBackdropSize^2 seen by the frame's camera, its mip chain made; then the frame,
// the transmissive primitives after the opaque ones, back to front, each reading the backdrop
// along its refracted ray at the blur of its roughness.
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/shader.h"
#include "gl/texture.h"
#include "gltf/model.h"
#include "math/punctual_light.h"

namespace pbr {

// The #defines of the advanced material's layers `material` uses: empty for the core material
// alone; else GLTF_EXTENSIONS (ior, KHR_materials_specular's factors, emissive strength) and
// CLEARCOAT (a clear coat of factor above 0), SHEEN (a sheen colour other than black), SPECULAR
// (KHR_materials_specular's textures), TRANSMISSION (a transmission factor above 0; the volume
// goes with it: without transmission the extension has nothing to act on).
std::vector<std::string> materialLayers(const Material& material);
// The layers' factors changed live (10's flags --clearcoat, --ior, ...): each one given replaces
// that factor in every material that has its layer, and leaves the others as their files have
// them (a plain material is given no clear coat, a backdrop no transmission). A clear coat, a
// sheen, a transmission: by the factor that makes the layer (materialLayers), the volume's with
// the transmission. The index of refraction, KHR_materials_specular's factors and the emissive
// strength are every material's (one without the extension has its default: 1.5, 1, 1). A
// factor taken to 0 takes its layer away with it, as in a file.
struct LayerFactors {
    std::optional<float> clearcoat{}, clearcoatRoughness{};
    std::optional<glm::vec3> sheenColor{};
    std::optional<float> sheenRoughness{};
    std::optional<float> transmission{}, thickness{};
    std::optional<glm::vec3> attenuationColor{};
    std::optional<float> attenuationDistance{};
    std::optional<float> ior{}, specular{};
    std::optional<glm::vec3> specularColor{};
    std::optional<float> emissiveStrength{};
};
Material withLayerFactors(const Material& material, const LayerFactors& factors);

// The texture units a program of `layers` needs (the core material's, the IBL maps', each
// layer's); throws Error("material 'NAME': its layers need N texture units, where this GL has
// M") past `available` (GL_MAX_TEXTURE_IMAGE_UNITS: 16 in WebGL 2, often 32 natively).
int textureUnitsNeeded(const std::vector<std::string>& layers);
void requireTextureUnits(const std::vector<std::string>& layers, int available,
                         const std::string& material);

class GltfRenderer {
public:
    static constexpr int kMaxLights = 8;  // MAX_PUNCTUAL_LIGHTS of punctual_lights.glsl
    // The split-sum maps' units (pbr::useIblMaps(shader, ..., kFirstIblUnit)): set even when no
    // maps are bound, so no two sampler types ever share a unit.
    static constexpr int kFirstIblUnit = 5;
    static constexpr int kFirstLayerUnit = kFirstIblUnit + 4;
    // tonemap.glsl's LINEAR_RADIANCE: the "tone mapper" the backdrop is drawn with (the
    // radiance as it is, for a float target).
    static constexpr int kLinearRadiance = -2;
    // The transmission backdrop's width and height (the reference viewer's).
    static constexpr int kBackdropSize = 1024;

    // The program for a set of layers' #defines (empty: the core material's).
    using ProgramFor = std::function<Shader&(const std::vector<std::string>& layers)>;
    // What the frame sets on a program before its first primitive of a draw: the camera, the
    // lights, the IBL maps' units.
    using SetFrame = std::function<void(Shader&)>;

    // Draws the core material alone (07, 08: every primitive with `programFor({})`), or with
    // `extensions` the advanced material's layers too (sample 10).
    explicit GltfRenderer(ProgramFor programFor, bool extensions = false);
    // Whether the layers are drawn from the next draw on (the term views show the core
    // material's terms, without them).
    void setExtensions(bool extensions) { extensions_ = extensions; }
    // The factors every frame's materials take from here rather than from their files (none by
    // default).
    void setLayerFactors(const LayerFactors& factors) { layerFactors_ = factors; }
    // The layers' maps (sample 10): their LUT (BrdfLutChannels::ScaleBiasSheen: the sheen's
    // albedo in A, and the split sum's scale and bias, which the transmission's Fresnel reads
    // without image-based light), and the sheen's prefiltered environment
    // (IblEnvironment::sheenMap; null without image-based light). Kept by pointer.
    void setLayerMaps(const Texture2D* layersLut, const TextureCube* sheenMap);

    // Sets a program's texture units for its layers (draw does, for each program it uses).
    void setUnits(Shader& program, const std::vector<std::string>& layers) const;
    // Whether draw is drawing the backdrop now (for SetFrame: the picture, whatever the view).
    bool drawingBackdrop() const { return backdropPass_; }
    // Uploads up to kMaxLights lights to `program`; returns how many were left out.
    static int setLights(Shader& program, std::span<const PunctualLight> lights);
    // Draws every primitive of `model`, placed by `world` x its node transform. With the layers
    // and a transmissive primitive, the backdrop first: `background` (the sky, drawn with
    // kLinearRadiance; none: the clear colour alone) and the other primitives into it; then the
    // frame, into the framebuffer and viewport bound when it was called.
    void draw(const GpuModel& model, const glm::mat4& world, const glm::mat4& view,
              const SetFrame& setFrame, const std::function<void()>& background = {});

private:
    // The program of `layers` (materialLayers of `material`), made current, its units and frame
    // set before its first primitive of a draw.
    Shader& programFor(const Material& material, const std::vector<std::string>& layers,
                       const SetFrame& setFrame);
    void setMaterial(Shader& program, const GpuModel& model, const Material& material,
                     const std::vector<std::string>& layers);
    // Draws one primitive with its material's program.
    void drawWithMaterial(const GpuModel& model, const GpuModel::Primitive& primitive,
                          const glm::mat4& world, const SetFrame& setFrame);
    void drawPrimitive(Shader& program, const GpuModel::Primitive& primitive,
                       const glm::mat4& world);
    // One pass over the primitives: the opaque and masked ones, then (unless `backdrop`, which
    // leaves them out) the transmissive ones, then the blended ones, each group's in glTF's order.
    void drawPass(const GpuModel& model, const glm::mat4& world, const glm::mat4& view,
                  const SetFrame& setFrame, bool backdrop);
    bool transmissive(const Material& material) const;
    // The backdrop of this frame: drawn, its mips made, the caller's framebuffer bound again.
    void drawBackdrop(const GpuModel& model, const glm::mat4& world, const glm::mat4& view,
                      const SetFrame& setFrame, const std::function<void()>& background);

    ProgramFor programFor_;
    bool extensions_ = false;
    LayerFactors layerFactors_;
    const TextureCube* sheenMap_ = nullptr;
    const Texture2D* layersLut_ = nullptr;
    Texture2D white_;
    int maxTextureUnits_ = 0;  // GL_MAX_TEXTURE_IMAGE_UNITS
    std::vector<Shader*> prepared_;  // the programs of this pass, units and frame set
    int largestUnit_ = 0;            // the highest unit a draw bound, unbound after it
    bool backdropPass_ = false;      // drawing the backdrop: linear radiance out
    struct Backdrop;                 // its framebuffer, made at the first transmissive draw
    std::shared_ptr<Backdrop> backdrop_;
    int backdropUnit_ = -1;          // where a draw bound the backdrop (unbound after it)
};

// One light for files that bring none: a white directional light of `lux`, from above the
// viewer's right shoulder (down and away from a camera looking along -Z).
PunctualLight defaultLight(float lux = 3.0f);

}  // namespace pbr
