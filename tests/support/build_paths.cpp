#include "support/build_paths.h"

#include <filesystem>
#include <fstream>
#include <map>

namespace pbr::test {

namespace {

// test-paths.txt beside this program: one "NAME=value" a line (a value may hold spaces and '=').
const std::map<std::string, std::string>& pathsBesideTheProgram() {
    static const std::map<std::string, std::string> paths = [] {
        std::map<std::string, std::string> read;
        std::error_code error;
        const std::filesystem::path program =
            std::filesystem::read_symlink("/proc/self/exe", error);
        if (error) return read;
        std::ifstream in(program.parent_path() / "test-paths.txt");
        for (std::string line; std::getline(in, line);) {
            const size_t equals = line.find('=');
            if (equals != std::string::npos) read[line.substr(0, equals)] = line.substr(equals + 1);
        }
        return read;
    }();
    return paths;
}

}  // namespace

std::string buildPath(const char* name, const char* compiled) {
    const auto& paths = pathsBesideTheProgram();
    const auto found = paths.find(name);
    return found != paths.end() ? found->second : std::string(compiled);
}

}  // namespace pbr::test
