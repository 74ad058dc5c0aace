#include "gl/shader.h"

#include <cstdio>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>

#include <glm/gtc/type_ptr.hpp>

#include "base/error.h"
#include "base/paths.h"

namespace pbr {

namespace fs = std::filesystem;

namespace {

// Mesa keeps the line number of `#line L S` but reports every message as source string 0, so
// the file is encoded in the line number itself: line L of file n is numbered n * 10000 + L.
constexpr int kLinesPerFile = 10000;

std::string lineDirective(int fileId, int line) {
    return "#line " + std::to_string(fileId * kLinesPerFile + line) + "\n";
}

// A tiny cursor over one line, for the two line formats below (no <regex>: it is slow to build
// and its GCC 12 headers warn under the sanitizers).
struct Scanner {
    std::string_view rest;
    void skipSpaces() {
        while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t'))
            rest.remove_prefix(1);
    }
    bool eat(std::string_view token) {
        if (rest.substr(0, token.size()) != token) return false;
        rest.remove_prefix(token.size());
        return true;
    }
    bool number(long& value) {
        size_t digits = 0;
        while (digits < rest.size() && rest[digits] >= '0' && rest[digits] <= '9') ++digits;
        if (digits == 0 || digits > 9) return false;
        value = std::stol(std::string(rest.substr(0, digits)));
        rest.remove_prefix(digits);
        return true;
    }
};

// `#include <argument>` (spaces allowed around '#'): returns the argument, trimmed.
std::optional<std::string> includeArgument(const std::string& line) {
    Scanner scan{line};
    scan.skipSpaces();
    if (!scan.eat("#")) return std::nullopt;
    scan.skipSpaces();
    if (!scan.eat("include")) return std::nullopt;
    std::string argument(scan.rest);
    while (!argument.empty() &&
           (argument.back() == ' ' || argument.back() == '\t' || argument.back() == '\r')) {
        argument.pop_back();
    }
    const size_t start = argument.find_first_not_of(" \t");
    return start == std::string::npos ? std::string() : argument.substr(start);
}

struct Preprocessor {
    fs::path includeDir;
    ShaderSource out;
    std::set<fs::path> included;  // canonical paths already expanded (each file once)
    std::vector<fs::path> stack;  // files being expanded, to refuse cycles

