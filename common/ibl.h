#pragma once
// Image-based lighting precomputation on the GPU, GL 3.3 fragment shaders only: an
// equirectangular HDR environment becomes a cube map, and the cube map's diffuse irradiance is
// convolved into a small one. Plus the skybox that draws the environment behind a scene.
#include "mesh.h"
#include "shader.h"
#include "texture.h"

namespace pbr {

// The environment as a cube map of `size`^2 faces, RGB16F, with a full mip chain (filtered
// reads of it need the smaller levels).
TextureCube equirectangularToCubemap(const Texture2D& equirectangular, int size);

// Diffuse irradiance / pi of `environment` (so a constant environment L gives L), `size`^2
// faces, one sample every `sampleDelta` radians of the hemisphere.
TextureCube convolveIrradiance(const TextureCube& environment, int size, float sampleDelta = 0.05f);

// The split-sum BRDF lookup table, `size`^2, RG16F: x = NdotV, y = roughness, both sampled at
// texel centres ((i + 0.5) / size); R = scale, G = bias to F0; `samples` Hammersley points.
Texture2D computeBrdfLut(int size, int samples = 1024);

// Draws a cube map behind everything else (depth 1, LEQUAL), tone-mapped like the samples.
class Skybox {
public:
    Skybox();
    void draw(const TextureCube& environment, const glm::mat4& view, const glm::mat4& projection);

private:
    Shader shader_;
    GpuMesh cube_;
};

}  // namespace pbr
