// A user's glTF file through the whole native loader (gltf/model.h, loadModel: our container,
// JSON and structure checks, Assimp, our checks of what Assimp made): the input is written to a
// file of this process's own (.glb when it starts with the GLB magic, else .gltf) and loaded. It
// either gives a Model that keeps loadModel's promises (model_promises.h, and a normal a vertex),
// or is refused in one line naming the file.
// Assimp is Debian's and not instrumented: each crash inside it that the fuzzing found is refused
// before Assimp reads the file, by gltfStructureError (its inputs are in regressions/model).
#include <unistd.h>

#include <fstream>

#include "base/paths.h"
#include "model_promises.h"

namespace pbr::fuzz {

// A folder of this process's own (libFuzzer's -jobs run several side by side), empty but for
// the model, so that the URIs a file names resolve to nothing of anyone else's; removed at exit.
struct ModelFolder {
    std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("pbr-fuzz-model-" + std::to_string(getpid()));
    ModelFolder() { std::filesystem::create_directories(dir); }
    ~ModelFolder() {
        std::error_code ec;
        std::filesystem::remove_all(dir, ec);
    }
};

std::filesystem::path modelFolder() {
    static const ModelFolder folder;
    return folder.dir;
}

}  // namespace pbr::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace pbr;
    const std::string_view bytes = fuzz::bytesOf(data, size);
    const std::filesystem::path file =
        fuzz::modelFolder() / (bytes.substr(0, 4) == "glTF" ? "model.glb" : "model.gltf");
    std::ofstream(file, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    Model model;
    const bool loaded = fuzz::reads(displayPath(file), [&] { model = loadModel(file); });
    std::filesystem::remove(file);
    if (!loaded) return 0;
    fuzz::expectModelPromises(model);
    fuzz::expect(std::all_of(model.primitives.begin(), model.primitives.end(),
                             [](const ModelPrimitive& p) {
                                 return p.mesh.normals.size() == p.mesh.positions.size();
                             }),
                 "a normal a vertex (flat ones where the file has none)");
    return 0;
}
