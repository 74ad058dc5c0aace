#include "support/web_page.h"

#include <cctype>
#include <cstdlib>
#include <initializer_list>
#include <sstream>
#include <string_view>
#include <utility>

#include "support/build_paths.h"

namespace pbr::test {

namespace fs = std::filesystem;

namespace {

std::optional<fs::path> firstOnPath(std::initializer_list<const char*> names) {
    for (const char* name : names) {
        if (auto found = onPath(name)) return found;
    }
    return std::nullopt;
}
std::optional<fs::path> chromium() {
    return firstOnPath({"chromium-headless-shell", "chromium"});
}
std::optional<fs::path> node() {
    return firstOnPath({"node", "nodejs"});
}

std::string percentEncoded(const std::string& text) {
    static const char* hex = "0123456789ABCDEF";
    std::string out;
    for (const unsigned char c : text) {
        if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == ',' || c == '/') {
            out += char(c);
        } else {
            out += '%';
            out += hex[c >> 4];
            out += hex[c & 15];
        }
    }
    return out;
}

}  // namespace

fs::path webPage(const std::string& sample) {
    return fs::path(PBR_PATH(PBR_WEB_DIR)) / (sample + ".html");
}

std::optional<std::string> webUnavailable(const std::string& sample) {
    if (!chromium()) {
        return "no chromium-headless-shell (or chromium) on PATH: the web tests need a browser "
               "(./build.sh test installs Debian's chromium-headless-shell)";
    }
    if (!node()) return "no node on PATH: it drives the browser (tests/web/run_page.js)";
    std::error_code ec;
    if (!fs::exists(webPage(sample), ec)) {
        return "no web build (" + webPage(sample).string() +
               "): build the web samples with ./build.sh web (needs emscripten)";
    }
    return std::nullopt;
}

PageRun runPage(const std::string& sample, const std::vector<std::string>& args,
                const fs::path& dir, const std::string& input) {
    std::string query;
    for (const std::string& arg : args) query += (query.empty() ? "?" : "&") + percentEncoded(arg);
    const fs::path files = dir / "page";
    fs::create_directories(files);
    PageRun page;
    page.browser = runSample({node()->string(), PBR_PATH(PBR_WEB_RUNNER), chromium()->string(),
                              "file://" + fs::absolute(webPage(sample)).string() + query +
                                  (input.empty() ? "" : "#" + input),
                              files.string(), "240"});
    for (const auto& entry : fs::directory_iterator(files)) {
        const std::string name = entry.path().filename().string();
        if (name == "page.log") {
            page.log = readBytes(entry.path());
        } else if (name == "address.txt") {
            page.address = readBytes(entry.path());
        } else if (name == "said.txt") {
            std::istringstream lines(readBytes(entry.path()));
            for (std::string line; std::getline(lines, line);) page.said.push_back(line);
        } else if (name == "hint.txt") {
            page.hint = readBytes(entry.path());
        } else if (name == "command.txt") {
            page.command = readBytes(entry.path());
        } else if (name == "frame.txt") {
            page.frame = readBytes(entry.path());
        } else if (name == "caption.txt") {
            page.caption = readBytes(entry.path());
        } else if (name == "scale.txt") {
            page.scale = readBytes(entry.path());
        } else if (name == "labels.txt") {
            page.labelsShown = std::atoi(readBytes(entry.path()).c_str());
        } else if (name == "exit.txt") {
            page.exitCode = std::atoi(readBytes(entry.path()).c_str());
        } else if (entry.is_regular_file() && name.front() != '.') {
            page.files[name] = readBytes(entry.path());
            fs::copy_file(entry.path(), dir / name, fs::copy_options::overwrite_existing);
        }
    }
    return page;
}

}  // namespace pbr::test

// ---- Additions for tests/khronos (see web_page.h) -----------------------------------------------
namespace pbr::test {

std::optional<std::filesystem::path> chromiumOnPath() {
    return chromium();
}
std::optional<std::filesystem::path> nodeOnPath() {
    return node();
}

}  // namespace pbr::test
