#pragma once
// The command line every sample shares (see DESIGN.md), plus the flags a sample adds of its own.
// A sample's flags say what values they take, so that parseOptions checks every flag, common or
// the sample's own, before any window or GL context exists. Pure: no GL, no window, so it is
// unit tested directly.
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace pbr {

// A flag a sample adds, made with one of the functions below: "--lights N" (a whole number in a
// range), "--filter trilinear|nearest" (one of some words), "--model FILE" (any text), a switch.
// The one declaration of a parameter: it is the command-line flag, its line in --help, and its
// control in the window's live panel (app/panel.h): a number a slider, an integer a stepper, a
// choice a combo box, a switch a checkbox. A flag the sample reads every frame is `live` (see
// asLive); the others are read once at start-up, and the panel shows them without a control.
struct FlagSpec {
    enum class Kind { Switch, Text, OutputFolder, Integer, Number, Numbers, Choice };
    std::string name{};       // "--lights"
    std::string valueName{};  // "N", "FILE", "a|b"; empty for a switch
    std::string help{};
    Kind kind = Kind::Text;
    double min = 0.0, max = 0.0;  // Integer, Number(s): the allowed range, both ends included
    int count = 0;                // Numbers: how many, comma-separated
    std::vector<std::string> choices{};  // Choice: the allowed words; the first is the default
    // Choice: other words for some of them, {alias, choice} (07's --view albedo is base-color):
    // taken as the choice they stand for, and listed by --help.
    std::vector<std::pair<std::string, std::string>> aliases{};
    // The value when the flag is not given, as its text ("4", "0.5", "1,0.7,1.8"): Integer,
    // Number and Numbers (where it is empty, the sample has no single default). --help says it.
    std::string defaultValue{};
    bool live = false;  // the sample reads it every frame: the panel may change it while it runs
    // A check of the sample's own beyond the kind's (09: not all three attenuation terms 0):
    // returns why a value is refused, or "". Run wherever a value comes from: the command line,
    // the panel, the page.
    std::function<std::string(const std::string& value)> refuse{};

    static FlagSpec toggle(std::string name, std::string help);
    static FlagSpec text(std::string name, std::string valueName, std::string help);
    // A folder the sample writes files into: it must exist (checked before rendering).
    static FlagSpec outputFolder(std::string name, std::string valueName, std::string help);
    static FlagSpec integer(std::string name, std::string valueName, std::string help, int min,
                            int max, int defaultValue);
    static FlagSpec number(std::string name, std::string valueName, std::string help, double min,
                           double max, double defaultValue);
    // "--attenuation 1,0.7,1.8": exactly `count` numbers, each in [min, max]; `defaults` has
    // `count` numbers, or none.
    static FlagSpec numbers(std::string name, std::string valueName, std::string help, int count,
                            double min, double max, std::vector<double> defaults = {});
    static FlagSpec choice(std::string name, std::vector<std::string> choices, std::string help);

    // The same flag, read by the sample every frame (so the panel's control for it is live).
    FlagSpec asLive() const;
    // The same choice flag, with other words for some of its choices.
    FlagSpec withAliases(std::vector<std::pair<std::string, std::string>> words) const;
    // The same number flag without a default: not given, the sample keeps a value of its own (10's
    // --clearcoat: each material's factor from its file). The panel and the page show it unset
    // until a value is chosen, and can unset it again.
    FlagSpec withoutDefault() const;
    // The same flag with a check of its own (see `refuse`).
    FlagSpec refusing(std::function<std::string(const std::string& value)> why) const;
};

// A number as a flag's text: the shortest that reads back as the same double ("0.3", "1e-05"),
// or, for a float, as the same float (2.2f is "2.2", not "2.200000047683716").
std::string flagNumberText(double value);
std::string flagNumberText(float value);

// --camera x,y,z[,yaw,pitch]: a start pose for the fly camera (yaw/pitch in degrees).
struct CameraStart {
    float x = 0, y = 0, z = 0;
    std::optional<float> yaw, pitch;
};

struct Options {
    bool help = false;
    bool headless = false;
    bool benchmark = false;
    bool panel = false;    // --panel: the live panel drawn into the picture, headless too
    bool caption = false;  // --caption: a view's caption drawn into the picture, headless too
    std::string output;    // empty: "<sample>.png" in the working directory
    int width = 1280, height = 720;
    std::optional<int> frames;   // unset: 1 headless, until closed in a window, 30 for --benchmark
    std::optional<double> time;  // fixed scene time; headless default 0
    int msaa = 4;                // samples per pixel; 0 or 1 turns multisampling off
    std::optional<CameraStart> camera;
    std::optional<double> fov;  // --fov: the fly camera's field of view in degrees
    std::string backend;        // offscreen backend: "osmesa", "egl", or "" (automatic)
    std::map<std::string, std::string> sampleFlags;  // "--lights" -> "3"; switches -> ""

    bool has(const std::string& flag) const { return sampleFlags.count(flag) != 0; }
};

// The largest --msaa the parser takes; the GL's own limit (4 on llvmpipe) is checked when the
// render target is made.
inline constexpr int kMaxMsaaSamples = 64;
// --camera coordinates beyond this are refused: the view would hold nothing (far plane 100).
inline constexpr double kMaxCameraCoordinate = 1.0e6;

// Parses argv[1..]. Every value is checked here, the sample's own flags included. Throws
// UsageError (the message names the flag and the reason) on the first bad flag.
Options parseOptions(std::span<const std::string> args, std::span<const FlagSpec> sampleFlags);

// The usage text: the common flags and the sample's own in two aligned columns, the environment
// variables the suite reads, and the keys.
// `orbitCamera`: the sample looks at a model through an orbit camera (07, 08): --camera takes
// x,y,z only, and the keys differ.
std::string usageText(const std::string& program, std::span<const FlagSpec> sampleFlags,
                      bool orbitCamera = false);

// Helpers for flag values, throwing UsageError naming the flag when the value is bad.
int parseIntFlag(const std::string& flag, const std::string& value, int min, int max);
double parseNumberFlag(const std::string& flag, const std::string& value, double min, double max);
// The numbers of a FlagSpec::numbers flag (throws UsageError naming the flag).
std::vector<double> parseNumbersFlag(const FlagSpec& spec, const std::string& value);

}  // namespace pbr
