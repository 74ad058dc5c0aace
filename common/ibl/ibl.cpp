#include "ibl/ibl.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/framebuffer.h"
#include "math/cube_geometry.h"

namespace pbr {

namespace {

// The six views from the centre of a cube map, in GL's face order (+X, -X, +Y, -Y, +Z, -Z),
// with the up vectors the cube-map convention needs.
std::array<glm::mat4, 6> captureViews() {
    const glm::vec3 o(0.0f);
    return {glm::lookAt(o, {1, 0, 0}, {0, -1, 0}), glm::lookAt(o, {-1, 0, 0}, {0, -1, 0}),
            glm::lookAt(o, {0, 1, 0}, {0, 0, 1}),  glm::lookAt(o, {0, -1, 0}, {0, 0, -1}),
            glm::lookAt(o, {0, 0, 1}, {0, -1, 0}), glm::lookAt(o, {0, 0, -1}, {0, -1, 0})};
}

// Gives a convolution shader its source: environmentMap on unit 0, and the solid angle of one
// texel of its level 0 (4 pi / (6 size^2)), from which the shader picks the mip level to read.
void readFrom(Shader& shader, const TextureCube& environment) {
    shader.set("environmentMap", 0);
    shader.set("sourceTexelSolidAngle",
               float(4.0 * std::numbers::pi /
                     (6.0 * double(environment.size()) * double(environment.size()))));
    environment.bind(0);
}

}  // namespace

void renderCubeFaces(Shader& shader, const TextureCube& target, int level) {
    const SavedGlState saved;
    const GpuMesh cube(pbr::cube());
    const GlFramebuffer framebuffer;
    const int size = std::max(1, target.size() >> level);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glViewport(0, 0, size, size);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    shader.set("projection", glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 10.0f));
    const auto views = captureViews();
    for (int face = 0; face < 6; ++face) {
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                               GL_TEXTURE_CUBE_MAP_POSITIVE_X + GLenum(face), target.id(), level);
        requireCompleteFramebuffer("cube map face");
        shader.set("view", views[size_t(face)]);
        cube.draw();
    }
}

TextureCube equirectangularToCubemap(const Texture2D& equirectangular, int size) {
    const SavedGlState saved;
    const int levels = int(std::floor(std::log2(double(size)))) + 1;
    // The cube keeps the source's range: 32-bit floats for a sun past half-float range.
    TextureCube cube(size, levels,
                     equirectangular.internalFormat() == GL_RGB32F ? kFloatRgb : kHalfFloatRgb);
    Shader shader("ibl/cubemap.vert", "ibl/equirect_to_cube.frag");
    shader.set("equirectangularMap", 0);
    equirectangular.bind(0);
    renderCubeFaces(shader, cube, 0);
    cube.bind(0);
    glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    return cube;
}

SplitEnvironment splitBrightTexels(const TextureCube& environment, int restSize) {
    const SavedGlState saved;
    restSize = std::min(restSize, environment.size());
    int level = 0;
    while ((environment.size() >> level) > restSize) ++level;
    const int n = std::max(1, environment.size() >> level);

    std::array<std::vector<float>, 6> faces;
    std::vector<float> luminances;
    luminances.reserve(size_t(6 * n * n));
    for (int face = 0; face < 6; ++face) {
        faces[size_t(face)] = environment.readFace(face, level);
        const std::vector<float>& rgb = faces[size_t(face)];
        for (size_t k = 0; k < rgb.size(); k += 3) {
            luminances.push_back(0.2126f * rgb[k] + 0.7152f * rgb[k + 1] + 0.0722f * rgb[k + 2]);
        }
    }
    // The threshold: the luminance of the brightest texel not kept apart.
    float threshold = 0.0f;
    if (luminances.size() > size_t(kMaxBrightTexels)) {
        std::vector<float> sorted = luminances;
        std::nth_element(sorted.begin(), sorted.begin() + kMaxBrightTexels, sorted.end(),
                         std::greater<>());
        threshold = std::max(0.0f, sorted[size_t(kMaxBrightTexels)]);
    }

    SplitEnvironment split{.rest = TextureCube(n, int(std::floor(std::log2(double(n)))) + 1,
                                               environment.internalFormat()),
                           .bright = {}};
    for (int face = 0; face < 6; ++face) {
        std::vector<float>& rgb = faces[size_t(face)];
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i) {
                const size_t k = size_t(j) * size_t(n) + size_t(i);
                const float lum = luminances[size_t(face) * size_t(n) * size_t(n) + k];
                if (lum <= threshold || split.bright.size() == size_t(kMaxBrightTexels)) continue;
                // Texels tied at the threshold stay in the rest; what is above it goes apart,
                // in the texel's own colour, so the rest keeps the threshold's luminance there.
                const float apart = 1.0f - threshold / lum;
                glm::vec3 radiance;
                for (int c = 0; c < 3; ++c) {
                    radiance[c] = rgb[3 * k + size_t(c)] * apart;
                    rgb[3 * k + size_t(c)] -= radiance[c];
                }
                const glm::dvec3 direction =
                    cubeFaceDirection(face, cubeTexelCentre(i, n), cubeTexelCentre(j, n));
                split.bright.push_back({.direction = glm::vec3(direction),
                                        .solidAngle = float(cubeTexelSolidAngle(i, j, n)),
                                        .radiance = radiance});
            }
        }
        split.rest.writeFace(face, 0, rgb);
    }
    split.rest.bind(0);
    glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    return split;
}

