#include "context/context.h"

#include <cstdlib>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif

#include "base/error.h"
#include "gl/gl.h"

namespace pbr {

std::vector<std::string> offscreenBackends() {
    std::vector<std::string> backends;
#ifdef PBR_WEBGL
    backends.push_back("webgl");
#endif
#ifdef PBR_HAVE_OSMESA
    backends.push_back("osmesa");
#endif
#ifdef PBR_HAVE_EGL
    backends.push_back("egl");
    backends.push_back("egl-software");
#endif
    return backends;
}

std::vector<std::string> softwareBackends() {
    std::vector<std::string> backends;
    for (const std::string& name : offscreenBackends()) {
        if (name != "egl") backends.push_back(name);
    }
    return backends;
}

void checkLeaksBeforeTheDriverExits() {
#if defined(__SANITIZE_ADDRESS__)
    // Mesa tears itself down in exit handlers it registers when its first context is made, and
    // one of them (util_queue's) stops the shader cache's writer threads with their queued jobs
    // still unwritten and unfreed: on a cold cache, when the low-priority writer has not caught
    // up by exit, each such job (a copy of a compiled shader, tens of kB) would be reported as a
    // leak of the program's, at random (docs/testing.md). Exit handlers run last registered
    // first, so a leak check registered now runs before Mesa's teardown: every block Mesa still
    // holds is reachable from its globals, and every block of ours not freed by then is not.
    // LeakSanitizer checks once a process: its own check at exit then does nothing.
    static const bool registered = std::atexit([] { __lsan_do_leak_check(); }) == 0;
    (void)registered;
#endif
}

namespace {
std::string builtInList() {
    std::string list;
    for (const std::string& name : offscreenBackends()) list += (list.empty() ? "" : ", ") + name;
    return list.empty() ? "none" : list;
}

std::unique_ptr<Context> createBackend(const std::string& backend, int width, int height,
                                       bool debug) {
    (void)width, (void)height, (void)debug;  // unused when no backend is built in
#ifdef PBR_WEBGL
    if (backend == "webgl") return createWebGlContext(width, height);
#endif
#ifdef PBR_HAVE_OSMESA
    if (backend == "osmesa") return createOsMesaContext(width, height);
#endif
#ifdef PBR_HAVE_EGL
    if (backend == "egl") return createEglContext(width, height, false, debug);
    if (backend == "egl-software") return createEglContext(width, height, true, debug);
#endif
    throw Error("--backend " + backend + ": not built into this binary (it has: " + builtInList() +
                ")");
}
}  // namespace

std::unique_ptr<Context> createOffscreenContext(const std::string& backend, int width, int height,
                                                bool debug) {
    if (!backend.empty()) {
        std::unique_ptr<Context> context = createBackend(backend, width, height, debug);
        checkLeaksBeforeTheDriverExits();
        return context;
    }
    std::string reasons;
    for (const std::string& candidate : offscreenBackends()) {
        if (candidate == "egl-software") continue;  // "egl" covers it when nothing else works
        try {
            std::unique_ptr<Context> context = createBackend(candidate, width, height, debug);
            checkLeaksBeforeTheDriverExits();
            return context;
        } catch (const Error& e) {
            reasons += (reasons.empty() ? "" : "; ") + std::string(e.what());
        }
    }
    if (offscreenBackends().empty()) {
        throw Error(
            "--headless: this build has no offscreen backend (built without OSMesa and EGL)");
    }
    throw Error("no offscreen backend works: " + reasons);
}

}  // namespace pbr
