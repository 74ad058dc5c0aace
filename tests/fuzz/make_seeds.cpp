// Writes the binary seeds of tests/fuzz/seeds: small files of each format made by the project's
// own writers (a few bytes each, so that every fuzz run starts from a sound file of each kind and
// the gcc builds have something of each to replay). The same bytes on every run; run it again
// when a writer's format changes:
//   cmake --build --preset fuzz --target fuzz_make_seeds
//   build/fuzz/bin/fuzz_make_seeds tests/fuzz/seeds
#include <cstdio>
#include <filesystem>
#include <string>

#include "base/error.h"
#include "base/output.h"
#include "files/image.h"
#include "files/ktx.h"
#include "gltf/model_pack.h"

namespace pbr {
namespace {

namespace fs = std::filesystem;

HdrImage gradient(int width, int height) {
    HdrImage image{width, height, {}};
    for (int i = 0; i < width * height; ++i) {
        // a few exponents and a run of equal texels (the writer's run-length case)
        const float v = i % 7 == 0 ? 0.0f : float(i % 5) * 0.37f + (i % 11 == 0 ? 300.0f : 0.0f);
        image.pixels.insert(image.pixels.end(), {v, v * 0.5f, 1.0f});
    }
    return image;
}

Image picture(int width, int height, int channels) {
    Image image{width, height, channels, {}};
    for (int i = 0; i < width * height * channels; ++i)
        image.pixels.push_back(std::uint8_t(i * 37));
    return image;
}

// A KTX image of `format` whose texels count up, with the key the ibl_cache target looks for.
KtxImage ktx(KtxFormat format, int size, int faces, int levels) {
    KtxImage image{
        .format = format, .width = size, .height = size, .faces = faces, .levels = levels};
    for (int level = 0; level < levels; ++level) {
        for (int face = 0; face < faces; ++face) {
            std::vector<std::uint8_t> texels(image.imageBytes(level));
            for (size_t i = 0; i < texels.size(); ++i) texels[i] = std::uint8_t(i + size_t(face));
            image.images.push_back(texels);
        }
    }
    image.metadata = {{"pbr.cacheKey", "a key"}, {"KTXorientation", "S=r,T=u"}};
    return image;
}

// One triangle with every attribute, a material with a texture, a light and a raw image.
Model triangle() {
    Model model;
    model.file = "triangle.gltf";
    model.extensionsUsed = {"KHR_lights_punctual"};
    ModelPrimitive primitive;
    primitive.transform = glm::mat4(1.0f);
    primitive.mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    primitive.mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    primitive.mesh.uvs = {{0, 0}, {1, 0}, {0, 1}};
    primitive.mesh.tangents = {{1, 0, 0, 1}, {1, 0, 0, 1}, {1, 0, 0, 1}};
    primitive.mesh.indices = {0, 1, 2};
    model.primitives.push_back(primitive);
    Material material;
    material.name = "red";
    material.baseColorFactor = {1, 0, 0, 1};
    material.baseColorTexture.embedded = 0;
    model.materials.push_back(material);
    model.embeddedImages.push_back({{255, 0, 0, 255}, 1, 1, "*0"});
    model.lights.push_back({.name = "sun", .color = {3, 3, 3}});
    model.boundsMax = {1, 1, 0};
    return model;
}

// The triangle as a binary glTF: the JSON chunk, then the BIN chunk with positions and indices.
std::string triangleGlb() {
    std::string bin;
    for (const float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f})
        bin.append(reinterpret_cast<const char*>(&v), 4);
    for (const std::uint16_t i : {0, 1, 2, 0}) bin.append(reinterpret_cast<const char*>(&i), 2);
    std::string json =
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]}],)"
        R"("materials":[{"name":"red","pbrMetallicRoughness":{"baseColorFactor":[1,0,0,1]}}],)"
        R"("buffers":[{"byteLength":44}],"bufferViews":[{"buffer":0,"byteLength":36},)"
        R"({"buffer":0,"byteOffset":36,"byteLength":6}],"accessors":[{"bufferView":0,)"
        R"("componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},)"
        R"({"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}]})";
    json.append((4 - json.size() % 4) % 4, ' ');
    std::string glb = "glTF";
    auto put32 = [&](std::uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
    put32(2);
    put32(std::uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    put32(std::uint32_t(json.size()));
    glb += "JSON";
    glb += json;
    put32(std::uint32_t(bin.size()));
    glb.append("BIN\0", 4);
    glb += bin;
    return glb;
}

int run(const fs::path& seeds) {
    auto write = [&](const std::string& target, const std::string& name, const std::string& bytes) {
        fs::create_directories(seeds / target);
        writeFileAtomically(seeds / target / name, bytes);
    };
    write("hdr", "flat_2x2.hdr", encodeHdr(gradient(2, 2)));
    write("hdr", "rle_8x2.hdr", encodeHdr(gradient(8, 2)));
    write("hdr", "rle_140x1.hdr", encodeHdr(gradient(140, 1)));
    write("png", "grey_3x2.png", encodePng(picture(3, 2, 1)));
    write("png", "grey_alpha_2x2.png", encodePng(picture(2, 2, 2)));
    write("png", "rgb_4x3.png", encodePng(picture(4, 3, 3)));
    write("png", "rgba_2x2.png", encodePng(picture(2, 2, 4)));
    for (const std::string target : {"ktx", "ibl_cache"}) {
        write(target, "lut_4_rg16f.ktx", encodeKtx(ktx(KtxFormat::RG16F, 4, 1, 1)));
        write(target, "lut_2_rgba16f.ktx", encodeKtx(ktx(KtxFormat::RGBA16F, 2, 1, 1)));
        write(target, "cube_4_rgba16f_3_levels.ktx", encodeKtx(ktx(KtxFormat::RGBA16F, 4, 6, 3)));
        write(target, "cube_2_rgba32f.ktx", encodeKtx(ktx(KtxFormat::RGBA32F, 2, 6, 1)));
        write(target, "cube_1_rgb16f.ktx", encodeKtx(ktx(KtxFormat::RGB16F, 1, 6, 1)));
    }
    write("model_pack", "triangle.gltf.pbrmodel", encodeModelPack(triangle()));
    write("model", "triangle.glb", triangleGlb());
    write("gltf_json", "triangle.glb", triangleGlb());
    return 0;
}

}  // namespace
}  // namespace pbr

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s <tests/fuzz/seeds>\n", argv[0]);
        return 2;
    }
    try {
        return pbr::run(argv[1]);
    } catch (...) {
        return pbr::reportFailure();
    }
}
