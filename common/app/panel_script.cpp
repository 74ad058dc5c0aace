#include "app/panel_script.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "base/error.h"

namespace pbr {

namespace {

// A flag's name as the command line spells it: "--" and lower-case words joined by '-'.
bool isFlagName(const std::string& word) {
    if (word.size() < 3 || word.rfind("--", 0) != 0) return false;
    return std::all_of(word.begin() + 2, word.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
    });
}

}  // namespace

std::vector<ScriptFrame> parsePanelScript(std::string_view text, const std::string& name) {
    std::vector<ScriptFrame> frames;
    std::vector<ScriptFlagChange> changes;  // the flags' lines since the last frame
    // Lines as std::getline splits a file: a last line without its '\n' still counts.
    int number = 0;
    for (size_t at = 0; at < text.size();) {
        const size_t end = std::min(text.find('\n', at), text.size());
        const std::string line(text.substr(at, end - at));
        at = end + 1;
        const std::string where = name + ":" + std::to_string(++number) + ": '" + printable(line);
        ScriptFrame script;
        InputFrame& frame = script.input;
        std::istringstream words(line);
        std::string first, flag, value, rest;
        words >> first;
        if (first == "set" || first == "unset") {
            bool read = bool(words >> flag) && isFlagName(flag);
            if (read && first == "set") words >> value;  // a switch has none
            if (!read || (words >> rest)) {
                throw Error(where + "' is not 'set --flag [value]' or 'unset --flag'");
            }
            changes.push_back({flag, first == "set" ? std::optional(value) : std::nullopt});
            continue;
        } else if (line == "F12") {
            frame.screenshot = true;
        } else if (line == "Tab") {
            frame.togglePanel = true;
        } else if (line != "-") {
            std::istringstream fields(line);
            int button = 0;
            bool read = bool(fields >> frame.cursor.x >> frame.cursor.y >> button);
            std::vector<std::string> more;  // [scroll] [Tab]
            for (std::string word; read && fields >> word;) more.push_back(word);
            if (!more.empty() && more.back() == "Tab") {
                frame.togglePanel = true;
                more.pop_back();
            }
            if (more.size() == 1) {
                std::istringstream number(more[0]);
                read = bool(number >> frame.scroll) && (number >> std::ws).eof();
            } else if (more.size() > 1) {
                read = false;
            }
            if (!read || button < 0 || button > 2) {
                throw Error(where +
                            "' is not 'x y button [scroll] [Tab]' (button 0 up, 1 held, 2 clicked "
                            "between frames; scroll steps, up positive), '-', 'set --flag "
                            "[value]', 'unset --flag', 'F12' or 'Tab'");
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
        script.changes = std::move(changes);
        changes.clear();
        frames.push_back(std::move(script));
    }
    if (!changes.empty()) frames.push_back({.input = {}, .changes = std::move(changes)});
    return frames;
}

}  // namespace pbr
