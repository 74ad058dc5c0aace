#pragma once
// Image-based lighting precomputation on the GPU, GL 3.3 fragment shaders only: an
// equirectangular HDR environment becomes a cube map; from it, the diffuse irradiance and the
// specular environment prefiltered for each roughness; and the BRDF lookup table of the split-sum
// approximation. Plus the skybox that draws the environment behind a scene. ibl_cache.h keeps
// the results on disk.
#include <vector>

#include <glm/glm.hpp>

#include "gl/mesh.h"
#include "gl/shader.h"
#include "gl/texture.h"

namespace pbr {

// Draws `shader` (with shaders/ibl/cubemap.vert) over the unit cube into every face of `target`
// at mip `level`, one capture view per face; the fragment shader gets the direction as WorldPos.
void renderCubeFaces(Shader& shader, const TextureCube& target, int level);

// The environment as a cube map of `size`^2 faces, RGB16F, with a full mip chain (filtered
// reads of it need the smaller levels).
TextureCube equirectangularToCubemap(const Texture2D& equirectangular, int size);

// The environment split in two for the convolutions below: its brightest texels (a sun), which
// they sum exactly, texel by texel, and the rest, which they sample. A sun thousands of times
// brighter than the sky is what sampling gets wrong (a sample hits it or not); the rest, at most
// as bright as the brightest texel not kept apart, samples well. `rest` is the environment's mip
// level of `restSize`^2 (128 for a 512^2 environment) less what is kept apart, with a full mip
// chain; `bright` are at most kMaxBrightTexels texels of that level, each with its centre's
// direction, its exact solid angle and the radiance above the threshold it carries (in its own
// colour). rest + bright is that level of the environment, exactly.
inline constexpr int kMaxBrightTexels = 64;  // shaders/include/bright_texels.glsl's array size
struct BrightTexel {
    glm::vec3 direction;
    float solidAngle;
    glm::vec3 radiance;
};
struct SplitEnvironment {
    TextureCube rest;
    std::vector<BrightTexel> bright;
};
SplitEnvironment splitBrightTexels(const TextureCube& environment, int restSize = 128);

// Diffuse irradiance / pi of `environment` (so a constant environment L gives L), `size`^2
// faces: the bright texels summed exactly, and the rest by a sample every `sampleDelta` radians
// of the hemisphere (midpoints of whole steps), each reading the rest at the mip level of its
// cell's size.
// 0.1 (1,008 samples a texel): against a CPU sum over every texel of the project's environment,
// 0.07 % mean and 0.4 % worst error, where sampling the sun with the rest gave 3.9 % and 29 %
// (1.8 % and 12 % at 0.075), and the text's 0.025 without mip levels (15,876 samples) gives
// 4.0 % and 26 %; see tools/ibl_accuracy.cpp.
inline constexpr float kIrradianceSampleDelta = 0.1f;
TextureCube convolveIrradiance(const TextureCube& environment, int size,
                               float sampleDelta = kIrradianceSampleDelta);

// The specular environment prefiltered with the GGX lobe: `size`^2 faces, `levels` mip levels,
// level m for roughness m / (levels - 1). The bright texels are summed exactly (each weighted by
// D(H) N.L and its solid angle over the lobe's integral, prefilterNormalization); the rest by
// `samples` GGX importance samples a texel, each reading it at the mip level matching its solid
// angle. Level 0 (a mirror) is the whole environment averaged over each texel's footprint.
// 256 samples (the text takes 1,024): against a CPU sum over every texel of the project's
// environment, 0.2-0.5 % mean and 0.6-1.8 % worst error at roughness 0.25-1, where 1,024 samples
// with the sun among them gave 1.2-7.7 % and 16-62 %; see tools/ibl_accuracy.cpp.
inline constexpr int kPrefilterSamples = 256;
TextureCube prefilterSpecular(const TextureCube& environment, int size = 128, int levels = 5,
                              int samples = kPrefilterSamples);

// The integral of D_GGX(H) N.L over the directions L with N.L > 0 when N = V (H halfway between
// V and L): what the prefiltered map's weights add up to at `roughness`. 1 at roughness 1.
double prefilterNormalization(double roughness);

// The environment prefiltered by the sheen's lobe (KHR_materials_sheen's Charlie distribution,
// alpha = sheenRoughness^2; sample 10's image-based sheen): `size`^2 faces, `levels` mip levels,
// level m for sheen roughness max(m / (levels - 1), kMinSheenMapRoughness), each texel the average
// of the environment weighted by D_Charlie(H) N.L with N = V. The weight depends on L's angle from
// N alone and gathers near the horizon, so it is summed by a fixed rule: kSheenPrefilterRings
// rings of `taps` reads each, at angles spaced geometrically towards the horizon; the bright
// texels exactly, as prefilterSpecular does.
inline constexpr int kSheenPrefilterRings = 32;  // prefilter_sheen.frag's MAX_RINGS
inline constexpr float kMinSheenMapRoughness = 0.1f;  // at 0 the lobe is a line on the horizon
TextureCube prefilterSheen(const TextureCube& environment, int size = 32, int levels = 5,
                           int taps = 32);
// The integral of D_Charlie(H) N.L over the directions L with N.L > 0 when N = V: what the sheen
// map's weights add up to at `sheenRoughness`.
double sheenPrefilterNormalization(double sheenRoughness);

// The BRDF lookup table, `size`^2: x = NdotV, y = roughness, both sampled at texel centres
// ((i + 0.5) / size), row 0 at t = 0 (roughness near 0); `samples` Hammersley points.
// ScaleBias: RG16F, R = scale and G = bias to F0 of the split-sum GGX integral, with the texts'
// masking-shadowing (Schlick-GGX, k = roughness^2 / 2: LearnOpenGL's and the cookbook's LUT).
// ScaleBiasSheen: RGBA16F, and B = the cookbook's Charlie sheen integral (Ashikhmin's
// visibility), A = the same with the sheen specification's Charlie visibility (V_Sheen).
// GltfScaleBias: RG16F, the scale and bias of the glTF BRDF itself, with its height-correlated
// Smith visibility (V_GGX, brdf.glsl), the one its direct light has: the directional albedo of
// the lobe the glTF samples light (07, 08, 10). The texts' table gives a white lobe less: up to
// 0.02 of its albedo seen head-on, 0.11 at NdotV 0.5 and 0.18 at NdotV 0.2 (roughness 0.5; by
// cpu::splitSumQuadrature and cpu::gltfSplitSumQuadrature).
enum class BrdfLutChannels { ScaleBias, ScaleBiasSheen, GltfScaleBias };
Texture2D computeBrdfLut(int size, int samples = 1024,
                         BrdfLutChannels channels = BrdfLutChannels::ScaleBias);

// Binds the split-sum maps for shaders/include/ibl_ambient.glsl to units `firstUnit` (irradiance),
// +1 (prefiltered), +2 (BRDF LUT) and +3 (the environment itself, the mirror end of the
// prefiltered range), points its samplers there, and sets prefilterMaxLod from the prefiltered
// map's own level count.
void useIblMaps(Shader& shader, const TextureCube& environment, const TextureCube& irradiance,
                const TextureCube& prefiltered, const Texture2D& brdfLut, int firstUnit);

// Draws a cube map behind everything else (depth 1, LEQUAL), tone-mapped like the samples.
class Skybox {
public:
    Skybox();
    // `lod`: the mip level read (0 the sharpest; a prefiltered map's levels are its roughnesses).
    void draw(const TextureCube& environment, const glm::mat4& view, const glm::mat4& projection,
              float lod = 0.0f);
    // The glTF samples' output: exposure and one of tonemap.glsl's tone mappers, written linear
    // for an sRGB render target. By default the sky is written as 04-06 write their spheres
    // (Reinhard, then gamma 1/2.2).
    void setToneMapping(int toneMapper, float exposure);

private:
    Shader shader_;
    GpuMesh cube_;
};

}  // namespace pbr
