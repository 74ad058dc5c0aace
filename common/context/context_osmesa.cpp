// Headless through OSMesa, created directly: Debian's GLFW 3.3 cannot make a context without an
// X display, even for its OSMesa context API, so this path does not use GLFW at all.
#include "gl/gl.h"  // glad first: it stands in for <GL/gl.h>, which osmesa.h would include

#ifndef GLAPI
#define GLAPI extern
#endif
#ifndef GLAPIENTRY
#define GLAPIENTRY
#endif
#include <GL/osmesa.h>

#include <vector>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif

#include "base/error.h"
#include "context/context.h"

namespace pbr {

namespace {

GLADapiproc osmesaProcAddress(const char* name) {
    // glad's own loader goes through libGL/GLX and finds nothing in an OSMesa context.
    return reinterpret_cast<GLADapiproc>(OSMesaGetProcAddress(name));
}

class OsMesaContext final : public OffscreenContext {
public:
    OsMesaContext(int width, int height) : OffscreenContext(width, height) {
        const int attributes[] = {
            OSMESA_FORMAT,
            OSMESA_RGBA,
            OSMESA_DEPTH_BITS,
            24,
            OSMESA_STENCIL_BITS,
            8,
            OSMESA_PROFILE,
            OSMESA_CORE_PROFILE,
            OSMESA_CONTEXT_MAJOR_VERSION,
            3,
            OSMESA_CONTEXT_MINOR_VERSION,
            3,
            0,
        };
        {
            // Mesa 22.3's OSMesa leaves a few blocks of each context it makes unfreed by
            // OSMesaDestroyContext (320 bytes in 3 blocks per process). Under LeakSanitizer the
            // allocations of this one call are left out of the leak check, rather than every
            // leak with libOSMesa on its stack suppressed (which would hide a leak of ours made
            // through any GL call too), and no leak report is symbolised at each exit (that
            // cost a seventh of a sample run under the sanitizers).
#if defined(__SANITIZE_ADDRESS__)
            const __lsan::ScopedDisabler mesasOwnLeak;
#endif
            context_ = OSMesaCreateContextAttribs(attributes, nullptr);
        }
        if (!context_) {
            throw Error(
                "osmesa: cannot create a GL 3.3 core context (OSMesaCreateContextAttribs failed)");
        }
        // We render into our own framebuffer objects; this buffer only has to exist.
        buffer_.resize(size_t(width) * size_t(height) * 4);
        if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
            OSMesaDestroyContext(context_);
            throw Error("osmesa: OSMesaMakeCurrent failed");
        }
        if (!gladLoadGL(osmesaProcAddress)) {
            OSMesaDestroyContext(context_);
            throw Error("osmesa: cannot load the OpenGL functions (gladLoadGL failed)");
        }
    }
    ~OsMesaContext() override {
        OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
        OSMesaDestroyContext(context_);
    }

    std::string backend() const override { return "osmesa"; }

private:
    OSMesaContext context_ = nullptr;
    std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<Context> createOsMesaContext(int width, int height) {
    return std::make_unique<OsMesaContext>(width, height);
}

}  // namespace pbr
