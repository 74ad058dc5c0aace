#include "context/context.h"

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
    if (!backend.empty()) return createBackend(backend, width, height, debug);
    std::string reasons;
    for (const std::string& candidate : offscreenBackends()) {
        if (candidate == "egl-software") continue;  // "egl" covers it when nothing else works
        try {
            return createBackend(candidate, width, height, debug);
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
