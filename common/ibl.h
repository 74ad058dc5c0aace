#pragma once
// Image-based lighting precomputation on the GPU, GL 3.3 fragment shaders only: an
// equirectangular HDR environment becomes a cube map; from it, the diffuse irradiance and the
// specular environment prefiltered for each roughness; and the BRDF lookup table of the split-sum
// approximation. Plus the skybox that draws the environment behind a scene. ibl_cache.h keeps
// the results on disk.
#include "mesh.h"
#include "shader.h"
#include "texture.h"

namespace pbr {

// Draws `shader` (with shaders/ibl/cubemap.vert) over the unit cube into every face of `target`
// at mip `level`, one capture view per face; the fragment shader gets the direction as WorldPos.
void renderCubeFaces(Shader& shader, const TextureCube& target, int level);

// The environment as a cube map of `size`^2 faces, RGB16F, with a full mip chain (filtered
// reads of it need the smaller levels).
TextureCube equirectangularToCubemap(const Texture2D& equirectangular, int size);

// Diffuse irradiance / pi of `environment` (so a constant environment L gives L), `size`^2
// faces, one sample every `sampleDelta` radians of the hemisphere (midpoints of whole steps),
// each reading the environment at the mip level of its cell's size.
// 0.075 (1,764 samples a texel): against a CPU sum over every texel of the project's environment,
// 1.8 % mean and 12 % worst error (the sun-facing texels), where the text's 0.025 without mip
// levels (15,876 samples) gives 4.0 % and 26 %; see tools/ibl_accuracy.cpp.
inline constexpr float kIrradianceSampleDelta = 0.075f;
TextureCube convolveIrradiance(const TextureCube& environment, int size,
                               float sampleDelta = kIrradianceSampleDelta);

// The specular environment prefiltered with the GGX lobe: `size`^2 faces, `levels` mip levels,
// level m for roughness m / (levels - 1), `samples` GGX importance samples a texel, each reading
// `environment` at the mip level matching its solid angle. Level 0 (a mirror) is the environment
// averaged over each texel's footprint.
TextureCube prefilterSpecular(const TextureCube& environment, int size = 128, int levels = 5,
                              int samples = 1024);

// The BRDF lookup table, `size`^2: x = NdotV, y = roughness, both sampled at texel centres
// ((i + 0.5) / size), row 0 at t = 0 (roughness near 0); `samples` Hammersley points.
// ScaleBias: RG16F, R = scale and G = bias to F0 of the split-sum GGX integral.
// ScaleBiasSheen: RGBA16F, and B = the cookbook's Charlie sheen integral (A = 1).
enum class BrdfLutChannels { ScaleBias, ScaleBiasSheen };
Texture2D computeBrdfLut(int size, int samples = 1024,
                         BrdfLutChannels channels = BrdfLutChannels::ScaleBias);

// Binds the split-sum maps for shaders/include/ibl_ambient.glsl to units `firstUnit` (irradiance),
// +1 (prefiltered) and +2 (BRDF LUT), points its samplers there, and sets prefilterMaxLod from
// the prefiltered map's own level count.
void useIblMaps(Shader& shader, const TextureCube& irradiance, const TextureCube& prefiltered,
                const Texture2D& brdfLut, int firstUnit);

// Draws a cube map behind everything else (depth 1, LEQUAL), tone-mapped like the samples.
class Skybox {
public:
    Skybox();
    void draw(const TextureCube& environment, const glm::mat4& view, const glm::mat4& projection);
    // The glTF samples' output: exposure and one of tonemap.glsl's tone mappers, written linear
    // for an sRGB render target. By default the sky is written as 04-06 write their spheres
    // (Reinhard, then gamma 1/2.2).
    void setToneMapping(int toneMapper, float exposure);

private:
    Shader shader_;
    GpuMesh cube_;
};

}  // namespace pbr
