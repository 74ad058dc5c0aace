// A window through GLFW 3.3: core profile 3.3 (forward-compatible on macOS), resizable, vsync.
// Multisampling happens in the App's own framebuffer, so the window's needs none.
//
// In the browser build the same code drives emscripten's GLFW: the "window" is the page's
// canvas with a WebGL 2 context, every swap waits for the browser's next animation frame, and
// the same canvas serves the offscreen backend ("webgl": nothing shown, the frame handed to the
// page; see createWebGlContext).
#ifdef _WIN32
#include <windows.h>  // (before GL's and GLFW's headers, which define APIENTRY where it is not)
#endif
#include "gl/gl.h"  // glad provides the GL declarations; GLFW must not include its own
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>

#include "base/error.h"
#include "base/paths.h"
#include "context/context.h"
#include "context/web.h"

namespace pbr {

namespace {

std::string lastGlfwError;

void onGlfwError(int, const char* description) {
    lastGlfwError = description ? description : "";
}

#ifdef _WIN32
// GLFW 3.3 loads an XInput DLL at glfwInit (for joysticks) and frees it at glfwTerminate. Wine
// 8's XInput stops its device thread when it is unloaded so, and is unmapped before that thread
// has left the DLL's code: a page fault at exit, after the picture is written, in about 1 run in
// 100 under Wine (docs/building.md). Pinned, the DLL stays until the process ends, when its
// thread ends with the process; on Windows it is a system DLL, kept loaded anyway.
void keepXInputLoaded() {
    for (const wchar_t* name : {L"xinput1_4.dll", L"xinput1_3.dll", L"xinput9_1_0.dll",
                                L"xinput1_2.dll", L"xinput1_1.dll"}) {
        HMODULE module = nullptr;
        if (GetModuleHandleExW(GET_MODULE_HANDLE_EX_FLAG_PIN, name, &module)) return;
    }
}
#endif

class GlfwContext final : public Context {
public:
    GlfwContext(GLFWwindow* window, bool captureCursor, bool windowed = true)
        : window_(window), windowed_(windowed) {
        glfwSetWindowUserPointer(window_, this);
        setCursorCaptured(captureCursor);
        glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
            static_cast<GlfwContext*>(glfwGetWindowUserPointer(w))->onCursor(x, y);
        });
        glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
            if (button == GLFW_MOUSE_BUTTON_LEFT && action == GLFW_PRESS)
                ++static_cast<GlfwContext*>(glfwGetWindowUserPointer(w))->pending_.leftPresses;
        });
        glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double y) {
            static_cast<GlfwContext*>(glfwGetWindowUserPointer(w))->pending_.scroll += float(y);
        });
        glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
            if (action != GLFW_PRESS) return;
            InputFrame& pending = static_cast<GlfwContext*>(glfwGetWindowUserPointer(w))->pending_;
            if (key == GLFW_KEY_F12) pending.screenshot = true;
            if (key == GLFW_KEY_R) pending.reload = true;
            if (key == GLFW_KEY_TAB) pending.togglePanel = true;
            if (key == GLFW_KEY_ESCAPE) pending.quit = true;
        });
    }
    ~GlfwContext() override {
        glfwDestroyWindow(window_);
        glfwTerminate();
    }

    bool windowed() const override { return windowed_; }
    std::string backend() const override { return windowed_ ? "glfw" : "webgl"; }
    glm::ivec2 framebufferSize() const override {
        int width = 0, height = 0;
        glfwGetFramebufferSize(window_, &width, &height);
        return {width, height};
    }
    InputFrame pollInput() override {
        glfwPollEvents();
        InputFrame frame = pending_;
        pending_ = {};
        frame.forward = glfwGetKey(window_, GLFW_KEY_W) == GLFW_PRESS;
        frame.backward = glfwGetKey(window_, GLFW_KEY_S) == GLFW_PRESS;
        frame.left = glfwGetKey(window_, GLFW_KEY_A) == GLFW_PRESS;
        frame.right = glfwGetKey(window_, GLFW_KEY_D) == GLFW_PRESS;
        frame.quit = frame.quit || glfwWindowShouldClose(window_);
        frame.leftButton = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        if (!captured_) {
            // The cursor in framebuffer pixels (a window's coordinates may be scaled on HiDPI).
            double x = 0.0, y = 0.0;
            int windowWidth = 0, windowHeight = 0;
            glfwGetCursorPos(window_, &x, &y);
            glfwGetWindowSize(window_, &windowWidth, &windowHeight);
            const glm::ivec2 framebuffer = framebufferSize();
            if (windowWidth > 0 && windowHeight > 0 && x >= 0.0 && y >= 0.0) {
                frame.cursor = {float(x) * float(framebuffer.x) / float(windowWidth),
                                float(y) * float(framebuffer.y) / float(windowHeight)};
            }
        }
        return frame;
    }
    void setCursorCaptured(bool captured) override {
        if (captured == captured_) return;
        captured_ = captured;
        // A page asks for pointer lock on a click on the picture (web/shell.html), as browsers
        // require; emscripten's GLFW would ask at once, and be refused.
        if (kWebGl) return;
        glfwSetInputMode(window_, GLFW_CURSOR, captured ? GLFW_CURSOR_DISABLED : GLFW_CURSOR_NORMAL);
        haveCursor_ = false;  // the next cursor event sets a new reference: the view does not jump
    }
    void setClipboard(const std::string& text) override {
        glfwSetClipboardString(window_, text.c_str());
    }
    void swapBuffers() override {
        glfwSwapBuffers(window_);
        web::waitForNextFrame();  // the browser shows the canvas, and input arrives
    }
    double seconds() const override { return glfwGetTime(); }
    void setVsync(bool on) override {
        if (!kWebGl) glfwSwapInterval(on ? 1 : 0);  // a page always draws at the display's rate
    }

