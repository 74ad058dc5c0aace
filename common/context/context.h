#pragma once
// Where GL runs: a GLFW window, or an offscreen context made directly (no display needed).
// The App picks one; samples never see this file.
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace pbr {

// What the user did since the last poll (windowed only; offscreen contexts report nothing).
struct InputFrame {
    bool forward = false, backward = false, left = false, right = false;
    glm::vec2 mouseDelta{0.0f};  // pixels, y up
    glm::vec2 dragDelta{0.0f};   // the part of it made with the left mouse button held
    float scroll = 0.0f;
    glm::vec2 cursor{-1.0f};  // framebuffer pixels from the top-left; negative: unknown
    bool leftButton = false;  // held
    // Presses of the left button since the last frame: at a software GL's 1-3 frames a second, a
    // click (press and release) often falls between two frames, leftButton up at both.
    int leftPresses = 0;
    bool togglePanel = false;  // Tab
    bool screenshot = false;  // F12
    bool reload = false;      // R
    bool quit = false;        // Esc or the window's close button
};

class Context {
public:
    virtual ~Context() = default;
    virtual bool windowed() const = 0;
    virtual std::string backend() const = 0;  // "glfw", "osmesa"
    virtual glm::ivec2 framebufferSize() const = 0;
    virtual InputFrame pollInput() { return {}; }
    virtual void swapBuffers() {}
    virtual double seconds() const = 0;  // monotonic clock
    virtual void setVsync(bool) {}
    // The fly camera's mouse look: a hidden cursor kept in the window, or a free one.
    virtual void setCursorCaptured(bool) {}
    virtual void setClipboard(const std::string&) {}
};

// The common part of the offscreen backends: a fixed size, no input, a steady clock.
class OffscreenContext : public Context {
public:
    OffscreenContext(int width, int height) : width_(width), height_(height) {}
    bool windowed() const override { return false; }
    glm::ivec2 framebufferSize() const override { return {width_, height_}; }
    double seconds() const override {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    int width_, height_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// An offscreen context from `backend`, or "" for the first that works, in this order:
//   "osmesa"        Mesa's off-screen library: always software rendering (llvmpipe), so its
//                   pictures match the goldens on any machine;
//   "egl"           EGL without a window system: a GPU where a driver offers one, else Mesa's
//                   surfaceless platform (the only way on Mesa 25.1 and later, without OSMesa);
//   "egl-software"  EGL on Mesa's software rasterizer only (its software device, else the
//                   surfaceless platform if that renders in software): the goldens' EGL path on
//                   a machine with a GPU.
// `debug` asks for a debug context where the platform can make one (EGL; OSMesa has no such
// attribute), so that KHR_debug reports every error. Throws Error naming each backend's reason
// when none works.
std::unique_ptr<Context> createOffscreenContext(const std::string& backend, int width, int height,
                                                bool debug);

// Under LeakSanitizer: the process's leak check is made at exit before the GL driver's own exit
// handlers run, not after them (see context.cpp); elsewhere nothing. Called once a context of a
// driver exists (every backend does it; a second call does nothing).
void checkLeaksBeforeTheDriverExits();

// The offscreen backends this build has, in the automatic order; and those of them that always
// render in software (the ones the golden tests compare).
std::vector<std::string> offscreenBackends();
std::vector<std::string> softwareBackends();

// The single backends (each throws Error with its reason).
std::unique_ptr<Context> createOsMesaContext(int width, int height);
std::unique_ptr<Context> createEglContext(int width, int height, bool softwareOnly, bool debug);
// The browser build's only one, "webgl": the page's canvas, drawn into but never shown.
std::unique_ptr<Context> createWebGlContext(int width, int height);

// A GLFW window with a GL 3.3 core context (a debug context when `debug`). `captureCursor` hides
// the cursor and keeps it in the window (the fly camera's mouse look); without it the cursor is
// free and dragDelta reports the drags. Returns nullptr, with the reason in `whyNot`, when there
// is no display to open it on.
std::unique_ptr<Context> createGlfwContext(const std::string& title, int width, int height,
                                           bool debug, bool captureCursor, std::string& whyNot);

}  // namespace pbr
