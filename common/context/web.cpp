#include "context/web.h"

#ifdef PBR_WEBGL
#include <emscripten.h>

#include <string>

#include "base/paths.h"
#include "gl/gl.h"

// JavaScript of the page: Module.pbrHandOver (web/shell.html) turns the bytes into a link and
// into text a test can read.
EM_JS(void, pbr_hand_over, (const char* name, const unsigned char* bytes, int size), {
    const data = HEAPU8.slice(bytes, bytes + size);
    if (Module["pbrHandOver"]) Module["pbrHandOver"](UTF8ToString(name), data);
});

// An import the build marks as one that suspends the wasm (-sASYNCIFY_IMPORTS). The page may
// hold the program after a frame (Module.pbrFrameShown, web/shell.html: a test's screenshot).
EM_ASYNC_JS(void, pbr_wait_for_animation_frame, (), {
    await new Promise(function(resolve) { requestAnimationFrame(function() { resolve(); }); });
    if (Module["pbrFrameShown"]) await Module["pbrFrameShown"]();
});

// After a rendering update of the browser (an animation frame, then a task after it): what the
// page shows has been painted.
EM_ASYNC_JS(void, pbr_wait_for_paint, (), {
    await new Promise(function(resolve) {
        requestAnimationFrame(function() { setTimeout(resolve, 0); });
    });
});

// The header's status (Module.pbrStatus), and the first frame's mark (Module.pbrFirstFrame).
EM_JS(void, pbr_status, (const char* text), {
    if (Module["pbrStatus"]) Module["pbrStatus"](UTF8ToString(text));
});
// Whether the page's WebGL is drawn by a software rasterizer (the unmasked renderer's name).
EM_JS(int, pbr_software_webgl, (), {
    const info = GLctx && GLctx.getExtension("WEBGL_debug_renderer_info");
    const name = info ? String(GLctx.getParameter(info.UNMASKED_RENDERER_WEBGL)) : "";
    return /swiftshader|llvmpipe|software/i.test(name) ? 1 : 0;
});
EM_JS(void, pbr_first_frame_submitted, (), {
    if (Module["pbrFirstFrameSubmitted"]) Module["pbrFirstFrameSubmitted"]();
});
EM_JS(void, pbr_first_frame_drawn, (), {
    if (Module["pbrFirstFrame"]) Module["pbrFirstFrame"]();
});

// The header's mouse and keys line (web/shell.html's #pbr-hint).
EM_JS(void, pbr_mouse_hint, (const char* text), {
    var hint = document.getElementById("pbr-hint");
    if (hint) hint.textContent = UTF8ToString(text);
});

// The bar under the picture (Module.pbrShowFrame), and its buttons' presses (Module.pbrClock:
// 1 pause or run, 2 step).
EM_JS(void, pbr_show_frame, (double milliseconds, const char* command, int paused), {
    if (Module["pbrShowFrame"]) Module["pbrShowFrame"](milliseconds, UTF8ToString(command), paused);
});
EM_JS(void, pbr_show_caption, (const char* text, const char* ticks), {
    if (Module["pbrShowCaption"]) Module["pbrShowCaption"](UTF8ToString(text), UTF8ToString(ticks));
});
EM_JS(int, pbr_take_clock_presses, (), {
    var pressed = Module["pbrClock"] || 0;
    Module["pbrClock"] = 0;
    return pressed;
});

// The controls: Module.pbrDeclareFlags builds them; their changes queue up in the page as
// lines "name<TAB>1<TAB>value" (1: given, 0: a switch turned off), fetched once a frame.
EM_JS(void, pbr_declare_flags, (const char* json), {
    if (Module["pbrDeclareFlags"]) Module["pbrDeclareFlags"](JSON.parse(UTF8ToString(json)));
});
EM_JS(int, pbr_flag_changes_length, (), {
    Module["pbrChangeText"] = (Module["pbrFlagChanges"] || []).join("\n");
    Module["pbrFlagChanges"] = [];
    return lengthBytesUTF8(Module["pbrChangeText"]) + 1;
});
EM_JS(void, pbr_copy_flag_changes, (char* buffer, int size), {
    stringToUTF8(Module["pbrChangeText"], buffer, size);
});

// Labels: Module.pbrLabels collects the frame's; pbrShowLabels places them over the canvas.
EM_JS(void, pbr_label, (float x, float y, const char* text), {
    (Module["pbrLabels"] = Module["pbrLabels"] || []).push([x, y, UTF8ToString(text)]);
});
EM_JS(void, pbr_show_labels, (int width, int height), {
    if (Module["pbrShowLabels"]) Module["pbrShowLabels"](Module["pbrLabels"] || [], width, height);
    Module["pbrLabels"] = [];
});

namespace pbr::web {

void label(float x, float y, const std::string& text) {
    pbr_label(x, y, text.c_str());
}

void showLabels(int width, int height) {
    pbr_show_labels(width, height);
}

void declareFlags(const std::string& json) {
    pbr_declare_flags(json.c_str());
}

void mouseHint(const std::string& text) {
    pbr_mouse_hint(text.c_str());
}

void showFrame(double milliseconds, const std::string& commandLine, bool paused) {
    pbr_show_frame(milliseconds, commandLine.c_str(), paused ? 1 : 0);
}

void showCaption(const std::string& text, const std::vector<std::pair<float, std::string>>& ticks) {
    // "at value" pairs, ';' between them (a tick's text is a number)
    std::string list;
    for (const auto& [at, value] : ticks) {
        list += (list.empty() ? "" : ";") + std::to_string(at) + " " + value;
    }
    pbr_show_caption(text.c_str(), list.c_str());
}

ClockPresses takeClockPresses() {
    const int pressed = pbr_take_clock_presses();
    return {.pause = (pressed & 1) != 0, .step = (pressed & 2) != 0};
}

std::vector<FlagChange> takeFlagChanges() {
    const int size = pbr_flag_changes_length();
    if (size <= 1) return {};
    std::string text(size_t(size), '\0');
    pbr_copy_flag_changes(text.data(), size);
    text.resize(size_t(size - 1));
    std::vector<FlagChange> changes;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::string line = text.substr(start, end - start);
        const size_t tab1 = line.find('\t'), tab2 = line.find('\t', tab1 + 1);
        if (tab1 != std::string::npos && tab2 != std::string::npos) {
            changes.push_back({line.substr(0, tab1), line.substr(tab1 + 1, tab2 - tab1 - 1) == "1",
                               line.substr(tab2 + 1)});
        }
        start = end + 1;
    }
    return changes;
}

void handOver(const std::filesystem::path& path) {
    const std::string bytes = readTextFile(path);
    pbr_hand_over(path.filename().string().c_str(),
                  reinterpret_cast<const unsigned char*>(bytes.data()), int(bytes.size()));
}

namespace {
bool waited = false;  // main() has given the browser a turn: it ends asynchronously
bool shownFirstFrame = false;
int exitCode = 0;
}  // namespace

void status(const std::string& text) {
    pbr_status(text.c_str());
    waited = true;
    pbr_wait_for_paint();
}

void announceFirstFrame() {
    status(pbr_software_webgl() ? "drawing the first frame (WebGL on the CPU, without a GPU: "
                                  "this takes a second or more)"
                                : "drawing the first frame");
}

void waitForNextFrame() {
    if (!shownFirstFrame) {
        pbr_first_frame_submitted();
        finishGl();  // drawn, not only queued (glFinish alone does not wait in WebGL)
        pbr_first_frame_drawn();
        shownFirstFrame = true;
    }
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
