// 09 light_types: the Overload engine's standard PBR shader and its five light types (point,
// directional, spot, ambient box, ambient sphere), fed from one buffer: every light a mat4
// (common/light_block.h), all of them in one std140 uniform block the fragment shader loops over
// (shaders/include/light_types.glsl). A floor and a row of spheres in the project's material
// sets, with the engine's material inputs (texture tiling and offset, an albedo tint). See
// README.md beside this file.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "app.h"
#include "error.h"
#include "light_buffer.h"
#include "mesh.h"
#include "paths.h"
#include "scene.h"
#include "texture.h"

namespace {

// One object of the scene: where it is, which material set, the engine's material inputs.
struct Object {
    const char* materialSet;
    glm::mat4 model;
    glm::vec2 tiling{1.0f}, offset{0.0f};
    glm::vec4 tint{1.0f};
    float metallic = 1.0f, roughness = 1.0f;  // factors on the maps
    bool floor = false;
};

std::vector<Object> scene() {
    std::vector<Object> objects;
    // the floor: 16 x 10 m at y = 0, the wall set tiled 8 x 5 and shifted by a quarter tile
    Object floor{"wall", glm::scale(glm::rotate(glm::mat4(1.0f), -std::numbers::pi_v<float> / 2,
                                                {1, 0, 0}),
                                    {8.0f, 5.0f, 1.0f})};
    floor.tiling = {8.0f, 5.0f};
    floor.offset = {0.25f, 0.0f};
    floor.floor = true;
    objects.push_back(floor);
    // five spheres in a row, 2.5 m apart, resting on the floor
    const char* sets[5] = {"rusted_iron", "gold", "grass", "plastic", "wall"};
    for (int i = 0; i < 5; ++i) {
        Object sphere{sets[i], glm::scale(glm::translate(glm::mat4(1.0f),
                                                         light_types::sphereCentre(i)),
                                          glm::vec3(light_types::kSphereRadius))};
        objects.push_back(sphere);
    }
    objects[3].tiling = {2.0f, 1.0f};             // grass: twice around
    objects[4].tint = {0.45f, 0.65f, 1.0f, 1.0f};  // plastic, tinted blue
    objects[5].offset = {0.5f, 0.0f};             // wall: the pattern turned half way round
    return objects;
}

// N moving point lights for the stress test: on a circle over the scene, turning with `time`,
// colours round the hue wheel; the same short range as the scene's point light (terms 1, 0.7,
// 1.8), so each makes its own small pool of light.
std::vector<pbr::PackedLight> movingLights(int count, float time) {
    std::vector<pbr::PackedLight> lights;
    for (int i = 0; i < count; ++i) {
        const float t = float(i) / float(count);
        const float angle = 2.0f * std::numbers::pi_v<float> * t + 0.5f * time;
        const glm::vec3 position(6.5f * std::cos(angle), 0.6f + 0.4f * std::sin(3.0f * angle),
                                 3.5f * std::sin(angle));
        const glm::vec3 hue = glm::clamp(
            glm::abs(glm::mod(6.0f * t + glm::vec3(0.0f, 4.0f, 2.0f), 6.0f) - 3.0f) - 1.0f, 0.0f,
            1.0f);
        lights.push_back(pbr::pointLight(position, hue, 3.0f, {1.0f, 0.7f, 1.8f}));
    }
    return lights;
}

}  // namespace

