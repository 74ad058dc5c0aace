#include "ibl.h"

#include <array>
#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "framebuffer.h"

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
                     equirectangular.internalFormat() == GL_RGB32F ? GL_RGB32F : GL_RGB16F);
    Shader shader("ibl/cubemap.vert", "ibl/equirect_to_cube.frag");
    shader.set("equirectangularMap", 0);
    equirectangular.bind(0);
    renderCubeFaces(shader, cube, 0);
    cube.bind(0);
    glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    return cube;
}

TextureCube convolveIrradiance(const TextureCube& environment, int size, float sampleDelta) {
    const SavedGlState saved;
    TextureCube irradiance(size, 1, environment.internalFormat());
    Shader shader("ibl/cubemap.vert", "ibl/irradiance.frag");
    readFrom(shader, environment);
    shader.set("sampleDelta", sampleDelta);
    renderCubeFaces(shader, irradiance, 0);
    return irradiance;
}

TextureCube prefilterSpecular(const TextureCube& environment, int size, int levels, int samples) {
    const SavedGlState saved;
    TextureCube prefiltered(size, levels, environment.internalFormat());
    Shader shader("ibl/cubemap.vert", "ibl/prefilter.frag");
    readFrom(shader, environment);
    shader.set("sampleCount", samples);
    for (int level = 0; level < levels; ++level) {
        shader.set("roughness", levels > 1 ? float(level) / float(levels - 1) : 0.0f);
        shader.set("footprintLod", float(std::log2(double(environment.size()) /
                                                   double(std::max(1, size >> level)))));
        renderCubeFaces(shader, prefiltered, level);
    }
    return prefiltered;
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
    const GpuMesh quad(pbr::quad());
    quad.draw();
    return lut;
}

void useIblMaps(Shader& shader, const TextureCube& irradiance, const TextureCube& prefiltered,
                const Texture2D& brdfLut, int firstUnit) {
    shader.set("irradianceMap", firstUnit);
    shader.set("prefilterMap", firstUnit + 1);
    shader.set("brdfLUT", firstUnit + 2);
    shader.set("prefilterMaxLod", float(prefiltered.levels() - 1));
    irradiance.bind(firstUnit);
    prefiltered.bind(firstUnit + 1);
    brdfLut.bind(firstUnit + 2);
}

Skybox::Skybox() : shader_("ibl/skybox.vert", "ibl/skybox.frag"), cube_(pbr::cube()) {
    shader_.set("environmentMap", 0);
    shader_.set("toneMapper", -1);
    shader_.set("exposure", 1.0f);
}

void Skybox::setToneMapping(int toneMapper, float exposure) {
    shader_.set("toneMapper", toneMapper);
    shader_.set("exposure", exposure);
}

void Skybox::draw(const TextureCube& environment, const glm::mat4& view,
                  const glm::mat4& projection) {
    GLint depthFunc = GL_LESS;
    glGetIntegerv(GL_DEPTH_FUNC, &depthFunc);
    GLint cullFace = GL_BACK;
    glGetIntegerv(GL_CULL_FACE_MODE, &cullFace);
    glDepthFunc(GL_LEQUAL);  // the sky sits at depth 1, where the cleared depth is
    glCullFace(GL_FRONT);    // seen from inside, the cube shows the backs of its faces
    shader_.use();
    shader_.set("view", view);
    shader_.set("projection", projection);
    environment.bind(0);
    cube_.draw();
    glDepthFunc(GLenum(depthFunc));  // the caller's, whatever they were
    glCullFace(GLenum(cullFace));
}

}  // namespace pbr
