// Headless through EGL, with no window system: the path for distributions whose Mesa (25.1 and
// later) no longer ships OSMesa, and for machines with a GPU driver.
//
// Display choice: a hardware device through EGL_EXT_platform_device when a driver offers one
// (NVIDIA's, or Mesa's on a machine with a render node); otherwise Mesa's surfaceless platform
// (EGL_MESA_platform_surfaceless, llvmpipe when there is no GPU); otherwise Mesa's software
// device. The context is made current without a surface (EGL_KHR_surfaceless_context), or on a
// 1x1 pbuffer where that extension is missing: the App draws into its own framebuffers anyway.
#include "gl/gl.h"  // glad first

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <vector>

#include "base/error.h"
#include "context/context.h"

#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>
#include <link.h>
#endif

namespace pbr {

namespace {

// LeakSanitizer names a leak's frames by the libraries still mapped at exit. Mesa unloads its DRI
// driver in eglTerminate, so the driver's own leaks would show as unnamed frames that no narrow
// suppression can match. In sanitizer builds, keep every loaded DRI driver mapped until exit.
void keepDriDriversLoaded() {
#if defined(__SANITIZE_ADDRESS__)
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void*) {
            if (info->dlpi_name && std::strstr(info->dlpi_name, "/dri/")) {
                dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
            }
            return 0;
        },
        nullptr);
#endif
}

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const size_t length = std::strlen(name);
    for (const char* at = std::strstr(list, name); at; at = std::strstr(at + 1, name)) {
        const bool startOk = at == list || at[-1] == ' ';
        const bool endOk = at[length] == ' ' || at[length] == '\0';
        if (startOk && endOk) return true;
    }
    return false;
}

GLADapiproc eglProcAddress(const char* name) {
    return reinterpret_cast<GLADapiproc>(eglGetProcAddress(name));
}

std::string eglErrorText() {
    char text[32];
    std::snprintf(text, sizeof text, "EGL error 0x%04X", unsigned(eglGetError()));
    return text;
}

struct ChosenDisplay {
    EGLDisplay display = EGL_NO_DISPLAY;
    std::string platform;
};

// The display to render on. `softwareOnly`: Mesa's software device, else the surfaceless
// platform (checked to render in software once the context exists); never a GPU device.
ChosenDisplay chooseDisplay(bool softwareOnly) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) return {eglGetDisplay(EGL_DEFAULT_DISPLAY), "default"};

    EGLDeviceEXT softwareDevice = nullptr;
    if (hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
        auto queryDevices =
            reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        auto queryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
            eglGetProcAddress("eglQueryDeviceStringEXT"));
        EGLint count = 0;
        if (queryDevices && queryDeviceString && queryDevices(0, nullptr, &count) && count > 0) {
            std::vector<EGLDeviceEXT> devices(size_t(count), nullptr);
            queryDevices(count, devices.data(), &count);
            for (EGLDeviceEXT device : devices) {
                const char* extensions = queryDeviceString(device, EGL_EXTENSIONS);
                if (hasExtension(extensions, "EGL_MESA_device_software")) {
                    if (!softwareDevice) softwareDevice = device;
                    continue;
                }
                if (softwareOnly) continue;
                EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
                if (display != EGL_NO_DISPLAY) return {display, "device"};
            }
        }
    }
    if (softwareOnly && softwareDevice) {
        EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, softwareDevice, nullptr);
        if (display != EGL_NO_DISPLAY) return {display, "software-device"};
    }
    if (hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay display =
            getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display != EGL_NO_DISPLAY) return {display, "surfaceless"};
    }
    if (softwareDevice) {
        EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, softwareDevice, nullptr);
        if (display != EGL_NO_DISPLAY) return {display, "software-device"};
    }
    if (softwareOnly) return {EGL_NO_DISPLAY, "software"};
    return {eglGetDisplay(EGL_DEFAULT_DISPLAY), "default"};
}

