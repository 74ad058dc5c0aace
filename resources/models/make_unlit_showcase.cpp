// The recipe for the project's own glTF 2.0 asset for sample 03 (run by the build):
//   make_unlit_showcase OUT_DIR
// writes OUT_DIR/unlit_showcase.gltf, .bin and _texture.png. Four objects, all with
// KHR_materials_unlit, each showing one input of colour = baseColorFactor x vertex colour x
// baseColorTexture, so a wrong or missing input shows:
//   top left      an RGB cube: vertex colours only (each corner's colour is its position)
//   top right     a sphere: baseColorFactor only (orange)
//   bottom left   a quad: baseColorTexture only (an "F" on a checker: a flipped uv shows)
//   bottom right  a quad: all three at once (a tinted factor, a colour gradient, the texture)
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "base/error.h"
#include "base/output.h"
#include "files/image.h"
#include "gltf_writer.h"

namespace {

namespace fs = std::filesystem;

struct Mesh {
    std::string name;
    pbr::MeshData data;  // uvs and colours empty where the object has none
};

Mesh rgbCube(float half) {
    Mesh mesh{"rgb_cube", {}};
    const float faces[6][3][3] = {
        // normal, u axis, v axis (u x v = normal: counter-clockwise outside)
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
    };
    for (const auto& face : faces) {
        const auto base = std::uint32_t(mesh.data.positions.size());
        for (const auto& corner : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
            glm::vec3 position, normal;
            glm::vec4 color(1.0f);
            for (int c = 0; c < 3; ++c) {
                const float p = face[0][c] + face[1][c] * float(corner.first) +
                                face[2][c] * float(corner.second);
                position[c] = p * half;
                normal[c] = face[0][c];
                color[c] = p > 0.0f ? 1.0f : 0.0f;  // the corner's position as its colour
            }
            mesh.data.positions.push_back(position);
            mesh.data.normals.push_back(normal);
            mesh.data.colors.push_back(color);
        }
        for (std::uint32_t i : {0, 1, 2, 0, 2, 3}) mesh.data.indices.push_back(base + i);
    }
    return mesh;
}

Mesh sphere(float radius, int columns, int rows) {
    Mesh mesh{"factor_sphere", {}};
    for (int y = 0; y <= rows; ++y) {
        for (int x = 0; x <= columns; ++x) {
            const float theta = float(y) / float(rows) * float(M_PI),
                        phi = float(x) / float(columns) * 2.0f * float(M_PI);
            const glm::vec3 n(std::cos(phi) * std::sin(theta), std::cos(theta),
                              std::sin(phi) * std::sin(theta));
            mesh.data.positions.push_back(n * radius);
            mesh.data.normals.push_back(n);
        }
    }
    for (int y = 0; y < rows; ++y) {
        for (int x = 0; x < columns; ++x) {
            const int a = y * (columns + 1) + x, b = a + columns + 1;
            for (int i : {a, a + 1, b, a + 1, b + 1, b})
                mesh.data.indices.push_back(std::uint32_t(i));
        }
    }
    return mesh;
}

// A square in the XY plane facing +Z; uv (0,0) at the top left, as glTF has it. Its back (-Z) is
// a second face of its own, with the texture mirrored, so that the "F" reads the right way round
// from both sides as the model turns (one material, single-sided: each face culls the other).
Mesh quad(const std::string& name, float half, bool gradient) {
    Mesh mesh{name, {}};
    const float corners[4][2] = {{-1, 1}, {1, 1}, {1, -1}, {-1, -1}};  // top left, clockwise
    const glm::vec4 colors[4] = {
        {1, 1, 1, 1}, {1, 0.45f, 0.45f, 1}, {0.45f, 1, 0.45f, 1}, {0.45f, 0.45f, 1, 1}};
    for (const float side : {1.0f, -1.0f}) {
        for (int i = 0; i < 4; ++i) {
            mesh.data.positions.push_back({corners[i][0] * half, corners[i][1] * half, 0.0f});
            mesh.data.normals.push_back({0.0f, 0.0f, side});
            // seen from behind, x runs the other way: mirror u so the picture reads the same
            mesh.data.uvs.push_back(
                {side * corners[i][0] * 0.5f + 0.5f, 0.5f - corners[i][1] * 0.5f});
            if (gradient) mesh.data.colors.push_back(colors[i]);
        }
    }
    // counter-clockwise seen from +Z, then the back's, counter-clockwise seen from -Z
    mesh.data.indices = {0, 3, 2, 0, 2, 1, 4, 5, 6, 4, 6, 7};
    return mesh;
}

// 128 x 128: 8 x 8 blocks of 16 texels, a two-tone checker with an "F" in dark blue.
pbr::Image texture() {
    static const char* glyph[8] = {"........", ".FFFFF..", ".F......", ".FFFF...",
                                   ".F......", ".F......", ".F......", "........"};
    pbr::Image image{128, 128, 3, {}};
    for (int y = 0; y < 128; ++y) {
        for (int x = 0; x < 128; ++x) {
            const int bx = x / 16, by = y / 16;
            std::uint8_t rgb[3] = {235, 225, 200};
            if ((bx + by) % 2) rgb[0] = 250, rgb[1] = 190, rgb[2] = 120;
            if (glyph[by][bx] == 'F') rgb[0] = 30, rgb[1] = 50, rgb[2] = 140;
            image.pixels.insert(image.pixels.end(), rgb, rgb + 3);
        }
    }
    return image;
}

}  // namespace

