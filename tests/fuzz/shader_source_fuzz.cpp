// The shader files a user edits or points the samples at (PBR_SHADER_DIR; the R key reloads them),
// through the pure functions of gl/shader.h: the input, cut at each '\0', is a main shader and the
// files it may include (kFiles), written to a folder of this process's own. preprocessShader
// either gives a text each line of which leads back to its place in one of the files it read, or
// is refused in one line naming the file at fault (one of the folder's) and the line. On that
// text, toGlslEs either changes the first line only, "#version 330 core" into "#version 300 es"
// and its precision statements, or is refused in one line naming the main shader; and
// mapShaderLog, given the input itself as a driver's log, gives one line for each line of the
// log that is not blank, and leads each file's "line 1" of every driver's format back to it.
#include <fcntl.h>
#include <unistd.h>

#include <set>

#include "base/paths.h"
#include "fuzz_check.h"
#include "gl/shader.h"

namespace pbr::fuzz {

namespace fs = std::filesystem;

// Line L of files[n] is numbered n * 10000 + L in the text for the compiler (gl/shader.h).
constexpr long kLinesPerFile = 10000;

// Where the parts of the input go, in order: the main shader, two files of the include folder,
// one beside the main shader, and one of the include folder of the same name that it hides from
// the main shader (but not from a.glsl and b.glsl, beside which it lies). Parts past these are
// left out; a file without its part is absent (an include of it is not found).
constexpr const char* kFiles[] = {"main.frag", "include/a.glsl", "include/b.glsl", "c.glsl",
                                  "include/c.glsl"};

// A folder of this process's own (libFuzzer's -jobs run several side by side), holding the files
// of one input at a time; removed at exit.
struct ShaderFolder {
    fs::path dir = fs::temp_directory_path() / ("pbr-fuzz-shader-" + std::to_string(getpid()));
    ShaderFolder() { fs::create_directories(dir / "include"); }
    ~ShaderFolder() {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
};

const fs::path& shaderFolder() {
    static const ShaderFolder folder;
    return folder.dir;
}

// Writes the files of one input, and removes those of the input before that this one lacks, so
// that it finds its own files and nothing else. A file is written over and then cut to its
// length, never truncated first: ext4 writes a file truncated to nothing out to the disk when it
// is closed, and each input waited for that (1250 inputs a second against 2500, 2026-12-06).
void writeFiles(const std::vector<std::string>& parts) {
    static bool present[std::size(kFiles)] = {};
    for (size_t i = 0; i < std::size(kFiles); ++i) {
        const fs::path file = shaderFolder() / kFiles[i];
        if (i == 0 || i < parts.size()) {  // the main shader always, empty without its part
            const std::string_view text = i < parts.size() ? std::string_view(parts[i]) : "";
            const int fd = open(file.c_str(), O_WRONLY | O_CREAT, 0644);
            if (fd < 0 || write(fd, text.data(), text.size()) != ssize_t(text.size()) ||
                ftruncate(fd, off_t(text.size())) != 0) {
                finding("cannot write " + file.string());
            }
            close(fd);
            present[i] = true;
        } else if (present[i]) {
            fs::remove(file);
            present[i] = false;
        }
    }
}

// The number of a "#line N" as shader.cpp writes it, else -1.
long directiveNumber(std::string_view line) {
    constexpr std::string_view kLine = "#line ";
    if (line.substr(0, kLine.size()) != kLine || line.size() == kLine.size() ||
        line.size() > kLine.size() + 9) {
        return -1;
    }
    long number = 0;
    for (const char c : line.substr(kLine.size())) {
        if (c < '0' || c > '9') return -1;
        number = number * 10 + (c - '0');
    }
    return number;
}

// Whether every line of `text` leads back to its place: each line either is line L of files[n]
// (`lines[n]`) where the lines before it number it n * kLinesPerFile + L, or is a "#line N" that
// numbers the next. A line of the files' own that reads "#line N" may be either: every numbering
// that the lines so far allow is followed.
bool leadsBack(const std::string& text, const std::vector<std::vector<std::string>>& lines) {
    std::set<long> next = {1};  // the numbers the next line may carry
    for (const std::string& line : split(text, '\n')) {
        std::set<long> after;
        for (const long number : next) {
            const size_t file = size_t(number / kLinesPerFile);
            const size_t at = size_t(number % kLinesPerFile);
            if (file < lines.size() && at >= 1 && at <= lines[file].size() &&
                lines[file][at - 1] == line) {
                after.insert(number + 1);
            }
        }
        if (const long number = directiveNumber(line); number >= 0) after.insert(number);
        if (after.empty()) return false;
        next = std::move(after);
    }
    return true;
}

// The promises of a preprocessed shader: it starts with the main shader, reads each file once,
// holds each line of theirs and a "#line" for each file and each #include, and every line of it
// leads back to its place.
void expectLeadsBack(const ShaderSource& source, const fs::path& main) {
    expect(!source.files.empty() && source.files[0] == main, "files[0] is the main shader");
    std::set<fs::path> distinct;
    std::vector<std::vector<std::string>> lines;
    size_t total = 0;
    for (const fs::path& file : source.files) {
        std::error_code ec;
        distinct.insert(fs::weakly_canonical(file, ec));
        lines.push_back(split(readTextFile(file), '\n'));
        total += lines.back().size();
    }
    expect(distinct.size() == source.files.size(), "each file read once");
    // A file's own lines, its "#line n * 10000 + 1" (but the main shader's) and one "#line" in
    // place of each #include line.
    expect(split(source.text, '\n').size() == total + source.files.size() - 1,
           "the files' lines and a #line for each included file");
    expect(leadsBack(source.text, lines), "every line leads back to its file and line");
}

// toGlslEs on the preprocessed text: the ES header in place of "#version 330 core", the rest as
// it was, numbered from 2 again; refused, naming the main shader, for any other first line.
void expectEs(const std::string& text, const fs::path& main) {
    const size_t end = text.find('\n');
    std::string_view first = std::string_view(text).substr(0, end);
    if (!first.empty() && first.back() == '\r') first.remove_suffix(1);
    const bool desktop = first == "#version 330 core";
    std::string es;
    if (!reads(displayPath(main) + ":1: ", [&] { es = toGlslEs(text, main); })) {
        expect(!desktop, "a #version 330 core shader is made an ES one");
        return;
    }
    expect(desktop, "only a #version 330 core shader is made an ES one");
    const std::string rest = end == std::string::npos ? "" : text.substr(end + 1);
    constexpr std::string_view kVersion = "#version 300 es\n";
    expect(es.substr(0, kVersion.size()) == kVersion, "an ES shader starts #version 300 es");
    expect(es.size() >= rest.size() && es.substr(es.size() - rest.size()) == rest,
           "an ES shader ends with the lines after the first, unchanged");
    const std::string header = es.substr(0, es.size() - rest.size());
    expect(header.size() >= 8 && header.substr(header.size() - 8) == "#line 2\n",
           "the lines after the first keep their numbers");
}

// mapShaderLog: the input as a driver's log, a line out for each line in that is not blank; and
// line 1 of each file, in Mesa's, NVIDIA's and ANGLE's words, mapped back to that file's line 1.
void expectLogLines(std::string_view log, const std::vector<fs::path>& files) {
    size_t notBlank = 0;
    for (std::string line : split(log, '\n')) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find_first_not_of(" \t") != std::string::npos) ++notBlank;
    }
    const std::vector<std::string> mapped = mapShaderLog(std::string(log), files);
    expect(mapped.size() == notBlank, "a line out for each line of the log that is not blank");
    for (const std::string& line : mapped)
        expect(line.find('\n') == std::string::npos, "a mapped line is one line");

