#include "context/web.h"

#ifdef PBR_WEBGL
#include <emscripten.h>

#include <string>

#include "base/paths.h"

// JavaScript of the page: Module.pbrHandOver (web/shell.html) turns the bytes into a link and
// into text a test can read.
EM_JS(void, pbr_hand_over, (const char* name, const unsigned char* bytes, int size), {
    const data = HEAPU8.slice(bytes, bytes + size);
    if (Module["pbrHandOver"]) Module["pbrHandOver"](UTF8ToString(name), data);
});

// An import the build marks as one that suspends the wasm (-sASYNCIFY_IMPORTS).
EM_ASYNC_JS(void, pbr_wait_for_animation_frame, (), {
    await new Promise(function(resolve) { requestAnimationFrame(function() { resolve(); }); });
});

namespace pbr::web {

void handOver(const std::filesystem::path& path) {
    const std::string bytes = readTextFile(path);
    pbr_hand_over(path.filename().string().c_str(),
                  reinterpret_cast<const unsigned char*>(bytes.data()), int(bytes.size()));
}

namespace {
bool waited = false;  // main() has given the browser a turn: it ends asynchronously
int exitCode = 0;
}  // namespace

void waitForNextFrame() {
    waited = true;
    pbr_wait_for_animation_frame();
}

void exitWithAfterMain(int code) {
    if (!waited) return;  // main() returns synchronously, and the page sees its code
    exitCode = code;
    emscripten_async_call([](void*) { emscripten_force_exit(exitCode); }, nullptr, 0);
}

}  // namespace pbr::web
#endif
