#pragma once
// PBR_PANEL_SCRIPT: the mouse over the picture, a frame a line, with which the tests drive the
// live panel headless. Pure: the App reads the file and hands its text here.
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

// The frames of a panel script's text: a line "x y button [scroll]" (framebuffer pixels from the
// top-left; the left button 0 up, 1 held, 2 pressed and released since the last frame: a click
// shorter than a frame; the wheel's steps, up positive, 0 when left out) is the mouse there, "-"
// a frame without the mouse. Frames past the last
// line have none. Throws Error("<name>:<line>: ...") for any other line.
std::vector<InputFrame> parsePanelScript(std::string_view text, const std::string& name);

}  // namespace pbr