class EglContext final : public OffscreenContext {
public:
    EglContext(int width, int height, bool softwareOnly, bool debug)
        : OffscreenContext(width, height), softwareOnly_(softwareOnly) {
        ChosenDisplay chosen = chooseDisplay(softwareOnly);
        display_ = chosen.display;
        platform_ = chosen.platform;
        if (display_ == EGL_NO_DISPLAY) {
            throw Error(prefix() + (softwareOnly ? "no software display (" : "no display (") +
                        eglErrorText() + ")");
        }
        EGLint major = 0, minor = 0;
        if (!eglInitialize(display_, &major, &minor)) {
            throw Error(prefix() + "cannot initialise the " + platform_ + " display (" +
                        eglErrorText() + ")");
        }
        keepDriDriversLoaded();
        try {
            create(major * 10 + minor >= 15, debug);
        } catch (...) {
            release();
            throw;
        }
    }
    ~EglContext() override { release(); }

    // What every message starts with: the backend asked for.
    std::string prefix() const { return softwareOnly_ ? "egl-software: " : "egl: "; }

    std::string backend() const override {
        return std::string(softwareOnly_ ? "egl-software/" : "egl/") + platform_;
    }

private:
    void create(bool egl15, bool debug) {
        if (!eglBindAPI(EGL_OPENGL_API)) throw Error(prefix() + "desktop OpenGL is not available");
        const EGLint configAttributes[] = {
            EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE,
        };
        EGLConfig config = nullptr;
        EGLint configs = 0;
        if (!eglChooseConfig(display_, configAttributes, &config, 1, &configs) || configs < 1) {
            throw Error(prefix() + "no config for desktop OpenGL on the " + platform_ + " display");
        }
        std::vector<EGLint> contextAttributes = {
            EGL_CONTEXT_MAJOR_VERSION,       3,
            EGL_CONTEXT_MINOR_VERSION,       3,
            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
        };
        if (debug) {
            // A debug context, so that KHR_debug reports every error (EGL 1.5's attribute, else
            // EGL_KHR_create_context's flag); without either, an ordinary context.
            if (egl15) {
                contextAttributes.insert(contextAttributes.end(),
                                         {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE});
            } else if (hasExtension(eglQueryString(display_, EGL_EXTENSIONS),
                                    "EGL_KHR_create_context")) {
                contextAttributes.insert(contextAttributes.end(),
                                         {EGL_CONTEXT_FLAGS_KHR, EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR});
            }
        }
        contextAttributes.push_back(EGL_NONE);
        context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, contextAttributes.data());
        if (context_ == EGL_NO_CONTEXT) {
            throw Error(prefix() + "cannot create a GL 3.3 core context (" + eglErrorText() + ")");
        }
        if (!hasExtension(eglQueryString(display_, EGL_EXTENSIONS),
                          "EGL_KHR_surfaceless_context")) {
            const EGLint pbufferAttributes[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
            surface_ = eglCreatePbufferSurface(display_, config, pbufferAttributes);
            if (surface_ == EGL_NO_SURFACE)
                throw Error(prefix() + "cannot create a pbuffer (" + eglErrorText() + ")");
        }
        if (!eglMakeCurrent(display_, surface_, surface_, context_)) {
            throw Error(prefix() + "cannot make the context current (" + eglErrorText() + ")");
        }
        if (!gladLoadGL(eglProcAddress))
            throw Error(prefix() + "cannot load the OpenGL functions (gladLoadGL failed)");
        if (softwareOnly_) {
            // The surfaceless platform renders on a GPU when it finds one: not what was asked.
            const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
            const std::string name = renderer ? renderer : "unknown";
            if (name.find("llvmpipe") == std::string::npos &&
                name.find("softpipe") == std::string::npos) {
                throw Error(prefix() + "the " + platform_ + " display renders on " + name +
                            ", not in software, and Mesa's software device is missing");
            }
        }
    }

    void release() {
        if (display_ == EGL_NO_DISPLAY) return;
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
        if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
        eglTerminate(display_);
        eglReleaseThread();
        display_ = EGL_NO_DISPLAY;
    }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
    EGLSurface surface_ = EGL_NO_SURFACE;
    std::string platform_;
    bool softwareOnly_ = false;
};

}  // namespace

std::unique_ptr<Context> createEglContext(int width, int height, bool softwareOnly, bool debug) {
    return std::make_unique<EglContext>(width, height, softwareOnly, debug);
}

}  // namespace pbr
