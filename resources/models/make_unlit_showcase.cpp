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
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "error.h"
#include "image.h"
#include "output.h"

namespace {

namespace fs = std::filesystem;

struct Vertex {
    float position[3];
    float normal[3];
    float uv[2];
    float color[4];
};

struct Mesh {
    std::string name;
    std::vector<Vertex> vertices;
    std::vector<std::uint16_t> indices;
    bool colors = false, uvs = false;
};

Mesh rgbCube(float half) {
    Mesh mesh{"rgb_cube", {}, {}, true, false};
    const float faces[6][3][3] = {
        // normal, u axis, v axis (u x v = normal: counter-clockwise outside)
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
    };
    for (const auto& face : faces) {
        const auto base = std::uint16_t(mesh.vertices.size());
        for (const auto& corner : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
            Vertex v{};
            for (int c = 0; c < 3; ++c) {
                const float p = face[0][c] + face[1][c] * float(corner.first) +
                                face[2][c] * float(corner.second);
                v.position[c] = p * half;
                v.normal[c] = face[0][c];
                v.color[c] = p > 0.0f ? 1.0f : 0.0f;  // the corner's position as its colour
            }
            v.color[3] = 1.0f;
            mesh.vertices.push_back(v);
        }
        for (int i : {0, 1, 2, 0, 2, 3}) mesh.indices.push_back(std::uint16_t(base + i));
    }
    return mesh;
}

Mesh sphere(float radius, int columns, int rows) {
    Mesh mesh{"factor_sphere", {}, {}, false, false};
    for (int y = 0; y <= rows; ++y) {
        for (int x = 0; x <= columns; ++x) {
            const float theta = float(y) / float(rows) * float(M_PI),
                        phi = float(x) / float(columns) * 2.0f * float(M_PI);
            const float n[3] = {std::cos(phi) * std::sin(theta), std::cos(theta),
                                std::sin(phi) * std::sin(theta)};
            Vertex v{};
            for (int c = 0; c < 3; ++c) {
                v.position[c] = n[c] * radius;
                v.normal[c] = n[c];
            }
            mesh.vertices.push_back(v);
        }
    }
    for (int y = 0; y < rows; ++y) {
        for (int x = 0; x < columns; ++x) {
            const int a = y * (columns + 1) + x, b = a + columns + 1;
            for (int i : {a, a + 1, b, a + 1, b + 1, b}) mesh.indices.push_back(std::uint16_t(i));
        }
    }
    return mesh;
}

// A square in the XY plane facing +Z; uv (0,0) at the top left, as glTF has it.
Mesh quad(const std::string& name, float half, bool gradient) {
    Mesh mesh{name, {}, {}, gradient, true};
    const float corners[4][2] = {{-1, 1}, {1, 1}, {1, -1}, {-1, -1}};  // top left, clockwise
    const float colors[4][4] = {
        {1, 1, 1, 1}, {1, 0.45f, 0.45f, 1}, {0.45f, 1, 0.45f, 1}, {0.45f, 0.45f, 1, 1}};
    for (int i = 0; i < 4; ++i) {
        Vertex v{};
        v.position[0] = corners[i][0] * half;
        v.position[1] = corners[i][1] * half;
        v.normal[2] = 1.0f;
        v.uv[0] = corners[i][0] * 0.5f + 0.5f;
        v.uv[1] = 0.5f - corners[i][1] * 0.5f;
        std::memcpy(v.color, colors[i], sizeof v.color);
        mesh.vertices.push_back(v);
    }
    mesh.indices = {0, 3, 2, 0, 2, 1};  // counter-clockwise seen from +Z
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

    std::string bin;
    std::ostringstream views, accessors, meshes, nodes, materials;
    int view = 0, accessor = 0;
    auto addView = [&](const void* data, size_t bytes, int target) {
        while (bin.size() % 4) bin += '\0';
        views << (view ? "," : "") << "{\"buffer\":0,\"byteOffset\":" << bin.size()
              << ",\"byteLength\":" << bytes << ",\"target\":" << target << "}";
        bin.append(static_cast<const char*>(data), bytes);
        return view++;
    };
    auto addAccessor = [&](int bufferView, int componentType, size_t count, const char* type,
                           const std::string& extra) {
        accessors << (accessor ? "," : "") << "{\"bufferView\":" << bufferView
                  << ",\"componentType\":" << componentType << ",\"count\":" << count
                  << ",\"type\":\"" << type << "\"" << extra << "}";
        return accessor++;
    };
    for (size_t i = 0; i < objects.size(); ++i) {
        const Object& o = objects[i];
        std::vector<float> positions, normals, uvs, colors;
        float lo[3] = {1e9f, 1e9f, 1e9f}, hi[3] = {-1e9f, -1e9f, -1e9f};
        for (const Vertex& v : o.mesh.vertices) {
            positions.insert(positions.end(), v.position, v.position + 3);
            normals.insert(normals.end(), v.normal, v.normal + 3);
            uvs.insert(uvs.end(), v.uv, v.uv + 2);
            colors.insert(colors.end(), v.color, v.color + 4);
            for (int c = 0; c < 3; ++c)
                lo[c] = std::min(lo[c], v.position[c]), hi[c] = std::max(hi[c], v.position[c]);
        }
        std::ostringstream bounds;
        bounds << ",\"min\":[" << lo[0] << "," << lo[1] << "," << lo[2] << "],\"max\":[" << hi[0]
               << "," << hi[1] << "," << hi[2] << "]";
        const size_t n = o.mesh.vertices.size();
        const int pos = addAccessor(addView(positions.data(), positions.size() * 4, 34962), 5126, n,
                                    "VEC3", bounds.str());
        const int nrm =
            addAccessor(addView(normals.data(), normals.size() * 4, 34962), 5126, n, "VEC3", "");
        std::ostringstream attributes;
        attributes << "\"POSITION\":" << pos << ",\"NORMAL\":" << nrm;
        if (o.mesh.uvs) {
            attributes << ",\"TEXCOORD_0\":"
                       << addAccessor(addView(uvs.data(), uvs.size() * 4, 34962), 5126, n, "VEC2",
                                      "");
        }
        if (o.mesh.colors) {
            attributes << ",\"COLOR_0\":"
                       << addAccessor(addView(colors.data(), colors.size() * 4, 34962), 5126, n,
                                      "VEC4", "");
        }
        const int idx =
            addAccessor(addView(o.mesh.indices.data(), o.mesh.indices.size() * 2, 34963), 5123,
                        o.mesh.indices.size(), "SCALAR", "");
        meshes << (i ? "," : "") << "{\"name\":\"" << o.mesh.name
               << "\",\"primitives\":[{\"attributes\":{" << attributes.str()
               << "},\"indices\":" << idx << ",\"material\":" << i << "}]}";
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
    while (bin.size() % 4) bin += '\0';

    std::ostringstream json;
    json << "{\n\"asset\":{\"version\":\"2.0\",\"generator\":\"pbr-samples "
            "resources/models/make_unlit_showcase\"},\n"
         << "\"extensionsUsed\":[\"KHR_materials_unlit\"],\n\"scene\":0,\n\"scenes\":[{\"nodes\":["
            "0,1,2,3]}],\n"
         << "\"nodes\":[" << nodes.str() << "],\n\"meshes\":[" << meshes.str()
         << "],\n\"materials\":[" << materials.str() << "],\n"
         << "\"textures\":[{\"source\":0,\"sampler\":0}],\n"
         << "\"samplers\":[{\"magFilter\":9729,\"minFilter\":9987,\"wrapS\":33071,\"wrapT\":33071}]"
            ",\n"
         << "\"images\":[{\"uri\":\"unlit_showcase_texture.png\"}],\n"
         << "\"buffers\":[{\"uri\":\"unlit_showcase.bin\",\"byteLength\":" << bin.size() << "}],\n"
         << "\"bufferViews\":[" << views.str() << "],\n\"accessors\":[" << accessors.str()
         << "]\n}\n";
    pbr::writeFileAtomically(dir / "unlit_showcase.gltf", json.str());
    pbr::writeFileAtomically(dir / "unlit_showcase.bin", bin);
    pbr::writePng(dir / "unlit_showcase_texture.png", texture());
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
