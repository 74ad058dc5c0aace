// The gpu tests' bookends, run by ctest as fixtures around them: one probe of `--backend egl`
// for the whole run instead of one a test (55 probes took about 18 test-seconds on software EGL,
// where every test is then skipped):
//   gpu_probe find    writes the renderer (or nothing: no EGL) to eglProbeFile()
//   gpu_probe clear   removes it, so that a gpu test run by hand probes for itself
#include <cstdio>
#include <filesystem>
#include <string>

#include "base/output.h"
#include "gpu/egl_probe.h"
#include "support/process.h"

namespace fs = std::filesystem;

int main(int argc, char** argv) try {
    const std::string mode = argc > 1 ? argv[1] : "";
    const fs::path file = pbr::test::eglProbeFile();
    if (mode == "clear") {
        fs::remove(file);
        return 0;
    }
    if (mode != "find") {
        std::fprintf(stderr, "usage: gpu_probe find|clear\n");
        return 2;
    }
    const std::string renderer =
        pbr::test::probeEglRenderer(pbr::test::testOutputDir("gpu_probe"));
    fs::create_directories(file.parent_path());
    pbr::writeFileAtomically(file, renderer);
    std::printf("--backend egl: %s\n", renderer.empty() ? "no context" : renderer.c_str());
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "gpu_probe: error: %s\n", e.what());
    return 1;
}
