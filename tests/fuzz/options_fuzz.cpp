// The command line (app/options.h, parseOptions) with a sample's own flags of every kind: any
// arguments (the input cut at each '\0') either give Options within every flag's range, or are
// refused with a UsageError whose message is one line naming the flag or argument at fault.
// The usage text of the same flags lists each of them.
#include <algorithm>

#include "app/options.h"
#include "fuzz_check.h"

namespace pbr::fuzz {

// One flag of each kind and a check of a sample's own, as the samples declare theirs.
const std::vector<FlagSpec>& sampleFlags() {
    static const std::vector<FlagSpec> flags = {
        FlagSpec::toggle("--no-cache", "compute the maps again"),
        FlagSpec::text("--hdr", "FILE", "an equirectangular .hdr environment"),
        FlagSpec::outputFolder("--output-dir", "DIR", "where the maps go"),
        FlagSpec::integer("--lights", "N", "how many lights", 0, 4, 4).asLive(),
        FlagSpec::number("--roughness-offset", "R", "added to every roughness", -1.0, 1.0, 0.0)
            .asLive(),
        FlagSpec::numbers("--attenuation", "C,L,Q", "the light's falloff", 3, 0.0, 10.0,
                          {1.0, 0.7, 1.8})
            .refusing([](const std::string& value) {
                const std::vector<double> terms =
                    parseNumbersFlag(sampleFlags()[5], value);  // already checked: 3 numbers
                return terms[0] == 0.0 && terms[1] == 0.0 && terms[2] == 0.0
                           ? "all three terms are 0 (the light would be infinite)"
                           : "";
            }),
        FlagSpec::choice("--filter", {"trilinear", "nearest"}, "how textures are sampled"),
        // without a default (10's layer factors: each material's own unless given)
        FlagSpec::number("--clearcoat", "F", "the clear coat's factor", 0.0, 1.0, 0.0)
            .withoutDefault()
            .asLive(),
        FlagSpec::numbers("--sheen-color", "R,G,B", "the sheen's colour", 3, 0.0, 1.0).asLive(),
    };
    return flags;
}

bool startsWith(const std::string& text, std::string_view start) {
    return text.rfind(start, 0) == 0;
}

void expectInRange(const Options& options) {
    expect(options.width >= 1 && options.width <= 16384 && options.height >= 1 &&
               options.height <= 16384,
           "a size of 1 to 16384 a side");
    expect(options.msaa == 0 || (options.msaa >= 2 && options.msaa <= kMaxMsaaSamples &&
                                 (options.msaa & (options.msaa - 1)) == 0),
           "--msaa off or a power of two");
    expect(!options.frames || (*options.frames >= 1 && *options.frames <= 1000000),
           "--frames in range");
    expect(!options.time || (std::isfinite(*options.time) && std::abs(*options.time) <= 1.0e6),
           "--time finite");
    expect(!options.fov || (*options.fov >= 1.0 && *options.fov <= 45.0), "--fov in range");
    if (const std::optional<CameraStart>& camera = options.camera) {
        for (const float v : {camera->x, camera->y, camera->z})
            expect(std::isfinite(v) && std::abs(v) <= kMaxCameraCoordinate, "--camera finite");
        expect(camera->yaw.has_value() == camera->pitch.has_value(), "yaw with pitch");
        if (camera->pitch) {
            expect(std::isfinite(*camera->yaw) && std::abs(*camera->pitch) <= 89.0f,
                   "--camera yaw finite, pitch within 89 degrees");
        }
    }
    expect(options.backend.empty() || options.headless, "--backend implies --headless");
    // Each of the sample's flags holds a value its own declaration takes.
    for (const auto& [flag, value] : options.sampleFlags) {
        const auto& flags = sampleFlags();
        const auto spec = std::find_if(flags.begin(), flags.end(),
                                       [&](const FlagSpec& s) { return s.name == flag; });
        expect(spec != flags.end(), "only the sample's own flags are kept as its flags");
        const std::vector<std::string> again = {flag, value};
        if (spec->kind == FlagSpec::Kind::Switch) {
            expect(value.empty(), "a switch holds no value");
        } else if (!reads<UsageError>("", [&] { parseOptions(again, flags); })) {
            finding("a kept value of " + flag + " that the parser refuses on its own");
        }
    }
}

}  // namespace pbr::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace pbr;
    const std::vector<std::string> args = fuzz::split(fuzz::bytesOf(data, size), '\0');
    Options options;
    std::string refusal;
    try {
        options = parseOptions(args, fuzz::sampleFlags());
    } catch (const UsageError& e) {
        refusal = e.what();
        fuzz::expectOneLine(refusal, "");
        // It names what is wrong: a flag ("--size: ..."), or the argument it does not know.
        fuzz::expect(fuzz::startsWith(refusal, "--") ||
                         fuzz::startsWith(refusal, "unexpected argument '") ||
                         fuzz::startsWith(refusal, "unknown flag '"),
                     "a refusal names the flag or argument: " + refusal);
    } catch (const std::exception& e) {
        fuzz::finding(std::string("not a UsageError but ") + fuzz::typeName(typeid(e)) + ": " +
                      e.what());
    }
    if (refusal.empty()) fuzz::expectInRange(options);
    // The usage, as a sample's --help prints it, for a program named by the first argument.
    const std::string program = args.empty() ? "fuzz_options" : args.front();
    const std::string usage = usageText(program, fuzz::sampleFlags(), size % 2 == 1);
    for (const FlagSpec& flag : fuzz::sampleFlags())
        fuzz::expect(usage.find("\n  " + flag.name) != std::string::npos,
                     "--help lists " + flag.name);
    return 0;
}
