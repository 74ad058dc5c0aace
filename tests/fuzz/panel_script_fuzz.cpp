// PBR_PANEL_SCRIPT (app/panel_script.h): any text either gives a frame for each of its lines,
// the mouse at a finite place within reach of the picture or absent, its scroll finite and
// bounded, a flag changed only by its name as the command line spells it, or is refused in one
// line naming the script and the line.
#include "app/panel_script.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace pbr;
    const std::string name = "fuzz.script";
    const std::string_view text = fuzz::bytesOf(data, size);
    std::vector<ScriptFrame> frames;
    try {
        frames = parsePanelScript(text, name);
    } catch (const Error& e) {
        fuzz::expectOneLine(e.what(), name + ":");
        return 0;
    } catch (const std::exception& e) {
        fuzz::finding(std::string("not an Error but ") + fuzz::typeName(typeid(e)) + ": " +
                      e.what());
    }
    // a frame a line, but for the flags' lines (and one more frame for those after the last)
    size_t changes = 0;
    for (const ScriptFrame& frame : frames) changes += frame.changes.size();
    const size_t lines = fuzz::split(text, '\n').size();
    fuzz::expect(frames.size() + changes == lines ||
                     (frames.size() + changes == lines + 1 && !frames.back().changes.empty()),
                 "a frame a line, but for the flags' lines");
    for (const ScriptFrame& script : frames) {
        const InputFrame& frame = script.input;
        for (const ScriptFlagChange& change : script.changes) {
            fuzz::expect(change.flag.size() > 2 && change.flag.rfind("--", 0) == 0 &&
                             change.flag.find_first_not_of(
                                 "-abcdefghijklmnopqrstuvwxyz0123456789") == std::string::npos,
                         "a flag named as the command line spells it");
            fuzz::expect(
                !change.value || change.value->find_first_of(" \t\r\n") == std::string::npos,
                "a flag's value is one word");
        }
        // "-" is the cursor at (-1, -1), unknown
        for (const float v : {frame.cursor.x, frame.cursor.y}) {
            fuzz::expect(std::isfinite(v) && std::abs(v) <= kMaxScriptCursor,
                         "the cursor finite, within reach of the picture");
        }
        fuzz::expect(std::isfinite(frame.scroll) && std::abs(frame.scroll) <= kMaxScriptScroll,
                     "a finite scroll of at most 100 steps");
        fuzz::expect(frame.leftPresses == 0 || !frame.leftButton,
                     "a click between frames leaves the button up");
        // What the App makes of two frames: the move between them is finite.
        fuzz::expect(std::isfinite(frame.cursor.x - frames.front().input.cursor.x) &&
                         std::isfinite(frame.cursor.y - frames.front().input.cursor.y),
                     "a finite move from frame to frame");
    }
    return 0;
}
