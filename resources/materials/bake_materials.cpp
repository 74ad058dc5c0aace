// The recipe for the project's PBR material sets (run by the build; see README.md):
//   bake_materials OUT_DIR [--size N] [--set NAME] [--contact-sheet FILE.png]
// writes OUT_DIR/<set>/{albedo,normal,metallic,roughness,ao}.png for every set (or one).
#include <string>
#include <vector>

#include "app/options.h"
#include "base/error.h"
#include "materials.h"

int main(int argc, char** argv) try {
    const std::string usage =
        "usage: bake_materials OUT_DIR [--size N] [--set NAME] [--contact-sheet FILE.png]\n";
    std::string outDir, sheetPath;
    std::vector<std::string> names = pbr::materials::kSetNames;
    int size = 1024;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool hasValue = i + 1 < argc;
        if (arg == "--size" && hasValue) {
            size = pbr::parseIntFlag("--size", argv[++i], 16, 8192);
        } else if (arg == "--set" && hasValue) {
            names = {argv[++i]};
        } else if (arg == "--contact-sheet" && hasValue) {
            sheetPath = argv[++i];
        } else if (outDir.empty() && arg.rfind("--", 0) != 0) {
            outDir = arg;
        } else {
            throw pbr::UsageError("unexpected argument '" + arg + "'", usage);
        }
    }
    if (outDir.empty()) throw pbr::UsageError("no output folder", usage);
    std::vector<pbr::materials::MaterialSet> sets;
    for (const std::string& name : names) {
        sets.push_back(pbr::materials::bake(name, size));
        pbr::materials::write(sets.back(), outDir);
    }
    if (!sheetPath.empty()) {
        pbr::writePng(sheetPath, pbr::materials::contactSheet(sets, 128), pbr::PngEncoding::Small);
    }
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