int main(int argc, char** argv) try {
    std::vector<std::string> onlyChoices = {"all"};
    onlyChoices.insert(onlyChoices.end(), std::begin(pbr::kLightTypeNames),
                       std::end(pbr::kLightTypeNames));
    pbr::App app(
        argc, argv,
        {.name = "09_light_types",
         .title = "09 light types: point, directional, spot, ambient box, ambient sphere",
         .cameraPosition = {0.0f, 5.5f, 12.0f},
         .cameraPitch = -22.0f,
         .flags = {
             pbr::FlagSpec::choice("--only", onlyChoices,
                                   "draw with one kind of light (default all)"),
             pbr::FlagSpec::integer("--point-lights", "N",
                                   "add N moving point lights (their places depend only on "
                                   "--time), for the cost of many lights",
                                   0, pbr::LightBlock::kMaxLights - 5),
             pbr::FlagSpec::numbers("--attenuation", "C,L,Q",
                                    "the point light's constant, linear and quadratic terms, "
                                    "each >= 0, not all 0 (default 1,0.7,1.8)",
                                    3, 0.0, 1e6),
             pbr::FlagSpec::toggle("--untextured",
                                   "a plain material instead of the maps: the tint as albedo, "
                                   "metallic 0, roughness = the roughness factor (the tests' "
                                   "surface)")}});
    const std::string only = app.flagChoice("--only");
    const int extraLights = app.flagInt("--point-lights", 0);
    pbr::Attenuation attenuation = light_types::kPointAttenuation;
    if (const auto n = app.flagNumbers("--attenuation")) {
        if ((*n)[0] + (*n)[1] + (*n)[2] <= 0.0f) {
            throw pbr::UsageError("--attenuation: '" + *app.flag("--attenuation") +
                                      "': all three terms are 0",
                                  "");
        }
        attenuation = {(*n)[0], (*n)[1], (*n)[2]};
    }
    const bool untextured = app.options().has("--untextured");

    pbr::Shader& shader = app.shader("common/pbr_tangent.vert", "09_light_types/light_types.frag");
    pbr::LightBuffer::attach(shader.id());
    shader.set("albedoMap", 0);
    shader.set("normalMap", 1);
    shader.set("metallicMap", 2);
    shader.set("roughnessMap", 3);
    shader.set("aoMap", 4);
    shader.set("useDerivativeTangents", 0);
    shader.set("untextured", untextured ? 1 : 0);

    const std::vector<Object> objects = scene();
    // Each material set loaded once; setOf[i] is object i's.
    std::vector<std::string> setNames;
    std::vector<pbr::PbrTextures> sets;
    std::vector<size_t> setOf;
    for (const Object& object : objects) {
        auto known = std::find(setNames.begin(), setNames.end(), object.materialSet);
        if (known == setNames.end()) {
            setNames.push_back(object.materialSet);
            if (!untextured)
                sets.push_back(pbr::loadPbrTextures(pbr::materialDir() / object.materialSet));
            known = setNames.end() - 1;
        }
        setOf.push_back(size_t(known - setNames.begin()));
    }
    const pbr::GpuMesh sphere(pbr::uvSphere(64, 32));
    const pbr::GpuMesh floorMesh(pbr::quad());

    std::vector<pbr::PackedLight> fixedLights;
    for (const pbr::PackedLight& light : light_types::sceneLights(attenuation)) {
        if (only == "all" || pbr::kLightTypeNames[int(light.type())] == only)
            fixedLights.push_back(light);
    }
    // The scene's own lights go up once; only the moving ones change from frame to frame.
    pbr::LightBuffer lightBuffer;
    lightBuffer.upload(fixedLights);

    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);  // closed meshes, counter-clockwise outside: their backs never show
    while (app.nextFrame()) {
        if (extraLights > 0) {
            std::vector<pbr::PackedLight> lights = fixedLights;
            const std::vector<pbr::PackedLight> moving = movingLights(extraLights, app.time());
            lights.insert(lights.end(), moving.begin(), moving.end());
            lightBuffer.upload(lights);
        }

        glClearColor(0.02f, 0.02f, 0.03f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        shader.use();
        shader.set("projection", app.projection());
        shader.set("view", app.view());
        shader.set("camPos", app.camera().position());
        for (size_t i = 0; i < objects.size(); ++i) {
            const Object& object = objects[i];
            if (!untextured) sets[setOf[i]].bind();
            shader.set("textureTiling", object.tiling);
            shader.set("textureOffset", object.offset);
            shader.set("albedoTint", untextured && object.floor ? glm::vec4(0.8f, 0.8f, 0.8f, 1.0f)
                                                                : object.tint);
            shader.set("metallicFactor", object.metallic);
            shader.set("roughnessFactor", untextured ? (object.floor ? 0.9f : 0.4f)
                                                     : object.roughness);
            shader.setModel(object.model);
            (object.floor ? floorMesh : sphere).draw();
        }
    }
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
