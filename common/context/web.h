#pragma once
// What the browser build (PBR_WEBGL, see gl.h) needs from the page its sample runs in; on the
// desktop these do nothing.
//
// The page (web/shell.html) shows every file the run writes as a download link and keeps its
// bytes (base64) in the DOM, where a test reads them back; and the frame loop gives the browser
// its turn between frames, so that it can show the canvas and deliver input.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "gl/gl.h"

namespace pbr::web {

#ifdef PBR_WEBGL
// Hands a file the run has written (in the page's memory file system) to the page.
void handOver(const std::filesystem::path& path);
// Returns at the browser's next animation frame (the sample's loop is suspended meanwhile).
// The first call finishes the first frame's GL work and tells the page it is drawn (the header
// then says "running", and the page keeps the time since it was opened: see docs/web.md).
void waitForNextFrame();
// What the page is doing, in its header ("computing sunny_courtyard.environment.ktx"); the
// browser is given a turn to show it before the work goes on.
void status(const std::string& text);
// Before the first frame's commands: the header says the first frame is being drawn, and, where
// the browser draws WebGL on the CPU (no GPU: SwiftShader, llvmpipe), that this takes a while.
void announceFirstFrame();
// Once main() has waited for a frame, the browser no longer sees what it returns (emscripten
// 3.1.6 drops the return value of a main that resumed): the program's main() (web/
// samples_main.cpp) hands the sample's exit code here, and the page exits with it right after
// main() returns.
void exitWithAfterMain(int code);
// The page's controls (web/shell.html builds them as form elements): the sample's flag
// declarations as JSON, handed over once; and what the controls changed since the last call, a
// flag and its new text each (a switch turned off: no text).
struct FlagChange {
    std::string name;
    bool present = true;
    std::string value;
};
void declareFlags(const std::string& json);
std::vector<FlagChange> takeFlagChanges();
// The header's line on how the picture takes the mouse and keys (the fly camera's, or the orbit
// camera's).
void mouseHint(const std::string& text);
// The bar under a shown picture, as the window's panel has it: the frame time (negative: none
// yet), the command line of the view, and whether time stands (pause or run).
void showFrame(double milliseconds, const std::string& commandLine, bool paused);
// A view's caption over the picture's top left ("" for none), with a scale bar under it where
// `ticks` has any: {where on the bar from 0 to 1, the value's text} (viewScaleTicks).
void showCaption(const std::string& text, const std::vector<std::pair<float, std::string>>& ticks);
// The bar's pause and step buttons pressed since the last frame.
struct ClockPresses {
    bool pause = false, step = false;
};
ClockPresses takeClockPresses();
// Labels over the picture, as the window's panel layer draws them (App::label): those of the
// frame being drawn, at pixels of the picture from its top-left; shown when the frame is.
void label(float x, float y, const std::string& text);
void showLabels(int width, int height);
#else
inline void handOver(const std::filesystem::path&) {}
inline void waitForNextFrame() {}
inline void status(const std::string&) {}
inline void announceFirstFrame() {}
inline void exitWithAfterMain(int) {}
#endif

}  // namespace pbr::web
