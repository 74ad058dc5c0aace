#pragma once
// A web sample's page (build/web/<sample>.html, ./build.sh web) run in headless Chromium on its
// software GL (SwiftShader) until the sample exits, and what it left in the page: its log, its
// exit code and the files it wrote (web/shell.html keeps each one's bytes in the DOM;
// tests/web/run_page.js, run by node, drives the browser and takes them out).
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "support/process.h"

namespace pbr::test {

struct PageRun {
    RunResult browser;            // the driver's exit code and messages (the browser's on failure)
    std::optional<int> exitCode;  // the sample's; none when it is still running or never ran
    std::string log;              // what the sample printed (stdout and stderr, in order)
    std::map<std::string, std::string> files;  // name -> bytes
    std::string address;  // the page's query string at the end (its controls keep it current)
    std::vector<std::string> said;  // every text the page's header showed, in order
    std::string hint;               // the header's line on the mouse and keys
    std::string command;            // the bar's command line under a shown picture
    std::string frame;              // the bar's frame time ("143 ms a frame")
    std::string caption;            // a view's caption over a shown picture
    std::string scale;              // its scale bar's ticks: "at value" pairs, ';' between them
    int labelsShown = 0;            // labels over the picture (App::label) still shown at the end
};

// Why the web tests cannot run on this machine (no browser, no web build), or nullopt.
std::optional<std::string> webUnavailable(const std::string& sample = "01_lighting");

// build/web/<sample>.html
std::filesystem::path webPage(const std::string& sample);

// Opens the page with `args` as the sample's command line (the query string, one item an
// argument) and waits for it to exit (4 minutes at most); the files it wrote land in `dir`.
// `input` goes after '#' (web/shell.html): "hold=87" keeps W down, "move=8,0" moves the mouse
// 8 pixels right at every frame, "set=--lights:2" changes that control of the page as a user
// would.
PageRun runPage(const std::string& sample, const std::vector<std::string>& args,
                const std::filesystem::path& dir, const std::string& input = "");

}  // namespace pbr::test

// ---- Additions for tests/khronos
// -----------------------------------------------------------------
namespace pbr::test {

// The browser (chromium-headless-shell, else chromium) and node on PATH, when there.
std::optional<std::filesystem::path> chromiumOnPath();
std::optional<std::filesystem::path> nodeOnPath();

}  // namespace pbr::test
