// Which file of a material folder is which map (files/material_folder.h): the folder's file
// names, one a line, either give one file for each required map, each the one file of the folder
// named for it, or are refused in one line naming the folder.
#include <algorithm>
#include <map>

#include "files/material_folder.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace pbr;
    namespace fs = std::filesystem;
    const fs::path dir = "fuzz-material";
    std::vector<fs::path> names;
    std::map<std::string, int> filesOf;  // map -> how many names stand for it
    for (const std::string& name : fuzz::split(fuzz::bytesOf(data, size), '\n')) {
        names.emplace_back(name);
        if (const std::optional<std::string> map = materialMapOf(names.back())) {
            static const std::vector<std::string> kMaps = {
                "albedo", "normal", "normal-directx", "metallic", "roughness", "ao"};
            fuzz::expect(std::find(kMaps.begin(), kMaps.end(), *map) != kMaps.end(),
                         "a map is one of the six");
            ++filesOf[*map];
        }
    }
    MaterialFiles files;
    if (!fuzz::reads(dir.string(), [&] { files = materialFilesOf(dir, names); })) return 0;
    // A chosen file is dir / one of the names, the only one standing for its map.
    auto chosen = [&](const fs::path& file, const std::string& map) {
        fuzz::expect(std::any_of(names.begin(), names.end(),
                                 [&](const fs::path& name) { return dir / name == file; }),
                     "the " + map + " map is one of the folder's files");
        fuzz::expect(materialMapOf(file) == map, "the " + map + " map is named for it");
        fuzz::expect(filesOf[map] == 1, "the " + map + " map is the only file named for it");
    };
    chosen(files.albedo, "albedo");
    chosen(files.normal,
           files.normalConvention == NormalConvention::OpenGL ? "normal" : "normal-directx");
    fuzz::expect(files.normalConvention == NormalConvention::OpenGL || filesOf["normal"] == 0,
                 "an OpenGL normal map wins over a DirectX one");
    chosen(files.metallic, "metallic");
    chosen(files.roughness, "roughness");
    if (files.ao) chosen(*files.ao, "ao");
    fuzz::expect(files.ao.has_value() == (filesOf["ao"] == 1), "ao taken when there is one");
    return 0;
}
