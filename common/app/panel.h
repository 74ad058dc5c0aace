#pragma once
// The live panel of a window (Dear ImGui, from Debian's libimgui-dev): the sample's flags as
// controls, made from their declarations (FlagSpec), so that there is no second list of
// parameters. A number is a slider, an integer a stepper, a choice a combo box, a switch a
// checkbox; a flag the sample reads only at start-up is shown with its value and no control. A
// control writes its flag's text into the App's flag values, and the sample reads it the next
// time it asks for the flag: a change goes through the very code the flag takes from the command
// line, so the frame after it equals a headless run started with that flag. Besides the flags:
// the frame time, pause and single step of time, and the command line that draws what is on
// screen, with a button that copies it.
//
// The App owns it (a window shows it; Tab hides and shows it; --panel draws it into a headless
// picture too). Its input comes from the App as plain values, the same from a window and from the
// tests' scripts (PBR_PANEL_SCRIPT, see App). Without Dear ImGui (another system, the browser
// build) `available()` is false and no panel is made.
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/options.h"
#include "app/views.h"

namespace pbr {

// What the mouse does over the picture this frame.
struct PanelInput {
    glm::vec2 cursor{-1.0f};  // in framebuffer pixels from the top-left; negative: not over it
    bool leftButton = false;
    int leftPresses = 0;  // since the last frame (InputFrame::leftPresses)
    float scroll = 0.0f;
    float deltaSeconds = 1.0f / 60.0f;  // since the last frame (> 0)
};

// What the panel shows besides the flags, and what was clicked there this frame.
struct PanelStatus {
    std::string title;
    std::string commandLine;          // the command that draws what is on screen
    double frameMilliseconds = -1.0;  // negative: not shown (headless, whose picture must repeat)
    bool paused = false;
    // set by Panel::update
    bool pauseClicked = false, stepClicked = false;
};

class Panel {
public:
    static bool available();  // this build has Dear ImGui

    // Needs the GL context current. `copy` puts a text on the clipboard (the window's).
    Panel(std::vector<FlagSpec> flags, std::function<void(const std::string&)> copy);
    ~Panel();
    Panel(const Panel&) = delete;
    Panel& operator=(const Panel&) = delete;

    // Starts this frame's layer over a picture of `size` pixels and lays out the panel (unless
    // `showPanel` is false: labels only). A control the input moved writes its flag's new text
    // into `values` (a switch that is off, and a flag at its default that was never given, are
    // absent); returns the names of the flags it changed. Labels may be added until end().
    std::vector<std::string> begin(const PanelInput& input, glm::ivec2 size,
                                   std::map<std::string, std::string>& values, PanelStatus& status,
                                   bool showPanel = true);
    // A label over the picture at `pixel` (from the top-left), centred there.
    void label(glm::vec2 pixel, const std::string& text);
    // A view's caption at the picture's top left (viewCaption), with a scale bar under it:
    // grey levels 0 to 255 across, ticked where a value as it is (0, 0.5, 1), or x of
    // x / (1 + x) (0, 0.25, 1, 4, each divided by `gain`: --gain), lands.
    void caption(const std::string& text, ViewScale scale, float gain = 1.0f);
    // Ends the frame's layer: what draw() draws.
    void end();
    // The cursor is over the panel, or one of its controls holds the mouse (a slider dragged
    // past the panel's edge): the camera leaves the mouse alone.
    bool wantsMouse() const;
    // Draws the last update's panel into the bound framebuffer (GL state restored after).
    void draw() const;
    // Where the last update put each control, a line each: "<id> x y w h" in framebuffer pixels
    // from the top-left. Ids: "--flag" (a slider's or a combo box's frame, a checkbox), "--flag -"
    // and "--flag +" (a stepper's buttons), "--flag=word" (an open combo box's item), "pause",
    // "step", "copy", "copied" (its note), "title" (the title bar). The tests aim their clicks
    // with it.
    std::string layout() const;

private:
    std::vector<std::string> layoutFrame(const PanelInput& input, glm::ivec2 size,
                                         std::map<std::string, std::string>& values,
                                         PanelStatus& status, bool showPanel);
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace pbr