    void expand(const fs::path& file, const std::string& where) {
        std::error_code ec;
        fs::path canonical = fs::weakly_canonical(file, ec);
        if (ec) canonical = file;
        for (const fs::path& open : stack) {
            if (open == canonical)
                throw Error(where + "#include cycle through " + displayPath(file));
        }
        if (!included.insert(canonical).second) return;

        std::string text;
        try {
            text = readTextFile(file);
        } catch (const Error& e) {
            throw Error(where + e.what());
        }
        const int id = int(out.files.size());
        out.files.push_back(file);
        stack.push_back(canonical);
        if (id != 0) out.text += lineDirective(id, 1);

        std::istringstream lines(text);
        std::string line;
        int number = 0;
        while (std::getline(lines, line)) {
            ++number;
            // Line kLinesPerFile would be numbered as line 0 of the next file.
            if (number >= kLinesPerFile) {
                throw Error(displayPath(file) + ":" + std::to_string(number) + ": more than " +
                            std::to_string(kLinesPerFile - 1) +
                            " lines: the compiler's messages could not lead back to them (split "
                            "the file with #include)");
            }
            const std::optional<std::string> argument = includeArgument(line);
            if (!argument) {
                out.text += line;
                out.text += '\n';
                continue;
            }
            const std::string here = displayPath(file) + ":" + std::to_string(number) + ": ";
            if (argument->size() < 3 || argument->front() != '"' || argument->back() != '"' ||
                argument->find('"', 1) != argument->size() - 1) {
                throw Error(here + "#include needs a \"quoted\" file name");
            }
            const std::string name = argument->substr(1, argument->size() - 2);
            fs::path target = file.parent_path() / name;
            if (!fs::exists(target, ec)) target = includeDir / name;
            if (!fs::exists(target, ec)) {
                throw Error(here + "#include \"" + printable(name) +
                            "\": not found beside the file or in " + displayPath(includeDir));
            }
            expand(target, here);
            // Back in this file: the next line is number + 1.
            out.text += lineDirective(id, number + 1);
        }
        stack.pop_back();
    }
};

}  // namespace

ShaderSource preprocessShader(const fs::path& file, const fs::path& includeDir) {
    Preprocessor preprocessor{includeDir, {}, {}, {}};
    preprocessor.expand(file, "");
    return std::move(preprocessor.out);
}

std::string toGlslEs(const std::string& text, const fs::path& file) {
    constexpr std::string_view kDesktop = "#version 330 core";
    const size_t end = text.find('\n');
    std::string_view first = std::string_view(text).substr(0, end);
    if (!first.empty() && first.back() == '\r') first.remove_suffix(1);
    if (first != kDesktop) {
        throw Error(displayPath(file) + ":1: the first line must be '" + std::string(kDesktop) +
                    "' (the browser build turns it into '#version 300 es')");
    }
    // highp everywhere: the IBL sums and the BRDF need float precision, and WebGL 2's fragment
    // shaders have no default for floats (samplers default to lowp). "#line 2" keeps the
    // numbering of the file's own lines.
    return "#version 300 es\n"
           "precision highp float;\n"
           "precision highp int;\n"
           "precision highp sampler2D;\n"
           "precision highp samplerCube;\n"
           "#line 2\n" +
           (end == std::string::npos ? std::string() : text.substr(end + 1));
}

std::vector<std::string> mapShaderLog(const std::string& log, const std::vector<fs::path>& files) {
    std::vector<std::string> mapped;
    std::istringstream lines(log);
    std::string line;
    while (std::getline(lines, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        // Mesa: "0:12(5): error: message"; NVIDIA: "0(12) : error C0000: message".
        Scanner scan{line};
        scan.skipSpaces();
        long source = 0, encoded = 0, column = 0;
        bool parsed = false;
        std::string severity;
        for (const char* word : {"ERROR: ", "WARNING: "}) {  // ANGLE: "ERROR: 0:12: message"
            if (scan.eat(word)) {
                severity = word[0] == 'E' ? "error: " : "warning: ";
                parsed =
                    scan.number(source) && scan.eat(":") && scan.number(encoded) && scan.eat(":");
            }
        }
        if (severity.empty() && scan.number(source)) {
            if (scan.eat(":")) {
                parsed =
                    scan.number(encoded) && scan.eat("(") && scan.number(column) && scan.eat("):");
            } else if (scan.eat("(")) {
                parsed = scan.number(encoded) && scan.eat(")");
                scan.skipSpaces();
                parsed = parsed && scan.eat(":");
            }
        }
        if (!parsed) {
            mapped.push_back(line);
            continue;
        }
        scan.skipSpaces();
        const size_t id = size_t(encoded / kLinesPerFile);
        const std::string file = id < files.size() ? displayPath(files[id]) : "<unknown file>";
        mapped.push_back(file + ":" + std::to_string(encoded % kLinesPerFile) + ": " + severity +
                         std::string(scan.rest));
    }
    return mapped;
}

namespace {

fs::path resolveShaderPath(const fs::path& path) {
    return path.is_absolute() ? path : shaderDir() / path;
}

GLuint compileStage(GLenum stage, const fs::path& path, const std::vector<std::string>& defines) {
    ShaderSource source = preprocessShader(path, shaderDir() / "include");
    if (!defines.empty()) {
        // After the #version line, which must come first; then the file's own line 2 again.
        std::string lines;
        for (const std::string& name : defines) lines += "#define " + name + " 1\n";
        const size_t afterVersion = source.text.find('\n') + 1;
        source.text.insert(afterVersion, lines + lineDirective(0, 2));
    }
    const std::string code = kWebGl ? toGlslEs(source.text, path) : source.text;
    const GLuint shader = glCreateShader(stage);
    const char* text = code.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok) return shader;

    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(size_t(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
    glDeleteShader(shader);
    std::vector<std::string> lines = mapShaderLog(log.c_str(), source.files);
    // The first error names the place; the count says if there is more to fix.
    std::string first = displayPath(path) + ": compile failed";
    for (const std::string& line : lines) {
        if (line.find("error") != std::string::npos) {
            first = line;
            break;
        }
    }
    if (lines.size() > 1) first += " (+" + std::to_string(lines.size() - 1) + " more)";
    throw Error(first);
}

GlProgram linkProgram(const fs::path& vertexPath, const fs::path& fragmentPath,
                      const std::vector<std::string>& defines) {
    const GLuint vertex = compileStage(GL_VERTEX_SHADER, vertexPath, defines);
    GLuint fragment = 0;
    try {
        fragment = compileStage(GL_FRAGMENT_SHADER, fragmentPath, defines);
    } catch (...) {
        glDeleteShader(vertex);
        throw;
    }
    GlProgram program;
    glAttachShader(program.id(), vertex);
    glAttachShader(program.id(), fragment);
    glLinkProgram(program.id());
    glDetachShader(program.id(), vertex);
    glDetachShader(program.id(), fragment);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(size_t(std::max(length, 1)), '\0');
        glGetProgramInfoLog(program.id(), GLsizei(log.size()), nullptr, log.data());
        throw Error(displayPath(vertexPath) + " + " + displayPath(fragmentPath) +
                    ": link failed: " + std::string(log.c_str()));
    }
    return program;
}

}  // namespace

Shader::Shader(fs::path vertexPath, fs::path fragmentPath, std::vector<std::string> defines)
    : vertexPath_(resolveShaderPath(vertexPath)),
      fragmentPath_(resolveShaderPath(fragmentPath)),
      defines_(std::move(defines)),
      program_(linkProgram(vertexPath_, fragmentPath_, defines_)) {}

std::string Shader::name() const {
    return displayPath(vertexPath_) + " + " + displayPath(fragmentPath_);
}

void Shader::use() const {
    useProgram(program_.id());
}

bool Shader::reload() {
    try {
        program_ = linkProgram(vertexPath_, fragmentPath_, defines_);
    } catch (const Error& e) {
        std::fprintf(stderr, "reload failed, keeping the old program: %s\n", e.what());
        return false;
    }
    locations_.clear();
    unreportedInactive_.clear();
    useProgram(program_.id());
    for (const auto& [name, value] : values_) apply(location(name), value);
    return true;
}

std::string Shader::takeInactiveNote() {
    if (unreportedInactive_.empty()) return {};
    std::string names;
    for (const std::string& uniform : unreportedInactive_) {
        names += (names.empty() ? "'" : ", '") + uniform + "'";
    }
    unreportedInactive_.clear();
    return "note: " + name() + ": no active uniform " + names +
           " (set, but misspelt or unused by this program)";
}

GLint Shader::location(const std::string& uniform) {
    auto found = locations_.find(uniform);
    if (found != locations_.end()) return found->second;
    const GLint where = glGetUniformLocation(program_.id(), uniform.c_str());
    // A misspelt name is a classic silent bug; it is said once (takeInactiveNote). A uniform
    // the compiler removed because it is unused also lands here.
    if (where < 0) unreportedInactive_.push_back(uniform);
    locations_.emplace(uniform, where);
    return where;
}

void Shader::apply(GLint where, const Value& value) {
    if (where < 0) return;
    std::visit(
        [where](const auto& v) {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, int>)
                glUniform1i(where, v);
            else if constexpr (std::is_same_v<T, float>)
                glUniform1f(where, v);
            else if constexpr (std::is_same_v<T, glm::vec2>)
                glUniform2fv(where, 1, glm::value_ptr(v));
            else if constexpr (std::is_same_v<T, glm::vec3>)
                glUniform3fv(where, 1, glm::value_ptr(v));
            else if constexpr (std::is_same_v<T, glm::vec4>)
                glUniform4fv(where, 1, glm::value_ptr(v));
            else if constexpr (std::is_same_v<T, glm::mat3>)
                glUniformMatrix3fv(where, 1, GL_FALSE, glm::value_ptr(v));
            else
                glUniformMatrix4fv(where, 1, GL_FALSE, glm::value_ptr(v));
        },
        value);
}

// Makes the program current first (a uniform set on the wrong program is a classic silent bug;
// useProgram skips the call when it is current already), and remembers the value for reload.
void Shader::store(const std::string& name, const Value& value) {
    useProgram(program_.id());
    apply(location(name), value);
    values_[name] = value;
}

void Shader::set(const std::string& name, int value) {
    store(name, value);
}
void Shader::set(const std::string& name, float value) {
    store(name, value);
}
void Shader::set(const std::string& name, const glm::vec2& value) {
    store(name, value);
}
void Shader::set(const std::string& name, const glm::vec3& value) {
    store(name, value);
}
void Shader::set(const std::string& name, const glm::vec4& value) {
    store(name, value);
}
void Shader::set(const std::string& name, const glm::mat3& value) {
    store(name, value);
}
void Shader::set(const std::string& name, const glm::mat4& value) {
    store(name, value);
}

void Shader::setModel(const glm::mat4& model) {
    set("model", model);
    set("normalMatrix", glm::transpose(glm::inverse(glm::mat3(model))));
}

void setPointLights(Shader& shader, std::span<const glm::vec3> positions, const glm::vec3& color) {
    shader.set("lightCount", int(positions.size()));
    for (size_t i = 0; i < positions.size(); ++i) {
        shader.set("lightPositions[" + std::to_string(i) + "]", positions[i]);
        shader.set("lightColors[" + std::to_string(i) + "]", color);
    }
}

}  // namespace pbr
