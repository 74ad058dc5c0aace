// The browser build's loadModel (model.h): a page has no Assimp (Debian has none for
// WebAssembly) and no second set of glTF rules, so it reads the compact form of the Model the
// native loader made (model_pack.h), which the build packs into the page beside where the glTF
// file would be. Any other --model is refused in one line, naming what the page carries.
#include <algorithm>

#include "base/error.h"
#include "base/paths.h"
#include "gltf/model.h"
#include "gltf/model_pack.h"

namespace pbr {

namespace fs = std::filesystem;

Model loadModel(const fs::path& file) {
    std::error_code ec;
    std::vector<fs::path> carried;  // the glTF files the page has packs of
    for (const auto& entry : fs::directory_iterator(modelDir(), ec)) {
        const std::string name = entry.path().filename().string();
        if (name.ends_with(".pbrmodel"))
            carried.push_back(modelDir() / name.substr(0, name.size() - 9));
    }
    std::sort(carried.begin(), carried.end());
    // The path itself, or a carried model of that file name (--model=pbr_showcase.gltf).
    fs::path model = file;
    if (!fs::exists(packedModelPath(model), ec)) {
        const auto named = std::find_if(carried.begin(), carried.end(), [&](const fs::path& c) {
            return c.filename() == file.filename();
        });
        if (named == carried.end()) {
            std::string list;
            for (const fs::path& c : carried) list += (list.empty() ? "" : ", ") + c.string();
            throw UsageError("--model: " + file.string() +
                                 ": a page draws only the models the build packed into it (no "
                                 "glTF reader in the browser): " +
                                 (list.empty() ? "none" : list),
                             "");
        }
        model = *named;
    }
    const fs::path pack = packedModelPath(model);
    return decodeModelPack(readTextFile(pack), model, displayPath(pack));
}

}  // namespace pbr
