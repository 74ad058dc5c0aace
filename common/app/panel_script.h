#pragma once
// PBR_PANEL_SCRIPT: the mouse over the picture, a frame a line, with which the tests drive the
// live panel headless. Pure: the App reads the file and hands its text here.
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

// One line of a script: the mouse of a frame, and what else happens before it is drawn.
struct ScriptFrame {
    InputFrame input;  // the mouse (cursor negative: none); `screenshot` (F12), `togglePanel` (Tab)
    // "set --flag [VALUE]", "unset --flag": a live flag changed before the frame, as a page's
    // control changes it (App::setLiveFlag); empty: none.
    std::string flag;
    std::optional<std::string>
        value;  // nullopt: unset (a switch off, a number back to its default)
};

// The frames of a panel script's text, a frame a line:
//   "x y button [scroll] [Tab]"
//                          the mouse there (framebuffer pixels from the top-left; the left button
//                          0 up, 1 held, 2 pressed and released since the last frame: a click
//                          shorter than a frame; the wheel's steps, up positive, 0 when left out),
//                          and Tab pressed in the same frame
//   "-"                    no mouse
//   "set --flag [VALUE]"   the live flag takes VALUE (a switch: on), no mouse
//   "unset --flag"         the live flag is left out (a switch off), no mouse
//   "F12"                  no mouse, and the frame is written as a window's F12 writes it
//   "Tab"                  no mouse, and Tab pressed (the panel hidden or shown)
// Frames past the last line have none. Throws Error("<name>:<line>: ...") for any other line.
std::vector<ScriptFrame> parsePanelScript(std::string_view text, const std::string& name);

}  // namespace pbr
