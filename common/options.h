#pragma once
// The command line every sample shares (see DESIGN.md), plus the flags a sample adds of its own.
// Pure: no GL, no window, so it is unit tested directly.
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace pbr {

// A flag a sample adds: "--lights" with value name "N", or a switch when valueName is empty.
struct FlagSpec {
    std::string name;
    std::string valueName;
    std::string help;
};

// --camera x,y,z[,yaw,pitch]: a start pose for the fly camera (yaw/pitch in degrees).
struct CameraStart {
    float x = 0, y = 0, z = 0;
    std::optional<float> yaw, pitch;
};

struct Options {
    bool help = false;
    bool headless = false;
    bool benchmark = false;
    std::string output;  // empty: "<sample>.png" in the working directory
    int width = 1280, height = 720;
    std::optional<int> frames;   // unset: 1 headless, until closed in a window, 30 for --benchmark
    std::optional<double> time;  // fixed scene time; headless default 0
    int msaa = 4;                // samples per pixel; 0 or 1 turns multisampling off
    std::optional<CameraStart> camera;
    std::string backend;  // offscreen backend: "osmesa", "egl", or "" (automatic)
    std::map<std::string, std::string> sampleFlags;  // "--lights" -> "3"; switches -> ""

    bool has(const std::string& flag) const { return sampleFlags.count(flag) != 0; }
};

// Parses argv[1..]. Throws UsageError (message names the flag and the reason) on a bad flag.
Options parseOptions(std::span<const std::string> args, std::span<const FlagSpec> sampleFlags);

// The usage text: every common flag and the sample's own, one a line.
std::string usageText(const std::string& program, std::span<const FlagSpec> sampleFlags);

// Helpers for sample flags, throwing UsageError naming the flag when the value is bad.
int parseIntFlag(const std::string& flag, const std::string& value, int min, int max);
float parseFloatFlag(const std::string& flag, const std::string& value);

}  // namespace pbr