double prefilterNormalization(double roughness) {
    // N = V: L at angle 2 theta_h from N, dOmega_L = 4 cos(theta_h) dOmega_H, and N.L > 0 for
    // theta_h < pi / 4. Midpoints in theta_h, fine enough for the narrowest lobe used (r 0.25).
    const double a = roughness * roughness, a2 = a * a, pi = std::numbers::pi;
    constexpr int kSteps = 1 << 16;
    const double step = (pi / 4.0) / kSteps;
    double sum = 0.0;
    for (int k = 0; k < kSteps; ++k) {
        const double theta = (k + 0.5) * step, c = std::cos(theta);
        const double denom = c * c * (a2 - 1.0) + 1.0;
        const double D = a2 / (pi * denom * denom);
        sum += D * std::cos(2.0 * theta) * 4.0 * c * 2.0 * pi * std::sin(theta) * step;
    }
    return sum;
}

namespace {

// The sheen map's weight at L's angle theta from N (N = V): D_Charlie(H) N.L, H halfway between,
// times the ring's circumference, 2 pi sin(theta).
double sheenRingWeight(double theta, double alpha) {
    const double cosH = std::cos(theta / 2.0), sin2h = std::max(1.0 - cosH * cosH, 0.0);
    const double D = (2.0 + 1.0 / alpha) * std::pow(sin2h, 0.5 / alpha) / (2.0 * std::numbers::pi);
    return D * std::cos(theta) * 2.0 * std::numbers::pi * std::sin(theta);
}

// Angles from N spaced geometrically towards the horizon: u = pi/2 - theta runs from
// `lowest` to pi/2 in `count` equal steps of log u (midpoints); returns (theta, d theta) pairs.
std::vector<std::pair<double, double>> horizonRings(int count, double lowest) {
    const double halfPi = std::numbers::pi / 2.0, step = std::log(halfPi / lowest) / count;
    std::vector<std::pair<double, double>> rings;
    for (int i = 0; i < count; ++i) {
        const double u = lowest * std::exp((i + 0.5) * step);
        rings.emplace_back(halfPi - u, u * step);  // du = u d(log u)
    }
    return rings;
}

}  // namespace

double sheenPrefilterNormalization(double sheenRoughness) {
    const double alpha = std::max(sheenRoughness * sheenRoughness, 1e-6);
    double sum = 0.0;
    for (const auto& [theta, width] : horizonRings(1 << 16, 1e-4 * alpha))
        sum += sheenRingWeight(theta, alpha) * width;
    return sum;
}

namespace {

// Hands a convolution shader the bright texels (shaders/include/bright_texels.glsl).
void useBrightTexels(Shader& shader, const SplitEnvironment& split) {
    shader.set("brightCount", int(split.bright.size()));
    for (size_t i = 0; i < split.bright.size(); ++i) {
        const BrightTexel& texel = split.bright[i];
        const std::string index = std::to_string(i) + "]";
        shader.set("brightDirection[" + index, glm::vec4(texel.direction, texel.solidAngle));
        shader.set("brightRadiance[" + index, texel.radiance);
    }
}

}  // namespace

TextureCube convolveIrradiance(const TextureCube& environment, int size, float sampleDelta) {
    const SplitEnvironment split = splitBrightTexels(environment);
    const SavedGlState saved;
    TextureCube irradiance(size, 1, environment.internalFormat());
    Shader shader("ibl/cubemap.vert", "ibl/irradiance.frag");
    readFrom(shader, split.rest);
    useBrightTexels(shader, split);
    shader.set("sampleDelta", sampleDelta);
    renderCubeFaces(shader, irradiance, 0);
    return irradiance;
}

TextureCube prefilterSpecular(const TextureCube& environment, int size, int levels, int samples) {
    const SplitEnvironment split = splitBrightTexels(environment);
    const SavedGlState saved;
    TextureCube prefiltered(size, levels, environment.internalFormat());
    Shader shader("ibl/cubemap.vert", "ibl/prefilter.frag");
    useBrightTexels(shader, split);
    shader.set("sampleCount", samples);
    for (int level = 0; level < levels; ++level) {
        const float roughness = levels > 1 ? float(level) / float(levels - 1) : 0.0f;
        shader.set("roughness", roughness);
        if (level == 0) {
            // the mirror reads the whole environment, sun and all, over this texel's footprint
            readFrom(shader, environment);
            shader.set("footprintLod", float(std::log2(double(environment.size()) /
                                                       double(std::max(1, size >> level)))));
        } else {
            readFrom(shader, split.rest);
            shader.set("lobeNormalization", float(prefilterNormalization(roughness)));
        }
        renderCubeFaces(shader, prefiltered, level);
    }
    return prefiltered;
}

