#include "app/panel_script.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "base/error.h"

namespace pbr {

std::vector<InputFrame> parsePanelScript(std::string_view text, const std::string& name) {
    std::vector<InputFrame> frames;
    // Lines as std::getline splits a file: a last line without its '\n' still counts.
    for (size_t at = 0; at < text.size();) {
        const size_t end = std::min(text.find('\n', at), text.size());
        const std::string line(text.substr(at, end - at));
        at = end + 1;
        const std::string where =
            name + ":" + std::to_string(frames.size() + 1) + ": '" + printable(line);
        InputFrame frame;
        if (line != "-") {
            std::istringstream fields(line);
            int button = 0;
            std::string rest;
            bool read = bool(fields >> frame.cursor.x >> frame.cursor.y >> button);
            if (read && !(fields >> std::ws).eof()) read = bool(fields >> frame.scroll);
            if (!read || (fields >> rest) || button < 0 || button > 2) {
                throw Error(where +
                            "' is not 'x y button [scroll]' (button 0 up, 1 held, 2 clicked "
                            "between frames; scroll steps, up positive) or '-'");
            }
            if (!(std::abs(frame.scroll) <= kMaxScriptScroll)) {
                throw Error(where + "': a scroll of more than 100 steps in a frame");
            }
            // A cursor at 3e38 is a number, but the move to the next one would be infinite.
            if (!(std::abs(frame.cursor.x) <= kMaxScriptCursor) ||
                !(std::abs(frame.cursor.y) <= kMaxScriptCursor)) {
                throw Error(where + "': the cursor lies further than 1e6 pixels from the picture");
            }
            frame.leftButton = button == 1;
            frame.leftPresses = button == 2 ? 1 : 0;
        }
        frames.push_back(frame);
    }
    return frames;
}

}  // namespace pbr
