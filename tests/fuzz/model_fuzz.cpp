// A user's glTF file through the whole native loader (gltf/model.h, loadModel: our container,
// JSON and structure checks, Assimp, our checks of what Assimp made): the input is written to a
// file of this process's own (.glb when it starts with the GLB magic, else .gltf) and loaded. It
// either gives a Model that keeps loadModel's promises (triangles, indices and materials in range,
// finite positions, normals, bounds and lights), or is refused in one line naming the file.
// Assimp is Debian's and not instrumented: each crash inside it that the fuzzing found is refused
// before Assimp reads the file, by gltfStructureError (its inputs are in regressions/model).
#include <unistd.h>

#include <fstream>

#include "base/paths.h"
#include "fuzz_check.h"
#include "gltf/model.h"

namespace pbr::fuzz {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

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

void expectDrawable(const Model& model) {
    expect(!model.primitives.empty(), "triangles to draw");
    expect(finite(model.boundsMin) && finite(model.boundsMax), "finite bounds");
    for (const PunctualLight& light : model.lights) {
        expect(finite(light.position) && finite(light.direction) && finite(light.color),
               "a light's place, direction and colour are finite");
    }
    for (const ModelPrimitive& p : model.primitives) {
        expect(p.material >= 0 && size_t(p.material) < model.materials.size(),
               "a primitive's material is in the model");
        const size_t n = p.mesh.positions.size();
        expect(p.mesh.normals.size() == n, "a normal a vertex");
        for (const glm::vec3& position : p.mesh.positions)
            expect(finite(position), "finite positions");
        for (const glm::vec3& normal : p.mesh.normals) expect(finite(normal), "finite normals");
        for (const std::uint32_t index : p.mesh.indices) expect(index < n, "indices in range");
    }
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
    fuzz::expectDrawable(model);
    return 0;
}
