// The recipe for the project's own glTF 2.0 asset for sample 08 (run by the build):
//   make_pbr_workflows OUT_DIR
// writes into OUT_DIR, all of them or none:
//   pbr_workflows.gltf           the same spheres twice, side by side: metallic-roughness on the
//                                left (x < 0), KHR_materials_pbrSpecularGlossiness on the right
//   pbr_workflows_required.gltf  the same, with the extension in extensionsRequired
//   pbr_workflows_mr.gltf        the left half alone, centred on x = 0 (for the tests)
//   pbr_workflows_sg.gltf        the right half alone, at the same place (for the tests)
// with one .bin each and the shared textures pbr_workflows_*.png. Y up, metres, seen from +Z.
//
// Each half is a 4 x 3 grid of spheres (radius 0.4, 1 m apart):
//   y = 2.5  metal: gold, roughness 0, 0.3, 0.6, 1.
//            MR: baseColorFactor gold, metallic 1. SG: diffuse black, specular gold,
//            glossiness 1 - roughness. Both: c_diff = 0, F0 = gold, exactly.
//   y = 1.5  dielectric: roughness 0, 0.3, 0.6, 1.
//            MR: baseColorFactor c, metallic 0 (c_diff = c, F0 = 0.04).
//            SG: specular 0.04, diffuse c / 0.96 (c_diff = c / 0.96 x (1 - 0.04) = c).
//   y = 0.5  x = -1.5: a textured metal (colour bands; roughness in bands across u).
//              MR: baseColorTexture + metallicRoughnessTexture (B = 255, G = roughness).
//              SG: diffuse black; specularGlossinessTexture RGB = the same colour bytes,
//              A = 255 - G.
//            x = -0.5: a textured dielectric (a checker; the same roughness bands).
//              MR: baseColorTexture x 0.96, metallicRoughnessTexture (B = 0).
//              SG: diffuseTexture (the same bytes) x 1, specularFactor 0.04,
//              specularGlossinessTexture RGB = 255, A = 255 - G.
//            x = 0.5, 1.5 (pbr_workflows.gltf only): what only specular-glossiness can say, a
//              non-metal with a coloured specular (diffuse blue, specular orange) and one with a
//              strong white specular (0.5); on the left the nearest metallic-roughness material,
//              the same diffuse colour as a dielectric (F0 0.04, white).
// One directional light (KHR_lights_punctual, 2 lux) from the upper left: it lights every
// sphere the same way wherever it stands, so the two halves differ only by where they are.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "base/error.h"
#include "base/output.h"
#include "files/image.h"
#include "gl/mesh.h"
#include "gltf_writer.h"

namespace {

namespace fs = std::filesystem;
namespace gltf = pbr::gltf;
using gltf::quoted;
using gltf::vec;
using pbr::Image;

constexpr float kRoughness[4] = {0.0f, 0.3f, 0.6f, 1.0f};
const glm::vec3 kGold(1.0f, 0.766f, 0.336f);
const glm::vec3 kRed(0.75f, 0.12f, 0.1f);
const glm::vec3 kBlue(0.1f, 0.25f, 0.6f);
const glm::vec3 kOrange(0.9f, 0.45f, 0.1f);
constexpr float kDielectricF0 = 0.04f;

Image makeImage(int size, int channels, const std::function<glm::ivec4(int x, int y)>& texel) {
    Image image{size, size, channels, {}};
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const glm::ivec4 t = texel(x, y);
            for (int c = 0; c < channels; ++c) image.pixels.push_back(std::uint8_t(t[c]));
        }
    }
    return image;
}