TextureCube prefilterSheen(const TextureCube& environment, int size, int levels, int taps) {
    const SplitEnvironment split = splitBrightTexels(environment);
    const SavedGlState saved;
    TextureCube sheen(size, levels, environment.internalFormat());
    Shader shader("ibl/cubemap.vert", "ibl/prefilter_sheen.frag");
    readFrom(shader, split.rest);
    useBrightTexels(shader, split);
    shader.set("ringTaps", taps);
    shader.set("ringCount", kSheenPrefilterRings);
    const double texelSolidAngle =
        4.0 * std::numbers::pi / (6.0 * double(split.rest.size()) * split.rest.size());
    for (int level = 0; level < levels; ++level) {
        const double roughness = std::max(
            levels > 1 ? double(level) / double(levels - 1) : 0.0, double(kMinSheenMapRoughness));
        const double alpha = roughness * roughness;
        // rings from a twentieth of the lobe's distance from the horizon (2 alpha) upwards
        const auto rings = horizonRings(kSheenPrefilterRings, 0.1 * alpha);
        double total = 0.0;
        for (const auto& [theta, width] : rings) total += sheenRingWeight(theta, alpha) * width;
        for (size_t i = 0; i < rings.size(); ++i) {
            const auto& [theta, width] = rings[i];
            const std::string index = std::to_string(i) + "]";
            shader.set("ringCos[" + index, float(std::cos(theta)));
            shader.set("ringWeight[" + index, float(sheenRingWeight(theta, alpha) * width / total));
            const double footprint = 2.0 * std::numbers::pi * std::sin(theta) / taps * width;
            shader.set("ringLod[" + index,
                       float(std::max(0.5 * std::log2(footprint / texelSolidAngle), 0.0)));
        }
        shader.set("alpha", float(alpha));
        shader.set("lobeNormalization", float(sheenPrefilterNormalization(roughness)));
        renderCubeFaces(shader, sheen, level);
    }
    return sheen;
}

Texture2D computeBrdfLut(int size, int samples, BrdfLutChannels channels) {
    const SavedGlState saved;
    const bool sheen = channels == BrdfLutChannels::ScaleBiasSheen;
    Texture2D lut(size, size, sheen ? GL_RGBA16F : GL_RG16F);
    const GlFramebuffer framebuffer;
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, lut.id(), 0);
    requireCompleteFramebuffer("BRDF LUT");
    glViewport(0, 0, size, size);
    glDisable(GL_DEPTH_TEST);
    Shader shader("ibl/fullscreen.vert", "ibl/brdf_lut.frag");
    shader.set("sampleCount", samples);
    shader.set("sheen", sheen ? 1 : 0);
    shader.set("heightCorrelated", channels == BrdfLutChannels::GltfScaleBias ? 1 : 0);
    const GpuMesh quad(pbr::quad());
    quad.draw();
    return lut;
}

void useIblMaps(Shader& shader, const TextureCube& environment, const TextureCube& irradiance,
                const TextureCube& prefiltered, const Texture2D& brdfLut, int firstUnit) {
    shader.set("irradianceMap", firstUnit);
    shader.set("prefilterMap", firstUnit + 1);
    shader.set("brdfLUT", firstUnit + 2);
    shader.set("environmentMap", firstUnit + 3);
    shader.set("prefilterMaxLod", float(prefiltered.levels() - 1));
    irradiance.bind(firstUnit);
    prefiltered.bind(firstUnit + 1);
    brdfLut.bind(firstUnit + 2);
    environment.bind(firstUnit + 3);
}

Skybox::Skybox() : shader_("ibl/skybox.vert", "ibl/skybox.frag"), cube_(pbr::cube()) {
    shader_.set("environmentMap", 0);
    shader_.set("toneMapper", -1);
    shader_.set("exposure", 1.0f);
    shader_.set("lod", 0.0f);
}

void Skybox::setToneMapping(int toneMapper, float exposure) {
    shader_.set("toneMapper", toneMapper);
    shader_.set("exposure", exposure);
}

void Skybox::draw(const TextureCube& environment, const glm::mat4& view,
                  const glm::mat4& projection, float lod) {
    GLint depthFunc = GL_LESS;
    glGetIntegerv(GL_DEPTH_FUNC, &depthFunc);
    GLint cullFace = GL_BACK;
    glGetIntegerv(GL_CULL_FACE_MODE, &cullFace);
    glDepthFunc(GL_LEQUAL);  // the sky sits at depth 1, where the cleared depth is
    glCullFace(GL_FRONT);    // seen from inside, the cube shows the backs of its faces
    shader_.use();
    shader_.set("view", view);
    shader_.set("projection", projection);
    shader_.set("lod", lod);
    environment.bind(0);
    cube_.draw();
    glDepthFunc(GLenum(depthFunc));  // the caller's, whatever they were
    glCullFace(GLenum(cullFace));
}

}  // namespace pbr
