// The golden report's bookends, run by ctest as fixtures around the golden tests:
//   golden_report reset   empties the report folder before the run
//   golden_report check   after the run: the page exists, has entries, and every picture it
//                         shows exists; prints the page's path. A run that compared no golden
//                         (a subset such as `ctest -R Web.KeysAndMouse`, whose tests share the
//                         fixture) has no entries folder, which the first comparison makes
//                         before it writes anything: said, and not a failure
#include <cstdio>
#include <filesystem>
#include <string>

#include "base/paths.h"
#include "support/golden.h"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
    const std::string mode = argc > 1 ? argv[1] : "";
    const fs::path dir = pbr::test::goldenReportDir();
    if (mode == "reset") {
        fs::remove_all(dir);
        fs::create_directories(dir);
        return 0;
    }
    if (mode != "check") {
        std::fprintf(stderr, "usage: golden_report reset|check\n");
        return 2;
    }
    const fs::path page = pbr::test::goldenReportPage();
    std::error_code ec;
    if (!fs::exists(dir / "entries", ec) && !fs::exists(page, ec)) {
        std::printf("golden report: no golden picture was compared in this run\n");
        return 0;
    }
    std::string html;
    try {
        html = pbr::readTextFile(page);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: no golden report: %s\n", e.what());
        return 1;
    }
    int pictures = 0, missing = 0;
    const std::string marker = "<img src=\"";
    for (size_t at = html.find(marker); at != std::string::npos; at = html.find(marker, at + 1)) {
        const size_t start = at + marker.size();
        const std::string source = html.substr(start, html.find('"', start) - start);
        ++pictures;
        if (!fs::exists(dir / source)) {
            std::fprintf(stderr, "error: %s shows %s, which does not exist\n", page.c_str(),
                         source.c_str());
            ++missing;
        }
    }
    const bool hasEntries = html.find("<section class=") != std::string::npos;
    if (!hasEntries || pictures == 0)
        std::fprintf(stderr, "error: %s has no entries\n", page.c_str());
    std::printf("golden report: %s (%d pictures)\n", page.c_str(), pictures);
    return missing == 0 && hasEntries && pictures > 0 ? 0 : 1;
}