// Textures, 64^2, in bands 16 texels wide (pure down to the 4^2 mip level).
constexpr int kSize = 64;
// Across u: about 0, 0.3, 0.6, 0.9. Chosen so that every mip level's box average is a whole
// byte both of G and of 255 - G (pairs and all four sum to multiples of 2 and 4): the two
// workflows then read the same roughness at every level, not one rounded up and one down.
int roughnessByte(int x) {
    static const int bytes[4] = {0, 76, 154, 230};
    return bytes[x / 16];
}
glm::ivec3 metalColor(int y) {  // down v: gold, copper, silver, a darker gold (sRGB bytes)
    static const glm::ivec3 colors[4] = {
        {255, 226, 155}, {250, 208, 192}, {252, 250, 245}, {229, 200, 120}};
    return colors[y / 16];
}
glm::ivec3 checkerColor(int x, int y) {  // 8-texel checks of a warm and a cool colour
    return ((x / 8) + (y / 8)) % 2 ? glm::ivec3(200, 90, 60) : glm::ivec3(70, 140, 190);
}

struct Document {
    gltf::Buffer buffer;
    std::vector<std::string> nodes, meshes, materials, textures, images;
    std::string sphere;  // the one sphere primitive (addPrimitive's JSON, open)

    int texture(const std::string& file) {
        images.push_back("{\"uri\":" + quoted(file) + "}");
        textures.push_back("{\"sampler\":0,\"source\":" + std::to_string(images.size() - 1) + "}");
        return int(textures.size()) - 1;
    }
    void sphereAt(const std::string& name, const std::string& material, glm::vec3 at) {
        materials.push_back("{\"name\":" + quoted(name) + "," + material + "}");
        meshes.push_back("{\"name\":" + quoted(name) + ",\"primitives\":[" + sphere +
                         ",\"material\":" + std::to_string(materials.size() - 1) + "}]}");
        nodes.push_back("{\"name\":" + quoted(name) + ",\"mesh\":" +
                        std::to_string(meshes.size() - 1) + ",\"translation\":" + vec(at) + "}");
    }
};

std::string textureInfo(int index) {
    return "{\"index\":" + std::to_string(index) + "}";
}
std::string specGloss(const std::string& members) {
    return "\"extensions\":{\"KHR_materials_pbrSpecularGlossiness\":{" + members + "}}";
}
std::string metallicRoughness(const std::string& members) {
    return "\"pbrMetallicRoughness\":{" + members + "}";
}

