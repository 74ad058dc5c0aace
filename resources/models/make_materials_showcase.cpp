// The recipe for the project's own glTF 2.0 asset for sample 10 (run by the build):
//   make_materials_showcase OUT_DIR
// writes OUT_DIR/advanced_materials.gltf, advanced_materials.bin and the backdrop's texture
// advanced_materials_stripes.png, all or none. Y up,
// metres, seen from +Z. A 7 x 5 grid of spheres (radius 0.4, 1 m apart, x = -2 .. 2), a row for
// each layer of the advanced material, what its parameters do from left to right:
//
// row (y)   extension                         base                          left to right
// 4.5       KHR_materials_clearcoat           rough red dielectric          clearcoat 0; 0.5 and
//                                             (0.7, 0.06, 0.05), r 0.6      1 at roughness 0;
//                                                                           1 at 0.25 and 0.5
// 3.5       KHR_materials_sheen               dark fabric (0.03, 0.03,      none; white at sheen
//                                             0.05), r 1                    roughness 0.3 and 0.8;
//                                                                           pink and blue at 0.5
// 2.5       KHR_materials_specular            dark dielectric 0.05, r 0.25  specular 0, 0.5, 1;
//                                                                           1 tinted orange, blue
// 1.5       KHR_materials_ior                 black dielectric 0.02, r 0.15 ior 1, 1.2, 1.5, 2, 3
// 0.5       KHR_materials_emissive_strength   black, emissive (1, 0.45,     strength 0.5, 1, 2, 4,
//                                             0.1)                          8
// -0.5      KHR_materials_transmission        white glass, transmission 1   roughness 0, 0.2, 0.4
//           (thin-walled)                                                   at ior 1.5; 0.4 at ior
//                                                                           1.2 and 1
// -1.5      KHR_materials_volume              white glass, transmission 1,  thin-walled; thickness
//                                             roughness 0, ior 1.5          0.8 clear; 0.4 and 0.8
//                                                                           amber (1, 0.55, 0.15)
//                                                                           at distance 0.3; 0.8
//                                                                           green at 0.5
//
// Behind the two glass rows, 1.2 m back, a backdrop of vertical stripes (0.125 m, pale grey and
// dark blue; a flattened cube with a texture, whose edges the GL filters the same way everywhere)
// shows what the glass bends and blurs. The spheres' materials are factors only: each sphere is
// one material. One directional light (KHR_lights_punctual, 2 lux) from the upper
// left. Deterministic: the same bytes every run.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "base/error.h"
#include "base/output.h"
#include "files/image.h"
#include "gltf_writer.h"

namespace {

namespace fs = std::filesystem;
namespace gltf = pbr::gltf;
using gltf::number;
using gltf::quoted;
using gltf::vec;

struct Document {
    gltf::Buffer buffer;
    std::vector<std::string> nodes, meshes, materials;
    std::string sphere;  // the one sphere primitive (addPrimitive's JSON, open)
    std::string box;     // the cube from -1 to 1 (the backdrop's stripes)

