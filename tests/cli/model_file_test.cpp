// --model with broken files, for both glTF samples (03 unlit, 07 metallic-roughness): Debian's
// assimp-testmodels corpus of bad glTF, and our own damaged copies. Each gives one line naming
// the file and the reason with a non-zero exit, or, where Assimp accepts the file, a sane render
// (exit 0, no GL error); never a crash or a hang. And 07 on every glTF 2.0 file of the corpus.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "support/gltf_scene.h"
#include "support/golden.h"
#include "support/test_data.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

struct Outcome {
    SampleRender render;
    bool refused;
};

Outcome run(const std::string& sample, const fs::path& model, const fs::path& output,
            std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {"--model", model.string(), "--size", "160x90"};
    args.insert(args.end(), extra.begin(), extra.end());
    Outcome o{renderSample(sample, output, args), false};
    const RunResult& r = o.render.run;
    EXPECT_NE(r.exitCode, -1) << model << " crashed: " << r.err;
    EXPECT_EQ(r.err.find("GL error"), std::string::npos) << model << ": " << r.err;
    o.refused = r.exitCode != 0;
    if (o.refused) {
        EXPECT_EQ(r.exitCode, 1) << model;
        const auto lines = r.errLines();
        EXPECT_EQ(lines.size(), 1u) << model << ": " << r.err;
        if (!lines.empty()) {
            const std::string name = model.filename().string();
            const size_t at = lines[0].find(name);
            EXPECT_NE(at, std::string::npos) << lines[0];
            EXPECT_GT(lines[0].size(), at + name.size() + 8) << "no reason given: " << lines[0];
        }
        EXPECT_FALSE(fs::exists(output));
    } else {
        EXPECT_TRUE(fs::exists(output)) << model;
    }
    return o;
}

class ModelFile : public ::testing::TestWithParam<std::string> {};

INSTANTIATE_TEST_SUITE_P(GltfSamples, ModelFile,
                         ::testing::Values("03_gltf_unlit", "07_gltf_metallic_roughness",
                                           "08_gltf_specular_glossiness"),
                         [](const auto& info) { return paramName(info.param.substr(0, 2)); });

