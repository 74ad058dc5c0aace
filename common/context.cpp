#include "context.h"

#include "error.h"

namespace pbr {

std::vector<std::string> offscreenBackends() {
    std::vector<std::string> backends;
#ifdef PBR_HAVE_OSMESA
    backends.push_back("osmesa");
#endif
#ifdef PBR_HAVE_EGL
    backends.push_back("egl");
#endif
    return backends;
}

namespace {
std::string builtInList() {
    std::string list;
    for (const std::string& name : offscreenBackends()) list += (list.empty() ? "" : ", ") + name;
    return list.empty() ? "none" : list;
}

std::unique_ptr<Context> createBackend(const std::string& backend, int width, int height) {
#ifdef PBR_HAVE_OSMESA
    if (backend == "osmesa") return createOsMesaContext(width, height);
#endif
#ifdef PBR_HAVE_EGL
    if (backend == "egl") return createEglContext(width, height);
#endif
    throw Error("--backend " + backend + ": not built into this binary (it has: " + builtInList() +
                ")");
}
}  // namespace

std::unique_ptr<Context> createOffscreenContext(const std::string& backend, int width, int height) {
    if (!backend.empty()) return createBackend(backend, width, height);
    std::string reasons;
    for (const std::string& candidate : offscreenBackends()) {
        try {
            return createBackend(candidate, width, height);
        } catch (const Error& e) {
            reasons += (reasons.empty() ? "" : "; ") + std::string(e.what());
        }
    }
    throw Error("no offscreen backend works: " + (reasons.empty() ? "none built in" : reasons));
}

}  // namespace pbr