    for (size_t n = 0; n < files.size(); ++n) {
        const std::string line = std::to_string(long(n) * kLinesPerFile + 1);
        const std::string place = displayPath(files[n]) + ":1: ";
        for (const auto& [driver, expected] :
             {std::pair{"0:" + line + "(5): error: x", place + "error: x"},
              std::pair{"0(" + line + ") : error C0000: x", place + "error C0000: x"},
              std::pair{"ERROR: 0:" + line + ": x", place + "error: x"}}) {
            expect(mapShaderLog(driver, files) == std::vector<std::string>{expected},
                   "a driver's message leads back to its file and line: " + driver);
        }
    }
}

}  // namespace pbr::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace pbr;
    namespace fs = std::filesystem;
    const std::string_view bytes = fuzz::bytesOf(data, size);
    const fs::path main = fuzz::shaderFolder() / fuzz::kFiles[0];
    fuzz::writeFiles(fuzz::split(bytes, '\0'));
    // The file at fault is one of the folder's: an #include may leave it, but no file that the
    // fuzzer reaches outside it holds an #include of its own.
    const std::string folder = displayPath(fuzz::shaderFolder()) + "/";
    ShaderSource source;
    try {
        source = preprocessShader(main, fuzz::shaderFolder() / "include");
    } catch (const Error& e) {
        fuzz::expectOneLine(e.what(), folder);
        fuzz::expect(std::string_view(e.what()).substr(0, folder.size()) == folder,
                     "a refusal starts with the file at fault");
        return 0;
    } catch (const std::exception& e) {
        fuzz::finding(std::string("not an Error but ") + fuzz::typeName(typeid(e)) + ": " +
                      e.what());
    }
    fuzz::expectLeadsBack(source, main);
    fuzz::expectEs(source.text, main);
    fuzz::expectLogLines(bytes, source.files);
    return 0;
}
