// A program of the browser build (samples/CMakeLists.txt: one for the pages of each layer of
// common/): each of its samples' own main.cpp is compiled into it as it is, its main() renamed
// pbr_main_NAME, and this main() runs the sample its page names. The page sets argv[0] to the
// sample's name (Module.thisProgram, written into each page by web/embed.py), as a native
// sample's argv[0] is its own name.
#include <cstdio>
#include <string_view>

#include "context/web.h"

#ifndef PBR_WEB_SAMPLES
#error "PBR_WEB_SAMPLES lists the samples: X(01_lighting) X(02_lighting_textured) ..."
#endif

#define X(name) int pbr_main_##name(int argc, char** argv);
PBR_WEB_SAMPLES
#undef X

// The sample's exit code reaches the page however its main() returned: directly, or (once it has
// given the browser a turn, which every run that draws does) through web::exitWithAfterMain,
// since emscripten drops the return value of a main() that resumed.
int exitWith(int code) {
    pbr::web::exitWithAfterMain(code);
    return code;
}

int main(int argc, char** argv) {
    const std::string_view program = argc > 0 ? argv[0] : "";
#define X(name) \
    if (program == #name) return exitWith(pbr_main_##name(argc, argv));
    PBR_WEB_SAMPLES
#undef X
    std::fprintf(stderr, "error: no sample named '%.*s' in this page's program\n",
                 int(program.size()), program.data());
    return 2;
}
