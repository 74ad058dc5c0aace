#include "options.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "error.h"

namespace pbr {

namespace {

struct CommonFlag {
    const char* name;
    const char* valueName;  // nullptr: a switch
    const char* help;
};

constexpr CommonFlag kCommonFlags[] = {
    {"--help", nullptr, "print this help and exit"},
    {"--headless", nullptr, "render offscreen (no window) and write the last frame to --output"},
    {"--output", "FILE.png", "where the headless frame goes (default: <sample>.png)"},
    {"--size", "WxH", "framebuffer size in pixels (default 1280x720)"},
    {"--frames", "N",
     "frames to render, then exit (default: 1 headless; with --benchmark: frames\n"
     "                            measured, default 30, after one warm-up frame)"},
    {"--time", "T", "fixed scene time in seconds (headless default 0)"},
    {"--msaa", "N", "samples per pixel: 0/1 (off), 2, 4, 8 (default 4)"},
    {"--camera", "x,y,z[,yaw,pitch]", "camera start position (and yaw/pitch in degrees)"},
    {"--benchmark", nullptr, "time the frames and print one JSON line of statistics"},
    {"--backend", "osmesa|egl",
     "offscreen backend (implies --headless; default: the first that works)"},
};

// Every bad value names its flag; the usage text is attached where the App knows the program.
[[noreturn]] void fail(const std::string& message) {
    throw UsageError(message, "");
}

template <class T>
bool parseNumber(const std::string& text, T& out) {
    const char* begin = text.data();
    const char* end = begin + text.size();
    auto [ptr, ec] = std::from_chars(begin, end, out);
    return ec == std::errc() && ptr == end;
}

std::vector<float> parseFloatList(const std::string& flag, const std::string& value) {
    std::vector<float> numbers;
    std::stringstream stream(value);
    std::string part;
    while (std::getline(stream, part, ',')) numbers.push_back(parseFloatFlag(flag, part));
    if (!value.empty() && value.back() == ',') fail(flag + ": trailing comma in '" + value + "'");
    return numbers;
}

}  // namespace

int parseIntFlag(const std::string& flag, const std::string& value, int min, int max) {
    int number = 0;
    if (!parseNumber(value, number)) fail(flag + ": '" + value + "' is not a whole number");
    if (number < min || number > max) {
        fail(flag + ": " + value + " is out of range [" + std::to_string(min) + ", " +
             std::to_string(max) + "]");
    }
    return number;
}

float parseFloatFlag(const std::string& flag, const std::string& value) {
    float number = 0;
    if (!parseNumber(value, number) || !std::isfinite(number)) {
        fail(flag + ": '" + value + "' is not a number");
    }
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
        if (flag.rfind("--", 0) != 0) fail("unexpected argument '" + flag + "'");

        const CommonFlag* common = nullptr;
        for (const CommonFlag& candidate : kCommonFlags) {
            if (flag == candidate.name) common = &candidate;
        }
        const FlagSpec* own = nullptr;
        for (const FlagSpec& candidate : sampleFlags) {
            if (flag == candidate.name) own = &candidate;
        }
        if (!common && !own) fail("unknown flag '" + flag + "'");

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
            options.sampleFlags[flag] = value;
        } else if (flag == "--help") {
            options.help = true;
        } else if (flag == "--headless") {
            options.headless = true;
        } else if (flag == "--benchmark") {
            options.benchmark = true;
        } else if (flag == "--output") {
            if (value.empty()) fail("--output: empty file name");
            options.output = value;
        } else if (flag == "--size") {
            auto x = value.find('x');
            if (x == std::string::npos) fail("--size: '" + value + "' is not WxH");
            options.width = parseIntFlag("--size", value.substr(0, x), 1, 16384);
            options.height = parseIntFlag("--size", value.substr(x + 1), 1, 16384);
        } else if (flag == "--frames") {
            options.frames = parseIntFlag("--frames", value, 1, 1000000);
        } else if (flag == "--time") {
            options.time = parseFloatFlag("--time", value);
        } else if (flag == "--msaa") {
            int samples = parseIntFlag("--msaa", value, 0, 16);
            if (samples > 1 && (samples & (samples - 1)) != 0) {
                fail("--msaa: " + value + " is not 0, 1 or a power of two");
            }
            options.msaa = samples <= 1 ? 0 : samples;
        } else if (flag == "--backend") {
            if (value != "osmesa" && value != "egl") {
                fail("--backend: '" + value + "' is not osmesa or egl");
            }
            options.backend = value;
            options.headless = true;
        } else if (flag == "--camera") {
            std::vector<float> numbers = parseFloatList("--camera", value);
            if (numbers.size() != 3 && numbers.size() != 5) {
                fail("--camera: '" + value + "' is not x,y,z or x,y,z,yaw,pitch");
            }
            CameraStart start{numbers[0], numbers[1], numbers[2], {}, {}};
            if (numbers.size() == 5) {
                start.yaw = numbers[3];
                start.pitch = numbers[4];
                if (std::abs(numbers[4]) > 89.0f) fail("--camera: pitch must lie in [-89, 89]");
            }
            options.camera = start;
        }
    }
    return options;
}

std::string usageText(const std::string& program, std::span<const FlagSpec> sampleFlags) {
    std::ostringstream out;
    out << "usage: " << program << " [flags]\n";
    auto line = [&](const std::string& name, const std::string& valueName,
                    const std::string& help) {
        std::string left = "  " + name + (valueName.empty() ? "" : " " + valueName);
        if (left.size() < 28)
            left.resize(28, ' ');
        else
            left += ' ';
        out << left << help << "\n";
    };
    for (const CommonFlag& flag : kCommonFlags) {
        line(flag.name, flag.valueName ? flag.valueName : "", flag.help);
    }
    for (const FlagSpec& flag : sampleFlags) line(flag.name, flag.valueName, flag.help);
    out << "keys: WASD move, mouse look, scroll zoom, F12 screenshot, R reload shaders, Esc quit\n";
    return out.str();
}

}  // namespace pbr
