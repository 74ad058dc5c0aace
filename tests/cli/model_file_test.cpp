// 03 --model with broken files: Debian's assimp-testmodels corpus of bad glTF, and our own
// damaged copies. Each gives one line naming the file and the reason with a non-zero exit, or,
// where Assimp accepts the file, a sane render (exit 0, no GL error); never a crash or a hang.
#include <gtest/gtest.h>

#include <fstream>

#include "support/golden.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

const fs::path kGltf = "/usr/share/assimp/models/glTF2";

struct Outcome {
    SampleRender render;
    bool refused;
};

Outcome run(const fs::path& model, const fs::path& output) {
    Outcome o{
        renderSample("03_gltf_unlit", output, {"--model", model.string(), "--size", "160x90"}),
        false};
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

TEST(ModelFile, BrokenFilesFromAssimpsCorpus) {
    const fs::path dir = testOutputDir("model_broken_corpus");
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
        const Outcome o = run(kGltf / file, dir / (std::to_string(index++) + ".png"));
        if (mustRefuse)
            EXPECT_TRUE(o.refused) << file << " was drawn";
        else
            EXPECT_FALSE(o.refused) << file << ": " << o.render.run.err;
    }
}

TEST(ModelFile, DamagedCopies) {
    const fs::path dir = testOutputDir("model_damaged");
    const std::string glb = readBytes(kGltf / "BoxTextured-glTF-Binary/BoxTextured.glb");
    ASSERT_GT(glb.size(), 1000u);
    std::ofstream(dir / "truncated.glb", std::ios::binary) << glb.substr(0, glb.size() / 2);
    std::ofstream(dir / "empty.gltf").close();
    fs::copy_file(kGltf / "BoxTextured-glTF/CesiumLogoFlat.png", dir / "picture.gltf");
    for (const char* file : {"truncated.glb", "empty.gltf", "picture.gltf"}) {
        const Outcome o = run(dir / file, dir / (std::string(file) + ".png"));
        EXPECT_TRUE(o.refused) << file << " was drawn";
    }
    EXPECT_NE(run(dir / "empty.gltf", dir / "e.png").render.run.err.find("empty file"),
              std::string::npos);
    EXPECT_NE(run(dir / "nowhere.gltf", dir / "n.png").render.run.err.find("no such file"),
              std::string::npos);
}

}  // namespace
}  // namespace pbr::test
