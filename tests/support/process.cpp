#include "support/process.h"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "support/build_paths.h"

namespace pbr::test {

namespace fs = std::filesystem;

namespace {
// A program's output, a line each; a Windows program's CR LF ends its lines too.
std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(line);
    }
    return lines;
}
}  // namespace

std::vector<std::string> RunResult::errLines() const {
    return linesOf(err);
}
std::vector<std::string> RunResult::outLines() const {
    return linesOf(out);
}

std::optional<fs::path> onPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        const fs::path candidate = fs::path(dir) / program;
        std::error_code ec;
        if (!dir.empty() && fs::is_regular_file(candidate, ec)) return candidate;
    }
    return std::nullopt;
}

fs::path sampleExecutable(const std::string& name) {
    return fs::path(PBR_PATH(PBR_SAMPLE_BIN_DIR)) / name;
}

fs::path testOutputDir(const std::string& name) {
    const fs::path dir = fs::path(PBR_PATH(PBR_TEST_OUTPUT_DIR)) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string paramName(std::string name) {
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

std::vector<std::string> folderEntries(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
    std::sort(names.begin(), names.end());
    return names;
}

std::string readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

RunResult runSample(std::vector<std::string> argv, const RunOptions& options) {
    if (argv.empty()) throw std::invalid_argument("runSample: empty argv");
    if (argv[0].find('/') == std::string::npos) argv[0] = sampleExecutable(argv[0]).string();

    char outName[] = "/tmp/pbr-test-out-XXXXXX";
    char errName[] = "/tmp/pbr-test-err-XXXXXX";
    const int outFd = mkstemp(outName);
    const int errFd = mkstemp(errName);
    if (outFd < 0 || errFd < 0) throw std::runtime_error("runSample: mkstemp failed");

    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("runSample: fork failed");
    if (pid == 0) {
        dup2(outFd, 1);
        dup2(errFd, 2);
        const int devNull = open("/dev/null", O_RDONLY);
        if (devNull >= 0) dup2(devNull, 0);
        for (const auto& [name, value] : options.setEnv) setenv(name.c_str(), value.c_str(), 1);
        for (const std::string& name : options.unsetEnv) unsetenv(name.c_str());
        if (!options.workingDirectory.empty() && chdir(options.workingDirectory.c_str()) != 0)
            _exit(126);
        if (options.fileSizeLimit > 0) {
            std::signal(SIGXFSZ, SIG_IGN);  // ignored across exec: the write returns EFBIG
            const rlimit limit{options.fileSizeLimit, options.fileSizeLimit};
            if (setrlimit(RLIMIT_FSIZE, &limit) != 0) _exit(125);
        }
        std::vector<char*> args;
        for (std::string& arg : argv) args.push_back(arg.data());
        args.push_back(nullptr);
        execv(args[0], args.data());
        _exit(127);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    close(outFd);
    close(errFd);
    RunResult result;
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = readBytes(outName);
    result.err = readBytes(errName);
    fs::remove(outName);
    fs::remove(errName);
    return result;
}

}  // namespace pbr::test
