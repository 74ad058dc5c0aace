// Which renderer `--backend egl` reaches on this machine, shared by the gpu tests and their
// fixture (tests/gpu/probe_fixture.cpp), which finds it once for a whole ctest run.
#pragma once

#include <filesystem>
#include <string>

#include "support/build_paths.h"
#include "support/golden.h"

namespace pbr::test {

// Where the fixture keeps the renderer while a ctest run lasts (removed at its end).
inline std::filesystem::path eglProbeFile() {
    return std::filesystem::path(PBR_PATH(PBR_TEST_OUTPUT_DIR)) / "gpu" / "egl_renderer.txt";
}

// Draws 16 x 16 pixels through `--backend egl` into `dir`: the GL_RENDERER string, or "" when
// there is no EGL context here.
inline std::string probeEglRenderer(const std::filesystem::path& dir) {
    const SampleRender probe =
        renderSample("01_lighting", dir / "probe.png", {"--backend", "egl", "--size", "16x16"});
    return probe.run.exitCode == 0 ? probe.renderer : std::string();
}

}  // namespace pbr::test