    // A sphere at `at` with a material of the core members `core` and the extensions `extensions`
    // (the inside of the material's "extensions" object, empty for none).
    void sphereAt(const std::string& name, glm::vec3 at, const std::string& core,
                  const std::string& extensions) {
        shapeAt(sphere, name, at, glm::vec3(1.0f), core, extensions);
    }
    // `primitive` (sphere or box) of its own material at `at`, scaled by `scale`.
    void shapeAt(const std::string& primitive, const std::string& name, glm::vec3 at,
                 glm::vec3 scale, const std::string& core, const std::string& extensions) {
        std::string material = "{\"name\":" + quoted(name) + "," + core;
        if (!extensions.empty()) material += ",\"extensions\":{" + extensions + "}";
        materials.push_back(material + "}");
        meshes.push_back("{\"name\":" + quoted(name) + ",\"primitives\":[" + primitive +
                         ",\"material\":" + std::to_string(materials.size() - 1) + "}]}");
        std::string node = "{\"name\":" + quoted(name) + ",\"mesh\":" +
                           std::to_string(meshes.size() - 1) + ",\"translation\":" + vec(at);
        if (scale != glm::vec3(1.0f)) node += ",\"scale\":" + vec(scale);
        nodes.push_back(node + "}");
    }
};

// The core material: base colour, metallic 0, roughness.
std::string dielectric(glm::vec3 color, float roughness) {
    return "\"pbrMetallicRoughness\":{\"baseColorFactor\":" + vec(glm::vec4(color, 1.0f)) +
           ",\"metallicFactor\":0,\"roughnessFactor\":" + number(roughness) + "}";
}
std::string extension(const std::string& name, const std::string& members) {
    return quoted(name) + ":{" + members + "}";
}

float column(int i) {
    return float(i) - 2.0f;
}

void addRows(Document& doc) {
    // clear coat over a rough red base
    struct Coat {
        float factor, roughness;
    };
    const Coat coats[] = {{0.0f, 0.0f}, {0.5f, 0.0f}, {1.0f, 0.0f}, {1.0f, 0.25f}, {1.0f, 0.5f}};
    for (int i = 0; i < 5; ++i) {
        doc.sphereAt("clearcoat_" + std::to_string(i), {column(i), 4.5f, 0.0f},
                     dielectric({0.7f, 0.06f, 0.05f}, 0.6f),
                     coats[i].factor > 0.0f
                         ? extension("KHR_materials_clearcoat",
                                     "\"clearcoatFactor\":" + number(coats[i].factor) +
                                         ",\"clearcoatRoughnessFactor\":" +
                                         number(coats[i].roughness))
                         : "");
    }
    // sheen on a dark fabric
    struct Sheen {
        glm::vec3 color;
        float roughness;
    };
    const Sheen sheens[] = {{glm::vec3(0.0f), 0.0f},
                            {glm::vec3(1.0f), 0.3f},
                            {glm::vec3(1.0f), 0.8f},
                            {{1.0f, 0.4f, 0.6f}, 0.5f},
                            {{0.3f, 0.6f, 1.0f}, 0.5f}};
    for (int i = 0; i < 5; ++i) {
        doc.sphereAt("sheen_" + std::to_string(i), {column(i), 3.5f, 0.0f},
                     dielectric({0.03f, 0.03f, 0.05f}, 1.0f),
                     i > 0 ? extension("KHR_materials_sheen",
                                       "\"sheenColorFactor\":" + vec(sheens[i].color) +
                                           ",\"sheenRoughnessFactor\":" +
                                           number(sheens[i].roughness))
                           : "");
    }
    // the specular layer's strength and colour on a grey dielectric
    struct Specular {
        float factor;
        glm::vec3 color;
    };
    const Specular speculars[] = {{0.0f, glm::vec3(1.0f)},
                                  {0.5f, glm::vec3(1.0f)},
                                  {1.0f, glm::vec3(1.0f)},
                                  {1.0f, {1.0f, 0.5f, 0.2f}},
                                  {1.0f, {0.2f, 0.5f, 1.0f}}};
    for (int i = 0; i < 5; ++i) {
        doc.sphereAt("specular_" + std::to_string(i), {column(i), 2.5f, 0.0f},
                     dielectric(glm::vec3(0.05f), 0.25f),
                     extension("KHR_materials_specular",
                               "\"specularFactor\":" + number(speculars[i].factor) +
                                   ",\"specularColorFactor\":" + vec(speculars[i].color)));
    }
    // the index of refraction on a glossy black dielectric
    const float iors[] = {1.0f, 1.2f, 1.5f, 2.0f, 3.0f};
    for (int i = 0; i < 5; ++i) {
        doc.sphereAt("ior_" + std::to_string(i), {column(i), 1.5f, 0.0f},
                     dielectric(glm::vec3(0.02f), 0.15f),
                     extension("KHR_materials_ior", "\"ior\":" + number(iors[i])));
    }
    // emission past the core material's factor of 1
    const float strengths[] = {0.5f, 1.0f, 2.0f, 4.0f, 8.0f};
    for (int i = 0; i < 5; ++i) {
        doc.sphereAt("emissive_" + std::to_string(i), {column(i), 0.5f, 0.0f},
                     dielectric(glm::vec3(0.0f), 0.5f) +
                         ",\"emissiveFactor\":" + vec(glm::vec3(1.0f, 0.45f, 0.1f)),
                     extension("KHR_materials_emissive_strength",
                               "\"emissiveStrength\":" + number(strengths[i])));
    }
    // light through white glass, thin-walled: its roughness blurs what is behind, less as ior
    // nears 1
    struct Glass {
        float roughness, ior;
    };
    const Glass glasses[] = {{0.0f, 1.5f}, {0.2f, 1.5f}, {0.4f, 1.5f}, {0.4f, 1.2f}, {0.4f, 1.0f}};
    for (int i = 0; i < 5; ++i) {
        doc.sphereAt("transmission_" + std::to_string(i), {column(i), -0.5f, 0.0f},
                     dielectric(glm::vec3(1.0f), glasses[i].roughness),
                     extension("KHR_materials_transmission", "\"transmissionFactor\":1") + "," +
                         extension("KHR_materials_ior", "\"ior\":" + number(glasses[i].ior)));
    }
    // a volume: the ray refracted through the thickness, its light attenuated by the colour
    struct Volume {
        float thickness;
        glm::vec3 color;
        float distance;  // 0: no attenuation
    };
    const Volume volumes[] = {{0.0f, glm::vec3(1.0f), 0.0f},
                              {0.8f, glm::vec3(1.0f), 0.0f},
                              {0.4f, {1.0f, 0.55f, 0.15f}, 0.3f},
                              {0.8f, {1.0f, 0.55f, 0.15f}, 0.3f},
                              {0.8f, {0.2f, 0.8f, 0.4f}, 0.5f}};
    for (int i = 0; i < 5; ++i) {
        std::string volume = "\"thicknessFactor\":" + number(volumes[i].thickness);
        if (volumes[i].distance > 0.0f) {
            volume += ",\"attenuationDistance\":" + number(volumes[i].distance) +
                      ",\"attenuationColor\":" + vec(volumes[i].color);
        }
        doc.sphereAt("volume_" + std::to_string(i), {column(i), -1.5f, 0.0f},
                     dielectric(glm::vec3(1.0f), 0.0f),
                     extension("KHR_materials_transmission", "\"transmissionFactor\":1") +
                         (volumes[i].thickness > 0.0f
                              ? "," + extension("KHR_materials_volume", volume)
                              : ""));
    }
    // the backdrop behind the glass: one flattened box, x = -2.75 to 2.75, y = -2.1 to 0, its
    // faces showing the stripes' texture (44 of 0.125 m across the front)
    doc.shapeAt(doc.box, "backdrop", {0.0f, -1.05f, -1.2f}, {2.75f, 1.05f, 0.05f},
                "\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0},"
                "\"metallicFactor\":0,\"roughnessFactor\":0.8}",
                "");
}

// The backdrop's texture: 44 vertical stripes of 8 texels, pale grey (0.8 linear) and dark blue
// (0.04, 0.06, 0.25), as sRGB bytes; 8 texels tall.
pbr::Image stripes() {
    pbr::Image image{44 * 8, 8, 3, {}};
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const bool pale = (x / 8) % 2 == 0;
            const std::uint8_t pixel[3] = {pale ? std::uint8_t(231) : std::uint8_t(56),
                                           pale ? std::uint8_t(231) : std::uint8_t(68),
                                           pale ? std::uint8_t(231) : std::uint8_t(137)};
            image.pixels.insert(image.pixels.end(), pixel, pixel + 3);
        }
    }
    return image;
}