// One half: `sg` chooses the workflow; `extra` adds the x = 0.5, 1.5 spheres of the textured
// row; every sphere is moved by `offset`.
void addHalf(Document& doc, bool sg, bool extra, glm::vec3 offset) {
    const std::string side = sg ? "sg_" : "mr_";
    auto at = [&](int column, float y) {
        return offset + glm::vec3(-1.5f + float(column), y, 0.0f);
    };
    for (int i = 0; i < 4; ++i) {
        const float r = kRoughness[i];
        doc.sphereAt(side + "metal_" + std::to_string(i),
                     sg ? specGloss("\"diffuseFactor\":[0,0,0,1],\"specularFactor\":" +
                                    vec(kGold) + ",\"glossinessFactor\":" + gltf::number(1.0f - r))
                        : metallicRoughness("\"baseColorFactor\":" + vec(glm::vec4(kGold, 1.0f)) +
                                            ",\"metallicFactor\":1,\"roughnessFactor\":" +
                                            gltf::number(r)),
                     at(i, 2.5f));
    }
    for (int i = 0; i < 4; ++i) {
        const float r = kRoughness[i];
        doc.sphereAt(side + "dielectric_" + std::to_string(i),
                     sg ? specGloss("\"diffuseFactor\":" +
                                    vec(glm::vec4(kRed / (1.0f - kDielectricF0), 1.0f)) +
                                    ",\"specularFactor\":" + vec(glm::vec3(kDielectricF0)) +
                                    ",\"glossinessFactor\":" + gltf::number(1.0f - r))
                        : metallicRoughness("\"baseColorFactor\":" + vec(glm::vec4(kRed, 1.0f)) +
                                            ",\"metallicFactor\":0,\"roughnessFactor\":" +
                                            gltf::number(r)),
                     at(i, 1.5f));
    }
    if (sg) {
        doc.sphereAt("sg_textured_metal",
                     specGloss("\"diffuseFactor\":[0,0,0,1],\"specularGlossinessTexture\":" +
                               textureInfo(doc.texture("pbr_workflows_metal_sg.png"))),
                     at(0, 0.5f));
        doc.sphereAt("sg_textured_dielectric",
                     specGloss("\"diffuseTexture\":" +
                               textureInfo(doc.texture("pbr_workflows_checker.png")) +
                               ",\"specularFactor\":" + vec(glm::vec3(kDielectricF0)) +
                               ",\"specularGlossinessTexture\":" +
                               textureInfo(doc.texture("pbr_workflows_dielectric_sg.png"))),
                     at(1, 0.5f));
    } else {
        doc.sphereAt("mr_textured_metal",
                     metallicRoughness(
                         "\"baseColorTexture\":" +
                         textureInfo(doc.texture("pbr_workflows_metal_color.png")) +
                         ",\"metallicRoughnessTexture\":" +
                         textureInfo(doc.texture("pbr_workflows_metal_mr.png"))),
                     at(0, 0.5f));
        doc.sphereAt("mr_textured_dielectric",
                     metallicRoughness(
                         "\"baseColorFactor\":" +
                         vec(glm::vec4(glm::vec3(1.0f - kDielectricF0), 1.0f)) +
                         ",\"baseColorTexture\":" +
                         textureInfo(doc.texture("pbr_workflows_checker.png")) +
                         ",\"metallicRoughnessTexture\":" +
                         textureInfo(doc.texture("pbr_workflows_dielectric_mr.png"))),
                     at(1, 0.5f));
    }
    if (!extra) return;
    if (sg) {
        doc.sphereAt("sg_coloured_specular",
                     specGloss("\"diffuseFactor\":" + vec(glm::vec4(kBlue, 1.0f)) +
                               ",\"specularFactor\":" + vec(kOrange) +
                               ",\"glossinessFactor\":0.7"),
                     at(2, 0.5f));
        doc.sphereAt("sg_strong_specular",
                     specGloss("\"diffuseFactor\":" + vec(glm::vec4(kBlue, 1.0f)) +
                               ",\"specularFactor\":[0.5,0.5,0.5],\"glossinessFactor\":0.7"),
                     at(3, 0.5f));
    } else {
        for (int i = 2; i < 4; ++i) {
            doc.sphereAt("mr_plain_dielectric_" + std::to_string(i),
                         metallicRoughness("\"baseColorFactor\":" + vec(glm::vec4(kBlue, 1.0f)) +
                                           ",\"metallicFactor\":0,\"roughnessFactor\":0.3"),
                         at(i, 0.5f));
        }
    }
}

// The document's text, its buffer beside it as `bin`.
std::string finish(Document& doc, const std::string& bin, bool sgUsed, bool required) {
    // the light's -Z turned to (0.5, -0.6, -0.62): from the upper left, in front
    const glm::vec3 to = glm::normalize(glm::vec3(0.5f, -0.6f, -0.62f)), from(0, 0, -1);
    const glm::vec3 axis = glm::cross(from, to);
    const glm::vec4 q = glm::normalize(glm::vec4(axis, 1.0f + glm::dot(from, to)));
    doc.nodes.push_back("{\"name\":\"sun\",\"rotation\":" + vec(q) +
                        ",\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}}");
    std::vector<std::string> roots;
    for (size_t i = 0; i < doc.nodes.size(); ++i) roots.push_back(std::to_string(i));
    const char* line = ",\n";
    std::string used = "[\"KHR_lights_punctual\"";
    if (sgUsed) used += ",\"KHR_materials_pbrSpecularGlossiness\"";
    used += "]";
    std::vector<std::pair<std::string, std::string>> members = {
        {"asset",
         "{\"version\":\"2.0\",\"generator\":\"pbr-samples resources/models/make_pbr_workflows\"}"},
        {"extensionsUsed", used}};
    if (required) members.push_back({"extensionsRequired", "[\"KHR_materials_pbrSpecularGlossiness\"]"});
    members.push_back({"extensions",
                       "{\"KHR_lights_punctual\":{\"lights\":[{\"name\":\"sun\",\"type\":"
                       "\"directional\",\"color\":[1,0.97,0.92],\"intensity\":2}]}}"});
    members.push_back({"scene", "0"});
    members.push_back({"scenes", "[{\"name\":\"pbr_workflows\",\"nodes\":" + gltf::array(roots) + "}]"});
    members.push_back({"nodes", gltf::array(doc.nodes, line)});
    members.push_back({"meshes", gltf::array(doc.meshes, line)});
    members.push_back({"materials", gltf::array(doc.materials, line)});
    if (!doc.textures.empty()) {
        members.push_back({"textures", gltf::array(doc.textures, line)});
        // NEAREST: each texel read as it is. Filtering would blend a linear 8-bit channel (G of
        // metallic-roughness) and the alpha of an sRGB texture (glossiness) at different
        // precisions on some GL implementations (llvmpipe: up to 1/255 of roughness at band
        // edges), a difference of the texture units, not of the workflows.
        members.push_back(
            {"samplers", "[{\"magFilter\":9728,\"minFilter\":9984,\"wrapS\":10497,\"wrapT\":10497}]"});
        members.push_back({"images", gltf::array(doc.images, line)});
    }
    for (auto& member : doc.buffer.members(bin)) members.push_back(member);
    return gltf::document(members);
}

}  // namespace