private:
    void onCursor(double x, double y) {
        if (!haveCursor_) {
            // The first event only sets the reference, so the view does not jump.
            haveCursor_ = true;
        } else {
            const glm::vec2 delta(float(x - lastX_), float(lastY_ - y));
            pending_.mouseDelta += delta;
            if (glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS)
                pending_.dragDelta += delta;
        }
        lastX_ = x;
        lastY_ = y;
    }

    GLFWwindow* window_;
    bool windowed_;
    InputFrame pending_;
    bool captured_ = false;
    bool haveCursor_ = false;
    double lastX_ = 0.0, lastY_ = 0.0;
};

}  // namespace

namespace {

GLFWwindow* openWindow(const std::string& title, int width, int height, bool debug,
                       std::string& whyNot) {
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) {
        whyNot = "GLFW cannot start: " + lastGlfwError;
        return nullptr;
    }
#ifdef _WIN32
    keepXInputLoaded();  // the one of them GLFW loaded (it tries them in this order)
#endif
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, kWebGl ? 0 : 3);
    if (!kWebGl) glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
#ifdef __APPLE__
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
#endif
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_SAMPLES, 0);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window) {
        whyNot = std::string(kWebGl ? "cannot make a WebGL 2 context: "
                                    : "cannot open a GL 3.3 core window: ") +
                 lastGlfwError;
        glfwTerminate();
        return nullptr;
    }
    glfwMakeContextCurrent(window);
#ifdef PBR_WEBGL
    const int loaded = gladLoadGLES2(glfwGetProcAddress);
#else
    const int loaded = gladLoadGL(glfwGetProcAddress);
#endif
    if (!loaded) {
        glfwDestroyWindow(window);
        glfwTerminate();
        throw Error("glfw: cannot load the OpenGL functions (glad found no GL)");
    }
    if (!kWebGl) glfwSwapInterval(1);
    return window;
}

}  // namespace

std::unique_ptr<Context> createGlfwContext(const std::string& title, int width, int height,
                                           bool debug, bool captureCursor, std::string& whyNot) {
    // X11 and Wayland need a display named in the environment: without one, the sample renders
    // offscreen instead. Windows and macOS always have their desktop (a Windows build that
    // asked, as it once did, never opened a window there), and a page its canvas.
    if (kDisplayVariables && !kWebGl) {
        const char* x11 = std::getenv("DISPLAY");
        const char* wayland = std::getenv("WAYLAND_DISPLAY");
        if ((!x11 || !*x11) && (!wayland || !*wayland)) {
            whyNot = "no display (DISPLAY and WAYLAND_DISPLAY are unset)";
            return nullptr;
        }
    }
    GLFWwindow* window = openWindow(title, width, height, debug, whyNot);
    if (!window) return nullptr;
    checkLeaksBeforeTheDriverExits();
    return std::make_unique<GlfwContext>(window, captureCursor);
}

#ifdef PBR_WEBGL
std::unique_ptr<Context> createWebGlContext(int width, int height) {
    std::string whyNot;
    GLFWwindow* window = openWindow("", width, height, false, whyNot);
    if (!window) throw Error("webgl: " + whyNot);
    return std::make_unique<GlfwContext>(window, false, false);
}
#endif

}  // namespace pbr