TEST_P(ModelFile, BrokenFilesFromAssimpsCorpus) {
    PBR_NEED_ASSIMP_MODELS(kGltf);
    const fs::path dir = testOutputDir("model_broken_corpus_" + GetParam());
    // file, and whether it must be refused (true) or may render (false: Assimp repairs it)
    const std::vector<std::pair<const char*, bool>> files = {
        {"IndexOutOfRange/IndexOutOfRange.gltf", false},  // Assimp drops the bad face
        {"IndexOutOfRange/AllIndicesOutOfRange.gltf", true},
        {"MissingBin/BoxTextured.gltf", true},
        {"RecursiveNodes/RecursiveNodes.gltf", true},
        {"SchemaFailures/sceneWrongType.gltf", true},
        {"TestNoRootNode/NoScene.gltf", true},
        {"TestNoRootNode/SceneWithoutNodes.gltf", true},
        {"IncorrectVertexArrays/Cube.gltf", false},  // normals generated where missing
        {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", true},
        {"BoxBadNormals-glTF-Binary/BoxBadNormals.glb", false},  // zero normals become +Z
    };
    int index = 0;
    for (const auto& [file, mustRefuse] : files) {
        const Outcome o = run(GetParam(), kGltf / file, dir / (std::to_string(index++) + ".png"));
        if (mustRefuse)
            EXPECT_TRUE(o.refused) << file << " was drawn";
        else
            EXPECT_FALSE(o.refused) << file << ": " << o.render.run.err;
    }
}

// Damaged copies of good files: each says what is wrong in words, never Assimp's "no suitable
// reader", and never a decoder's code.
TEST_P(ModelFile, DamagedCopies) {
    PBR_NEED_ASSIMP_MODELS(kGltf);
    const fs::path dir = testOutputDir("model_damaged_" + GetParam());
    const std::string glb = readBytes(kGltf / "BoxTextured-glTF-Binary/BoxTextured.glb");
    const std::string gltf = readBytes(kGltf / "BoxTextured-glTF/BoxTextured.gltf");
    ASSERT_GT(glb.size(), 1000u);
    ASSERT_GT(gltf.size(), 1000u);
    std::ofstream(dir / "truncated.glb", std::ios::binary) << glb.substr(0, glb.size() / 2);
    std::ofstream(dir / "truncated.gltf", std::ios::binary) << gltf.substr(0, gltf.size() / 2);
    std::string comma = gltf;
    // BoxTextured.gltf opens with "{", then "    \"asset\"" on line 2: a comma at column 4 of line
    // 2 stands before any member.
    const size_t asset = comma.find("\"asset\"");
    ASSERT_NE(asset, std::string::npos);
    comma[asset - 1] = ',';  // the last of the four spaces
    std::ofstream(dir / "comma.gltf", std::ios::binary) << comma;
    std::ofstream(dir / "empty.gltf").close();
    fs::copy_file(kGltf / "BoxTextured-glTF/CesiumLogoFlat.png", dir / "picture.gltf");
    fs::copy_file(kGltf / "BoxTextured-glTF/CesiumLogoFlat.png", dir / "picture.glb");
    // The model is fine, its texture is cut short.
    fs::create_directory(dir / "texture");
    fs::copy_file(kGltf / "BoxTextured-glTF/BoxTextured.gltf", dir / "texture/BoxTextured.gltf");
    fs::copy_file(kGltf / "BoxTextured-glTF/BoxTextured0.bin", dir / "texture/BoxTextured0.bin");
    const std::string png = readBytes(kGltf / "BoxTextured-glTF/CesiumLogoFlat.png");
    std::ofstream(dir / "texture/CesiumLogoFlat.png", std::ios::binary)
        << png.substr(0, png.size() / 2);

    const std::vector<std::pair<std::string, std::string>> cases = {
        {"truncated.glb", "truncated.glb: truncated: the GLB header says " +
                              std::to_string(glb.size()) + " bytes, the file has " +
                              std::to_string(glb.size() / 2)},
        {"truncated.gltf", "truncated.gltf: truncated: the JSON ends inside"},
        {"comma.gltf", "comma.gltf: invalid JSON at line 2, column 4: expected a name in quotes"},
        {"empty.gltf", "empty.gltf: empty file"},
        {"picture.gltf", "picture.gltf: invalid JSON at line 1, column 1"},
        {"picture.glb", "picture.glb: not a binary glTF file (it does not start with 'glTF')"},
        {"texture/BoxTextured.gltf", "CesiumLogoFlat.png: truncated or damaged PNG data"},
        {"nowhere.gltf", "nowhere.gltf: no such file"},
    };
    for (const auto& [file, message] : cases) {
        const Outcome o =
            run(GetParam(), dir / file, dir / (fs::path(file).filename().string() + ".png"));
        EXPECT_TRUE(o.refused) << file << " was drawn";
        EXPECT_NE(o.render.run.err.find(message), std::string::npos)
            << o.render.run.err << "(expected: " << message << ")";
        EXPECT_EQ(o.render.run.err.find("No suitable reader"), std::string::npos);
    }
}

// Files whose primitives name no material are drawn in glTF's default material (white): visible
// on 03's grey background, and said on stderr.
TEST(ModelFile, NoMaterialIsVisibleAndSaid) {
    PBR_NEED_ASSIMP_MODELS(kGltf);
    const fs::path dir = testOutputDir("model_no_material");
    int index = 0;
    for (const char* file : {"IncorrectVertexArrays/Cube.gltf", "cameras/Cameras.gltf",
                             "simple_skin/simple_skin.gltf"}) {
        const fs::path output = dir / (std::to_string(index++) + ".png");
        const Outcome o = run("03_gltf_unlit", kGltf / file, output);
        ASSERT_FALSE(o.refused) << file << ": " << o.render.run.err;
        EXPECT_NE(o.render.run.err.find("name no material; drawn in glTF's default material"),
                  std::string::npos)
            << file << ": " << o.render.run.err;
        // Some pixels are the default material's white, far from the background.
        const Image image = readImage(output, 3);
        size_t white = 0;
        for (size_t i = 0; i < image.pixels.size(); i += 3) {
            if (image.pixels[i] > 240 && image.pixels[i + 1] > 240 && image.pixels[i + 2] > 240)
                ++white;
        }
        EXPECT_GT(white, size_t(image.width * image.height) / 200) << file;
        EXPECT_LT(image.at(0, 0, 0), 200) << file << ": the background is as light as the model";
    }
}

// 07 on every glTF 2.0 file of Debian's assimp-testmodels: drawn (exit 0, no GL error, and
// visible: against the plain background of --no-ibl, some pixels differ from the corner), or
// refused in one line naming the file (nothing drawable, or broken). Files requiring an
// extension 07 does not draw say so in a warning naming it.
TEST(ModelFile, EveryCorpusFileIn07) {
    PBR_NEED_ASSIMP_MODELS(kGltf);
    const fs::path dir = testOutputDir("model_corpus_07");
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(kGltf)) {
        const std::string extension = entry.path().extension().string();
        if (entry.is_regular_file() && (extension == ".gltf" || extension == ".glb"))
            files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    ASSERT_GT(files.size(), 30u);
    int drawn = 0, refused = 0, index = 0;
    for (const fs::path& file : files) {
        const fs::path output = dir / (std::to_string(index++) + ".png");
        const Outcome o = run("07_gltf_metallic_roughness", file, output, {"--no-ibl"});
        if (o.refused) {
            ++refused;
            continue;
        }
        ++drawn;
        EXPECT_GT(pixelsUnlikeCorner(readImage(output, 3)), 20u)
            << file << " drew nothing visible: " << o.render.run.err;
        const std::string text = readBytes(file);
        // (KHR_materials_pbrSpecularGlossiness is drawn: 07 and 08 share one shading path)
        for (const char* extension :
             {"KHR_materials_emissive_strength", "KHR_draco_mesh_compression"}) {
            const size_t required = text.find("extensionsRequired");
            if (required != std::string::npos &&
                text.find(extension, required) != std::string::npos &&
                text.find(extension, required) < text.find(']', required)) {
                const std::string& err = o.render.run.err;
                const size_t warning = err.find("which this renderer does not draw");
                EXPECT_TRUE(warning != std::string::npos &&
                            err.rfind(extension, warning) != std::string::npos)
                    << file << " requires " << extension << ": " << err;
            }
        }
    }
    std::printf("07 on the corpus: %d files drawn, %d refused in one line\n", drawn, refused);
    EXPECT_GT(drawn, 20);
}

// 07 draws the core material alone: a file whose materials use sample 10's extensions is drawn,
// with one note naming each extension and the material that uses it (the file's own JSON names
// material 'layers' for all seven; KHR_texture_transform, which 07 draws, is not named).
TEST(ModelFile, A07SaysWhichMaterialUsesWhatItDoesNotDraw) {
    const fs::path dir = testOutputDir("model_extensions_07");
    const Outcome o = run("07_gltf_metallic_roughness", writeMaterialExtensionsFile(dir),
                          dir / "extensions.png", {"--no-ibl"});
    ASSERT_FALSE(o.refused) << o.render.run.err;
    std::vector<std::string> notes;
    for (const std::string& line : o.render.run.errLines()) {
        if (line.find("(optional), not drawn") != std::string::npos) notes.push_back(line);
    }
    ASSERT_EQ(notes.size(), 1u) << o.render.run.err;
    std::string expected;
    for (const char* name :
         {"clearcoat", "sheen", "transmission", "volume", "ior", "specular", "emissive_strength"}) {
        expected += std::string(expected.empty() ? "" : ", ") + "KHR_materials_" + name +
                    " (material 'layers')";
    }
    EXPECT_NE(notes[0].find(": uses " + expected + " (optional), not drawn"), std::string::npos)
        << notes[0];
    EXPECT_EQ(notes[0].find("KHR_texture_transform"), std::string::npos) << notes[0];
}

// A file that requires an extension 07 does not draw is drawn without it, and the warning says
// so first, naming the file and the extension; the extensions it only uses are not named again in
// the note. (The same file as above, with KHR_materials_clearcoat required.)
TEST(ModelFile, A07WarnsOfARequiredExtensionItDrawsWithout) {
    const fs::path dir = testOutputDir("model_required_extension_07");
    const fs::path file = writeMaterialExtensionsFile(dir);
    std::string json = readBytes(file);
    const std::string asset = R"({"asset":{"version":"2.0"},)";
    ASSERT_EQ(json.rfind(asset, 0), 0u) << json.substr(0, 80);
    json.insert(asset.size(), R"("extensionsRequired":["KHR_materials_clearcoat"],)");
    const fs::path required = writeTextFile(dir, "required.gltf", json);
    const Outcome o =
        run("07_gltf_metallic_roughness", required, dir / "required.png", {"--no-ibl"});
    ASSERT_FALSE(o.refused) << o.render.run.err;
    const std::vector<std::string> lines = o.render.run.errLines();
    const auto warning = std::find_if(lines.begin(), lines.end(), [](const std::string& line) {
        return line.starts_with("warning: ");
    });
    ASSERT_NE(warning, lines.end()) << o.render.run.err;
    EXPECT_NE(warning->find("required.gltf: requires KHR_materials_clearcoat, which this renderer "
                            "does not draw; drawn without it"),
              std::string::npos)
        << *warning;
    int notes = 0;
    for (const std::string& line : lines) {
        if (line.find("(optional), not drawn") == std::string::npos) continue;
        ++notes;
        EXPECT_EQ(line.find("KHR_materials_clearcoat"), std::string::npos) << line;
        EXPECT_NE(line.find("KHR_materials_sheen"), std::string::npos) << line;
    }
    EXPECT_EQ(notes, 1) << "the note of the extensions only used\n" << o.render.run.err;
}

// 10 draws all seven of them: the same file, no note of an extension not drawn.
TEST(ModelFile, A10DrawsEveryMaterialExtensionItReads) {
    const fs::path dir = testOutputDir("model_extensions_10");
    const Outcome o = run("10_gltf_advanced_materials", writeMaterialExtensionsFile(dir),
                          dir / "extensions.png", {"--no-ibl"});
    ASSERT_FALSE(o.refused) << o.render.run.err;
    EXPECT_EQ(o.render.run.err.find("not drawn"), std::string::npos) << o.render.run.err;
}

}  // namespace
}  // namespace pbr::test
