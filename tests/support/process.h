#pragma once
// Runs a sample as a child process and captures what it printed, for tests that check exit codes,
// messages and the images it writes.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pbr::test {

struct RunResult {
    int exitCode = -1;  // -1: killed by a signal (a crash)
    std::string out;
    std::string err;
    // The lines of err and out, without their ends (LF, or a Windows program's CR LF).
    std::vector<std::string> errLines() const;
    std::vector<std::string> outLines() const;
};

struct RunOptions {
    std::map<std::string, std::string> setEnv{};  // variables to set
    std::vector<std::string> unsetEnv{};          // variables to remove
    std::filesystem::path workingDirectory{};     // empty: inherit
    // A nearly full disk, for the child alone: no file it writes may grow past this many bytes
    // (RLIMIT_FSIZE; the write fails with EFBIG instead of killing it). 0: no limit.
    size_t fileSizeLimit = 0;
};

// argv[0] is a sample name ("01_lighting") or a path.
RunResult runSample(std::vector<std::string> argv, const RunOptions& options = {});

// A fresh, empty folder under the build's test-output/ for one test.
std::filesystem::path testOutputDir(const std::string& name);

// The names in a folder, hidden files included, sorted.
std::vector<std::string> folderEntries(const std::filesystem::path& dir);

// A file's bytes ("" when it cannot be read).
std::string readBytes(const std::filesystem::path& path);

// A backend's name as a gtest parameter name ("egl-software" -> "egl_software").
std::string paramName(std::string name);

// Where `program` is found on PATH, if anywhere.
std::optional<std::filesystem::path> onPath(const std::string& program);

// The full path of a sample executable.
std::filesystem::path sampleExecutable(const std::string& name);

}  // namespace pbr::test
