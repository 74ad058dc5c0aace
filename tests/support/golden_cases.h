#pragma once
// The table of golden pictures, shared by the golden tests (software rendering, the tight gate)
// and the GPU tests (a GPU through EGL, a gate of their own).
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace pbr::test {

// Every golden image, one case each: the golden's name (tests/golden/<golden>.png), the sample
// and its arguments, how much of the picture must differ from its clear colour, and, for one
// golden drawn from several inputs, the other inputs that must give the very same bytes. The
// test of a case is named after its golden (MatchesGolden/<golden>_<backend>), so that a check
// can tell which tests rewrite which goldens (see tests/docs/check_docs.py).
struct GoldenCase {
    std::string golden;
    std::string sample;
    std::vector<std::string> args{};
    double minNonBlank = 0.0;
    std::vector<std::vector<std::string>> sameBytesAs{};
    bool needsAssimpModels = false;  // draws Debian's assimp-testmodels: skipped without them
};

std::vector<GoldenCase> goldenCases();

// The goldens of the browser build (tests/golden/web/<golden>.png): each sample of the web build
// at its default view (05 also --textured), named as the native golden it is compared with.
std::vector<GoldenCase> webGoldenCases();

// The goldens a folder holds: the names of its pictures (<golden>.png) and of their metadata
// (<golden>.json), and the names a table of cases gives; a test compares the three.
struct GoldenFolder {
    std::set<std::string> pictures, metadata, cases;
};
GoldenFolder goldenFolder(const std::filesystem::path& dir, const std::vector<GoldenCase>& cases);

}  // namespace pbr::test