int main(int argc, char** argv) try {
    if (argc != 2) throw pbr::UsageError("no output folder", "usage: make_pbr_workflows OUT_DIR\n");
    const fs::path dir = argv[1];
    fs::create_directories(dir);
    pbr::OutputBatch files;

    // The textures: colour and roughness bands for the metal, a checker for the dielectric,
    // written as the pages carry them (PngEncoding::Small).
    const auto texture = [&](const char* name, const Image& image) {
        files.add(dir / name, pbr::encodePng(image, pbr::PngEncoding::Small));
    };
    texture("pbr_workflows_metal_color.png",
            makeImage(kSize, 3, [](int, int y) { return glm::ivec4(metalColor(y), 255); }));
    texture("pbr_workflows_metal_mr.png", makeImage(kSize, 3, [](int x, int) {
                return glm::ivec4(0, roughnessByte(x), 255, 255);
            }));
    texture("pbr_workflows_metal_sg.png", makeImage(kSize, 4, [](int x, int y) {
                return glm::ivec4(metalColor(y), 255 - roughnessByte(x));
            }));
    texture("pbr_workflows_checker.png",
            makeImage(kSize, 3, [](int x, int y) { return glm::ivec4(checkerColor(x, y), 255); }));
    texture("pbr_workflows_dielectric_mr.png", makeImage(kSize, 3, [](int x, int) {
                return glm::ivec4(0, roughnessByte(x), 0, 255);
            }));
    texture("pbr_workflows_dielectric_sg.png", makeImage(kSize, 4, [](int x, int) {
                return glm::ivec4(255, 255, 255, 255 - roughnessByte(x));
            }));

    struct Output {
        std::string name;
        bool mr, sg, extra, required;
        float mrX, sgX;
    };
    const Output outputs[] = {
        {"pbr_workflows", true, true, true, false, -2.25f, 2.25f},
        {"pbr_workflows_required", true, true, true, true, -2.25f, 2.25f},
        {"pbr_workflows_mr", true, false, false, false, 0.0f, 0.0f},
        {"pbr_workflows_sg", false, true, false, false, 0.0f, 0.0f},
    };
    for (const Output& out : outputs) {
        Document doc;
        doc.sphere = doc.buffer.addPrimitive(gltf::gridSphere(0.4f));
        if (out.mr) addHalf(doc, false, out.extra, {out.mrX, 0.0f, 0.0f});
        if (out.sg) addHalf(doc, true, out.extra, {out.sgX, 0.0f, 0.0f});
        const std::string bin = out.name + ".bin";
        const std::string text = finish(doc, bin, out.sg, out.required);
        files.add(dir / bin, doc.buffer.bytes());
        files.add(dir / (out.name + ".gltf"), text);
    }
    files.commit();
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