std::string finish(Document& doc, const std::string& bin) {
    // the light's -Z turned to (0.5, -0.6, -0.62): from the upper left, in front
    const glm::vec3 to = glm::normalize(glm::vec3(0.5f, -0.6f, -0.62f)), from(0, 0, -1);
    const glm::vec4 q = glm::normalize(glm::vec4(glm::cross(from, to), 1.0f + glm::dot(from, to)));
    doc.nodes.push_back("{\"name\":\"sun\",\"rotation\":" + vec(q) +
                        ",\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}}");
    std::vector<std::string> roots;
    for (size_t i = 0; i < doc.nodes.size(); ++i) roots.push_back(std::to_string(i));
    const char* line = ",\n";
    std::vector<std::pair<std::string, std::string>> members = {
        {"asset",
         "{\"version\":\"2.0\",\"generator\":\"pbr-samples resources/models/"
         "make_materials_showcase\"}"},
        {"extensionsUsed",
         "[\"KHR_lights_punctual\",\"KHR_materials_clearcoat\",\"KHR_materials_sheen\","
         "\"KHR_materials_specular\",\"KHR_materials_ior\",\"KHR_materials_emissive_strength\","
         "\"KHR_materials_transmission\",\"KHR_materials_volume\"]"},
        {"extensions",
         "{\"KHR_lights_punctual\":{\"lights\":[{\"name\":\"sun\",\"type\":\"directional\","
         "\"color\":[1,0.97,0.92],\"intensity\":2}]}}"},
        {"scene", "0"},
        {"scenes", "[{\"name\":\"advanced_materials\",\"nodes\":" + gltf::array(roots) + "}]"},
        {"nodes", gltf::array(doc.nodes, line)},
        {"meshes", gltf::array(doc.meshes, line)},
        {"materials", gltf::array(doc.materials, line)},
        {"textures", "[{\"source\":0}]"},
        {"images", "[{\"uri\":\"advanced_materials_stripes.png\"}]"}};
    for (auto& member : doc.buffer.members(bin)) members.push_back(member);
    return gltf::document(members);
}

}  // namespace

int main(int argc, char** argv) try {
    if (argc != 2) {
        throw pbr::UsageError("no output folder", "usage: make_materials_showcase OUT_DIR\n");
    }
    const fs::path dir = argv[1];
    fs::create_directories(dir);
    Document doc;
    doc.sphere = doc.buffer.addPrimitive(gltf::gridSphere(0.4f));
    doc.box = doc.buffer.addPrimitive(pbr::cube());
    addRows(doc);
    const std::string text = finish(doc, "advanced_materials.bin");
    pbr::OutputBatch files;
    files.add(dir / "advanced_materials.bin", doc.buffer.bytes());
    files.add(dir / "advanced_materials_stripes.png", pbr::encodePng(stripes(), pbr::PngEncoding::Small));
    files.add(dir / "advanced_materials.gltf", text);
    files.commit();
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
