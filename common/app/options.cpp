#include "app/options.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <type_traits>

#include "base/error.h"
#include "base/paths.h"

namespace pbr {

namespace {

struct CommonFlag {
    const char* name;
    const char* valueName;  // nullptr: a switch
    const char* help;
};

constexpr CommonFlag kCommonFlags[] = {
    {"--help", nullptr, "print this help and exit (also -h)"},
    {"--headless", nullptr, "render offscreen (no window) and write the last frame to --output"},
    {"--output", "FILE.png",
     "where the last frame goes; the folder must exist (headless default: <sample>.png in the "
     "current folder; a window writes a picture only when --output is given)"},
    {"--size", "WxH", "framebuffer size in pixels, 1 to 16384 a side (default 1280x720)"},
    {"--frames", "N",
     "frames to render, then exit (default: 1 headless; with --benchmark: frames measured, "
     "default 30, after one warm-up frame)"},
    {"--time", "T", "fixed scene time in seconds (headless default 0)"},
    {"--msaa", "N",
     "samples per pixel: 0 or 1 (off), or a power of two up to what the GL allows (4 on "
     "llvmpipe); default 4"},
    {"--camera", "x,y,z[,yaw,pitch]",
     "camera start position, and yaw/pitch in degrees (default yaw -90, pitch 0)"},
    {"--fov", "DEGREES",
     "the camera's field of view, 1 to 45 (default 45; scrolling in a window changes it)"},
    {"--benchmark", nullptr, "time the frames and print one JSON line of statistics"},
    {"--panel", nullptr,
     "draw the live panel into the picture too, headless as well (a window always shows it; "
     "Tab hides it)"},
    {"--caption", nullptr,
     "under a view (--view), a caption in the picture, headless as well: the view's name, its "
     "formula and encoding, and a scale bar for mapped values (a window and a page always show "
     "it)"},
    {"--backend", "osmesa|egl|egl-software",
     "offscreen backend (implies --headless; default: the first that works of osmesa, egl); "
     "egl may pick a GPU, egl-software never does"},
};

// The browser build (gl/gl.h's PBR_WEBGL comes from the same macro; this file knows no GL): a
// page's --help lists what a page has, without the offscreen backends, the panel, the
// environment variables or the shader reload.
#ifdef __EMSCRIPTEN__
constexpr bool kInPage = true;
#else
constexpr bool kInPage = false;
#endif

constexpr int kUsageWidth = 100;    // columns the help text is wrapped to
constexpr size_t kFlagColumn = 30;  // where the help starts; a longer flag puts it on the next line

// Every bad value names its flag; the usage text is attached where the App knows the program.
[[noreturn]] void fail(const std::string& message) {
    throw UsageError(message, "");
}

#if !defined(__cpp_lib_to_chars)
// A standard library without floating-point from_chars (emscripten's libc++ 13): strtod, held to
// what from_chars takes (no leading space or '+', no hexadecimal).
bool parseFloating(const std::string& text, double& out, std::errc& error) {
    error = std::errc::invalid_argument;
    if (text.empty() || text.front() == '+' ||
        std::isspace(static_cast<unsigned char>(text.front())) ||
        text.find_first_of("xX") != std::string::npos) {
        return false;
    }
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size()) return false;
    if (errno == ERANGE && std::isinf(value)) {
        error = std::errc::result_out_of_range;
        return false;
    }
    error = std::errc();
    out = value;
    return true;
}
#endif

template <class T>
bool parseNumber(const std::string& text, T& out, std::errc& error) {
#if !defined(__cpp_lib_to_chars)
    if constexpr (std::is_floating_point_v<T>) {
        return parseFloating(text, out, error);
    } else
#endif
    {
        const char* begin = text.data();
        const char* end = begin + text.size();
        auto [ptr, ec] = std::from_chars(begin, end, out);
        error = ec;
        return ec == std::errc() && ptr == end;
    }
}

std::string formatNumber(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

// A user's text in a message, quoted, one line whatever it holds.
std::string inQuotes(const std::string& text) {
    return "'" + printable(text) + "'";
}

std::vector<double> parseNumberList(const std::string& flag, const std::string& value,
                                    double limit) {
    std::vector<double> numbers;
    std::stringstream stream(value);
    std::string part;
    while (std::getline(stream, part, ',')) {
        if (part.empty()) fail(flag + ": empty number in " + inQuotes(value));
        numbers.push_back(parseNumberFlag(flag, part, -limit, limit));
    }
    if (!value.empty() && value.back() == ',')
        fail(flag + ": trailing comma in " + inQuotes(value));
    return numbers;
}

}  // namespace

std::vector<double> parseNumbersFlag(const FlagSpec& spec, const std::string& value) {
    std::vector<double> numbers;
    std::stringstream stream(value);
    std::string part;
    while (std::getline(stream, part, ','))
        numbers.push_back(parseNumberFlag(spec.name, part, spec.min, spec.max));
    if (int(numbers.size()) != spec.count || (!value.empty() && value.back() == ',')) {
        fail(spec.name + ": " + inQuotes(value) + " is not " + spec.valueName + " (" +
             std::to_string(spec.count) + " numbers, comma-separated)");
    }
    return numbers;
}

namespace {

void checkSampleFlag(const FlagSpec& spec, const std::string& value) {
    switch (spec.kind) {
        case FlagSpec::Kind::Switch:
            break;
        case FlagSpec::Kind::Text:
        case FlagSpec::Kind::OutputFolder:
            if (value.empty()) fail(spec.name + ": empty value");
            break;
        case FlagSpec::Kind::Integer:
            parseIntFlag(spec.name, value, int(spec.min), int(spec.max));
            break;
        case FlagSpec::Kind::Number:
            parseNumberFlag(spec.name, value, spec.min, spec.max);
            break;
        case FlagSpec::Kind::Numbers:
            parseNumbersFlag(spec, value);
            break;
        case FlagSpec::Kind::Choice:
            if (std::find(spec.choices.begin(), spec.choices.end(), value) == spec.choices.end() &&
                std::none_of(spec.aliases.begin(), spec.aliases.end(),
                             [&](const auto& alias) { return alias.first == value; })) {
                // The choices as the usage lists them ("--filter trilinear|nearest").
                fail(spec.name + ": " + inQuotes(value) + " is not one of " + spec.valueName);
            }
            break;
    }
    if (spec.refuse) {
        if (const std::string why = spec.refuse(value); !why.empty()) {
            fail(spec.name + ": " + inQuotes(value) + ": " + why);
        }
    }
}

// "--size 640x360": the message says which half is wrong and why.
void parseSize(const std::string& value, Options& options) {
    const size_t x = value.find('x');
    if (x == std::string::npos || x == 0 || x + 1 == value.size() ||
        value.find('x', x + 1) != std::string::npos) {
        fail("--size: " + inQuotes(value) +
             " is not WxH (width x height in pixels, e.g. 1280x720)");
    }
    const std::string width = value.substr(0, x), height = value.substr(x + 1);
    options.width = parseIntFlag("--size", width, 1, 16384);
    options.height = parseIntFlag("--size", height, 1, 16384);
}

}  // namespace

FlagSpec FlagSpec::toggle(std::string name, std::string help) {
    return {.name = std::move(name), .help = std::move(help), .kind = Kind::Switch};
}

FlagSpec FlagSpec::text(std::string name, std::string valueName, std::string help) {
    return {.name = std::move(name),
            .valueName = std::move(valueName),
            .help = std::move(help),
            .kind = Kind::Text};
}

FlagSpec FlagSpec::outputFolder(std::string name, std::string valueName, std::string help) {
    return {.name = std::move(name),
            .valueName = std::move(valueName),
            .help = std::move(help),
            .kind = Kind::OutputFolder};
}

FlagSpec FlagSpec::integer(std::string name, std::string valueName, std::string help, int min,
                           int max, int defaultValue) {
    return {.name = std::move(name),
            .valueName = std::move(valueName),
            .help = std::move(help),
            .kind = Kind::Integer,
            .min = double(min),
            .max = double(max),
            .defaultValue = std::to_string(defaultValue)};
}

FlagSpec FlagSpec::number(std::string name, std::string valueName, std::string help, double min,
                          double max, double defaultValue) {
    return {.name = std::move(name),
            .valueName = std::move(valueName),
            .help = std::move(help),
            .kind = Kind::Number,
            .min = min,
            .max = max,
            .defaultValue = flagNumberText(defaultValue)};
}

FlagSpec FlagSpec::numbers(std::string name, std::string valueName, std::string help, int count,
                           double min, double max, std::vector<double> defaults) {
    std::string defaultText;
    for (const double value : defaults) {
        defaultText += (defaultText.empty() ? "" : ",") + flagNumberText(value);
    }
    return {.name = std::move(name),
            .valueName = std::move(valueName),
            .help = std::move(help),
            .kind = Kind::Numbers,
            .min = min,
            .max = max,
            .count = count,
            .defaultValue = std::move(defaultText)};
}

FlagSpec FlagSpec::choice(std::string name, std::vector<std::string> choices, std::string help) {
    std::string valueName;
    for (const std::string& choice : choices) valueName += (valueName.empty() ? "" : "|") + choice;
    return {.name = std::move(name),
            .valueName = std::move(valueName),
            .help = std::move(help),
            .kind = Kind::Choice,
            .choices = std::move(choices)};
}

FlagSpec FlagSpec::withAliases(std::vector<std::pair<std::string, std::string>> words) const {
    FlagSpec spec = *this;
    spec.aliases = std::move(words);
    return spec;
}

FlagSpec FlagSpec::asLive() const {
    FlagSpec spec = *this;
    spec.live = true;
    return spec;
}

FlagSpec FlagSpec::withoutDefault() const {
    FlagSpec spec = *this;
    spec.defaultValue.clear();
    return spec;
}

FlagSpec FlagSpec::refusing(std::function<std::string(const std::string& value)> why) const {
    FlagSpec spec = *this;
    spec.refuse = std::move(why);
    return spec;
}

namespace {
// The shortest of %.1g ... %.<most>g that `same` takes for the value, with at least the digits
// of its whole part, so that -90 stays -90 (not -9e+01).
template <typename Same>
std::string shortestText(double value, int most, Same same) {
    const double magnitude = std::abs(value);
    const int wholeDigits =
        magnitude >= 1.0 && magnitude < 1e17 ? int(std::floor(std::log10(magnitude))) + 1 : 1;
    char text[32];
    for (int digits = 1; digits <= most; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", std::max(digits, wholeDigits), value);
        if (same(std::strtod(text, nullptr))) break;
    }
    return text;
}
}  // namespace

std::string flagNumberText(double value) {
    return shortestText(value, 17, [&](double read) { return read == value; });
}

std::string flagNumberText(float value) {
    // read as the flags read it: a double, then stored as a float
    return shortestText(double(value), 9, [&](double read) { return float(read) == value; });
}

int parseIntFlag(const std::string& flag, const std::string& value, int min, int max) {
    long long number = 0;
    std::errc error{};
    if (!parseNumber(value, number, error)) {
        if (error == std::errc::result_out_of_range) {
            fail(flag + ": " + printable(value) + " is out of range [" + std::to_string(min) +
                 ", " + std::to_string(max) + "]");
        }
        fail(flag + ": " + inQuotes(value) + " is not a whole number");
    }
    if (number < min || number > max) {
        fail(flag + ": " + value + " is out of range [" + std::to_string(min) + ", " +
             std::to_string(max) + "]");
    }
    return int(number);
}

double parseNumberFlag(const std::string& flag, const std::string& value, double min, double max) {
    double number = 0;
    std::errc error{};
    const std::string range =
        std::string("[").append(formatNumber(min)).append(", ").append(formatNumber(max)) + "]";
    if (!parseNumber(value, number, error)) {
        if (error == std::errc::result_out_of_range) {
            fail(flag + ": " + printable(value) + " is out of range " + range);
        }
        fail(flag + ": " + inQuotes(value) + " is not a number");
    }
    if (!std::isfinite(number)) fail(flag + ": " + inQuotes(value) + " is not a finite number");
    if (number < min || number > max) fail(flag + ": " + value + " is out of range " + range);
    return number;
}

Options parseOptions(std::span<const std::string> args, std::span<const FlagSpec> sampleFlags) {
    Options options;
    for (size_t i = 0; i < args.size(); ++i) {
        std::string flag = args[i];
        std::optional<std::string> inlineValue;
        if (auto eq = flag.find('='); flag.rfind("--", 0) == 0 && eq != std::string::npos) {
            inlineValue = flag.substr(eq + 1);
            flag = flag.substr(0, eq);
        }
        if (flag == "-h") flag = "--help";
        if (flag.rfind("--", 0) != 0) fail("unexpected argument " + inQuotes(flag));

        const CommonFlag* common = nullptr;
        for (const CommonFlag& candidate : kCommonFlags) {
            if (flag == candidate.name) common = &candidate;
        }
        const FlagSpec* own = nullptr;
        for (const FlagSpec& candidate : sampleFlags) {
            if (flag == candidate.name) own = &candidate;
        }
        if (!common && !own) fail("unknown flag " + inQuotes(flag));

        const bool takesValue = common ? common->valueName != nullptr : !own->valueName.empty();
        std::string value;
        if (takesValue) {
            if (inlineValue) {
                value = *inlineValue;
            } else if (i + 1 < args.size()) {
                value = args[++i];
            } else {
                fail(flag + ": missing value");
            }
        } else if (inlineValue) {
            fail(flag + ": takes no value");
        }

        if (own) {
            checkSampleFlag(*own, value);
            for (const auto& [alias, choice] : own->aliases) {
                if (value == alias) value = choice;  // kept as the word the sample knows
            }
            options.sampleFlags[flag] = value;
        } else if (flag == "--help") {
            options.help = true;
        } else if (flag == "--headless") {
            options.headless = true;
        } else if (flag == "--fov") {
            options.fov = parseNumberFlag("--fov", value, 1.0, 45.0);
        } else if (flag == "--caption") {
            options.caption = true;
        } else if (flag == "--panel") {
            options.panel = true;
        } else if (flag == "--benchmark") {
            options.benchmark = true;
        } else if (flag == "--output") {
            if (value.empty()) fail("--output: empty file name");
            options.output = value;
        } else if (flag == "--size") {
            parseSize(value, options);
        } else if (flag == "--frames") {
            options.frames = parseIntFlag("--frames", value, 1, 1000000);
        } else if (flag == "--time") {
            options.time = parseNumberFlag("--time", value, -1.0e6, 1.0e6);
        } else if (flag == "--msaa") {
            const int samples = parseIntFlag("--msaa", value, 0, kMaxMsaaSamples);
            if (samples > 1 && (samples & (samples - 1)) != 0) {
                fail("--msaa: " + value + " is not 0, 1 or a power of two");
            }
            options.msaa = samples <= 1 ? 0 : samples;
        } else if (flag == "--backend") {
            if (value != "osmesa" && value != "egl" && value != "egl-software") {
                fail("--backend: " + inQuotes(value) + " is not osmesa, egl or egl-software");
            }
            options.backend = value;
            options.headless = true;
        } else if (flag == "--camera") {
            const std::vector<double> numbers =
                parseNumberList("--camera", value, kMaxCameraCoordinate);
            if (numbers.size() != 3 && numbers.size() != 5) {
                fail("--camera: " + inQuotes(value) + " is not x,y,z or x,y,z,yaw,pitch");
            }
            CameraStart start{float(numbers[0]), float(numbers[1]), float(numbers[2]), {}, {}};
            if (numbers.size() == 5) {
                start.yaw = float(numbers[3]);
                start.pitch = float(numbers[4]);
                if (std::abs(numbers[4]) > 89.0) fail("--camera: pitch must lie in [-89, 89]");
            }
            options.camera = start;
        }
    }
    return options;
}

namespace {

// "  --name VALUE" then the help, wrapped at kUsageWidth, every line of it starting at
// kFlagColumn; a left part too long for the column puts the help on the line below.
void usageLine(std::ostringstream& out, const std::string& left, const std::string& help) {
    std::string line = "  " + left;
    if (line.size() + 2 > kFlagColumn) {
        out << line << "\n";
        line.clear();
    }
    line.resize(kFlagColumn, ' ');
    std::istringstream words(help);
    std::string word;
    bool first = true;
    while (words >> word) {
        if (!first && line.size() + 1 + word.size() > size_t(kUsageWidth)) {
            out << line << "\n";
            line = std::string(kFlagColumn, ' ');
            first = true;
        }
        line += (first ? "" : " ") + word;
        first = false;
    }
    out << line << "\n";
}

}  // namespace

std::string usageText(const std::string& program, std::span<const FlagSpec> sampleFlags,
                      bool orbitCamera) {
    std::ostringstream out;
    out << "usage: " << program << " [flags]\n\nflags every sample takes:\n";
    for (const CommonFlag& flag : kCommonFlags) {
        if (kInPage &&
            (std::string(flag.name) == "--backend" || std::string(flag.name) == "--panel" ||
             std::string(flag.name) == "--caption"))
            continue;
        std::string left = flag.name;
        if (flag.valueName) left.append(" ").append(flag.valueName);
        usageLine(out, left, flag.help);
    }
    if (!sampleFlags.empty()) {
        out << "\nflags of " << program << ":\n";
        for (const FlagSpec& flag : sampleFlags) {
            const bool saysDefault =
                !flag.defaultValue.empty() && flag.kind != FlagSpec::Kind::Choice;
            std::string also;
            for (const auto& [alias, choice] : flag.aliases)
                also += (also.empty() ? "; " : ", ") + alias + " is " + choice;
            usageLine(
                out, flag.name + (flag.valueName.empty() ? "" : " " + flag.valueName),
                flag.help + (saysDefault ? " (default " + flag.defaultValue + ")" : "") + also);
        }
    }
    if (kInPage) {
        out << (orbitCamera ? "\nthis sample's camera orbits the model's centre: --camera takes "
                              "x,y,z only\nin the page: drag (left button) orbit, scroll dolly\n"
                            : "\nin the page: click the picture to look around, WASD move, scroll "
                              "zoom;\n  the controls under the picture change the live flags\n");
        return out.str();
    }
    out << "\nenvironment:\n";
    for (const EnvironmentVariable& variable : environmentVariables()) {
        usageLine(out, variable.name, variable.meaning);
    }
    if (orbitCamera) {
        out << "\nthis sample's camera orbits the model's centre: --camera takes x,y,z only\n"
               "keys in a window: drag (left button) orbit, scroll dolly, Tab hide or show the "
               "panel,\n  F12 screenshot, R reload shaders, Esc quit\n";
    } else {
        out << "\nkeys in a window: WASD move, drag (left button) look, scroll zoom, Tab hide or "
               "show the\n  panel (hidden: the mouse looks), F12 screenshot, R reload shaders, Esc "
               "quit\n";
    }
    return out.str();
}

}  // namespace pbr