int main(int argc, char** argv) try {
    if (argc != 2)
        throw pbr::UsageError("no output folder", "usage: make_unlit_showcase OUT_DIR\n");
    const fs::path dir = argv[1];
    fs::create_directories(dir);

    struct Object {
        Mesh mesh;
        float translation[3];
        float factor[4];
        bool textured;
        const char* materialName;
    };
    const std::vector<Object> objects = {
        {rgbCube(0.4f), {-1.1f, 0.6f, 0.0f}, {1, 1, 1, 1}, false, "vertex colours"},
        {sphere(0.45f, 32, 16),
         {1.1f, 0.6f, 0.0f},
         {1.0f, 0.42f, 0.08f, 1},
         false,
         "base colour factor"},
        {quad("texture_quad", 0.45f, false),
         {-1.1f, -0.6f, 0.0f},
         {1, 1, 1, 1},
         true,
         "base colour texture"},
        {quad("all_three_quad", 0.45f, true),
         {1.1f, -0.6f, 0.0f},
         {0.95f, 0.85f, 1.0f, 1},
         true,
         "all three"},
    };

    pbr::gltf::Buffer buffer;
    std::ostringstream meshes, nodes, materials;
    for (size_t i = 0; i < objects.size(); ++i) {
        const Object& o = objects[i];
        meshes << (i ? "," : "") << "{\"name\":\"" << o.mesh.name << "\",\"primitives\":["
               << buffer.addPrimitive(o.mesh.data) << ",\"material\":" << i << "}]}";
        nodes << (i ? "," : "") << "{\"name\":\"" << o.mesh.name << "\",\"mesh\":" << i
              << ",\"translation\":[" << o.translation[0] << "," << o.translation[1] << ","
              << o.translation[2] << "]}";
        materials << (i ? "," : "") << "{\"name\":\"" << o.materialName
                  << "\",\"pbrMetallicRoughness\":{"
                  << "\"baseColorFactor\":[" << o.factor[0] << "," << o.factor[1] << ","
                  << o.factor[2] << "," << o.factor[3] << "],"
                  << (o.textured ? "\"baseColorTexture\":{\"index\":0}," : "")
                  << "\"metallicFactor\":0,\"roughnessFactor\":0.9},\"extensions\":{\"KHR_"
                     "materials_unlit\":{}}}";
    }

    std::vector<std::pair<std::string, std::string>> members = {
        {"asset",
         "{\"version\":\"2.0\",\"generator\":\"pbr-samples "
         "resources/models/make_unlit_showcase\"}"},
        {"extensionsUsed", "[\"KHR_materials_unlit\"]"},
        {"scene", "0"},
        {"scenes", "[{\"nodes\":[0,1,2,3]}]"},
        {"nodes", "[" + nodes.str() + "]"},
        {"meshes", "[" + meshes.str() + "]"},
        {"materials", "[" + materials.str() + "]"},
        {"textures", "[{\"source\":0,\"sampler\":0}]"},
        {"samplers", "[{\"magFilter\":9729,\"minFilter\":9987,\"wrapS\":33071,\"wrapT\":33071}]"},
        {"images", "[{\"uri\":\"unlit_showcase_texture.png\"}]"},
    };
    for (auto& member : buffer.members("unlit_showcase.bin")) members.push_back(member);
    pbr::writeFileAtomically(dir / "unlit_showcase.gltf", pbr::gltf::document(members));
    pbr::writeFileAtomically(dir / "unlit_showcase.bin", buffer.bytes());
    pbr::writePng(dir / "unlit_showcase_texture.png", texture(), pbr::PngEncoding::Small);
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
