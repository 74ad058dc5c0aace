#pragma once
// A GLSL program from files: `#include "file"` (searched beside the including file, then in
// shaders/include/), compile errors reported as `file:line: message` in the original file,
// cached uniform locations, and reload (on R) that keeps the uniform values already set.
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <unordered_map>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "gl/gl.h"

namespace pbr {

// The text handed to the compiler and the files it came from: line L of files[n] carries the
// line number n * 10000 + L in `text` (see mapShaderLog).
struct ShaderSource {
    std::string text;
    std::vector<std::filesystem::path> files;
};

// Expands #include directives (each file once, cycles refused) and numbers the lines so that a
// compiler message leads back to the file. Pure: no GL.
// Throws Error("<file>:<line>: <reason>") for a missing include, a cycle, a bad directive or a
// file of more than 9999 lines (line 10000 would be numbered as the next file's).
ShaderSource preprocessShader(const std::filesystem::path& file,
                              const std::filesystem::path& includeDir);

// The shader for WebGL 2: `#version 330 core` (the first line of every shader of the suite)
// becomes `#version 300 es` with highp precision for floats, ints and samplers, and nothing else
// changes (the line numbers stay the file's). Throws Error("<file>:1: ...") for any other first
// line. Pure: the browser build uses it, the native tests check it.
std::string toGlslEs(const std::string& text, const std::filesystem::path& file);

// Rewrites a driver's info log ("0:12(5): error: ..." from Mesa, "0(12) : error ..." from
// NVIDIA, "ERROR: 0:12: ..." from ANGLE, the browsers' GLSL compiler) into
// "<file>:<line>: error: ..." lines of the original files.
std::vector<std::string> mapShaderLog(const std::string& log,
                                      const std::vector<std::filesystem::path>& files);

class Shader {
public:
    // Paths relative to shaderDir() (or absolute). `defines` are #defined (as 1) in both stages,
    // ahead of the files' text (the term views' TERM_VIEWS). Throws Error on any compile or link
    // failure.
    Shader(std::filesystem::path vertexPath, std::filesystem::path fragmentPath,
           std::vector<std::string> defines = {});

    void use() const;
    // Builds the program again from the files. On failure prints the error, keeps the old
    // program and returns false. On success re-applies every uniform value set so far.
    bool reload();

    void set(const std::string& name, int value);
    void set(const std::string& name, float value);
    void set(const std::string& name, const glm::vec2& value);
    void set(const std::string& name, const glm::vec3& value);
    void set(const std::string& name, const glm::vec4& value);
    void set(const std::string& name, const glm::mat3& value);
    void set(const std::string& name, const glm::mat4& value);
    // "model" and its "normalMatrix" (transpose(inverse(mat3(model))), right for any model matrix).
    void setModel(const glm::mat4& model);

    GLuint id() const { return program_.id(); }
    std::string name() const;

    // The uniforms set on this program that it does not have (misspelt, or unused by this code
    // and removed by the compiler), not yet reported: one note line naming them all, or "" when
    // there are none. The App prints it after each frame, so a reload or a new view gives one
    // line, not one per uniform.
    std::string takeInactiveNote();

private:
    using Value = std::variant<int, float, glm::vec2, glm::vec3, glm::vec4, glm::mat3, glm::mat4>;
    GLint location(const std::string& uniform);
    void apply(GLint location, const Value& value);
    void store(const std::string& name, const Value& value);

    std::filesystem::path vertexPath_, fragmentPath_;
    std::vector<std::string> defines_;
    GlProgram program_;
    std::unordered_map<std::string, GLint> locations_;
    std::vector<std::string> unreportedInactive_;
    std::map<std::string, Value> values_;
};

// Sets the shaders' lightCount, lightPositions[i] and lightColors[i] (see shaders/01_lighting).
void setPointLights(Shader& shader, std::span<const glm::vec3> positions, const glm::vec3& color);

}  // namespace pbr
