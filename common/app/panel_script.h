#pragma once
// PBR_PANEL_SCRIPT: the mouse over the picture and the live flags, frame by frame, with which the
// tests drive the live panel and the samples headless. Pure: the App reads the file and hands its
// text here.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "context/context.h"

namespace pbr {

// Cursor coordinates further than this from the picture's corner are refused: the framebuffer is
// at most 16384 pixels a side, and a frame's move (the difference of two cursors) stays exact.
inline constexpr float kMaxScriptCursor = 1.0e6f;
// Scroll steps in one frame, at most (a wheel gives one a notch).
inline constexpr float kMaxScriptScroll = 100.0f;

// A live flag changed before a frame, as a page's control changes it (App::setLiveFlag).
struct ScriptFlagChange {
    std::string flag;                  // "--view"
    std::optional<std::string> value;  // nullopt: left out (a switch off, a number at its default)
};

// One frame of a script: its mouse, and the flags changed before it is drawn.
struct ScriptFrame {
    InputFrame input;  // the mouse (cursor negative: none); `screenshot` (F12), `togglePanel` (Tab)
    std::vector<ScriptFlagChange> changes;
};

// The frames of a panel script's text, a frame a line, but for the flags' lines:
//   "x y button [scroll] [Tab]"
//                          the mouse there (framebuffer pixels from the top-left; the left button
//                          0 up, 1 held, 2 pressed and released since the last frame: a click
//                          shorter than a frame; the wheel's steps, up positive, 0 when left out),
//                          and Tab pressed in the same frame
//   "-"                    no mouse
//   "F12"                  no mouse, and the frame is written as a window's F12 writes it
//   "Tab"                  no mouse, and Tab pressed (the panel hidden or shown)
//   "set --flag [VALUE]"   not a frame: the live flag takes VALUE (a switch: on) before the next
//   "unset --flag"         not a frame: the live flag is left out (a switch off) before the next
// Flags' lines after the last frame make one more frame, without the mouse. Frames past the last
// have none. Throws Error("<name>:<line>: ...") for any other line.
std::vector<ScriptFrame> parsePanelScript(std::string_view text, const std::string& name);

}  // namespace pbr
