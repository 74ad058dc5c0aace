// The recipe for the project's own HDR environment (for the image-based lighting samples):
//   make_environment OUT.hdr [--width W] [--preview PREVIEW.png]
// An equirectangular Radiance .hdr (2:1, row 0 = straight up): a clear sky, darker blue at the
// zenith, pale at the horizon, with a sun about 5,000 times brighter than the sky, and below the
// horizon a sunlit checkerboard ground, so reflections read as "sky above, tiles below, a sun".
// Deterministic: the same bytes every run. --preview writes it tone-mapped (Reinhard, gamma 2.2).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "app/options.h"
#include "base/error.h"
#include "files/image.h"

namespace {

constexpr float kPi = 3.14159265358979f;

// The sun: 35 degrees up, towards -Z rotated 30 degrees (in front of the samples' camera, up left).
const glm::vec3 kSunDirection = glm::normalize(glm::vec3(
    -std::sin(0.52f) * std::cos(0.61f), std::sin(0.61f), -std::cos(0.52f) * std::cos(0.61f)));
constexpr float kSunAngularRadius = 0.0233f;  // about 1.3 degrees: a few texels wide at 2048
const glm::vec3 kSunRadiance(5200.0f, 4900.0f, 4400.0f);

glm::vec3 sky(const glm::vec3& d) {
    const float up = std::max(d.y, 0.0f);
    const glm::vec3 horizon(1.10f, 1.25f, 1.45f), zenith(0.18f, 0.36f, 0.85f);
    glm::vec3 color = glm::mix(horizon, zenith, std::pow(up, 0.45f));
    const float toSun = std::acos(std::clamp(glm::dot(d, kSunDirection), -1.0f, 1.0f));
    color += glm::vec3(40.0f, 34.0f, 24.0f) * std::exp(-toSun * 18.0f);  // the glow around the sun
    if (toSun < kSunAngularRadius) color = kSunRadiance;
    return color;
}

glm::vec3 ground(const glm::vec3& d) {
    // a plane 1.5 units below the viewer, tiles 1 unit wide
    const float distance = 1.5f / std::max(-d.y, 1e-4f);
    const float x = d.x * distance, z = d.z * distance;
    const bool dark = (int(std::floor(x)) + int(std::floor(z))) % 2 != 0;
    const glm::vec3 light(0.55f, 0.50f, 0.44f), terracotta(0.42f, 0.16f, 0.08f);
    // far tiles blend to their average before they alias at the horizon
    const float fade = std::clamp((distance - 12.0f) / 30.0f, 0.0f, 1.0f);
    const glm::vec3 albedo = glm::mix(dark ? terracotta : light, 0.5f * (light + terracotta), fade);
    // lit by the sun (cosine of its elevation) and the sky (about pi x 1 over the hemisphere)
    const glm::vec3 irradiance =
        kSunRadiance * (kPi * kSunAngularRadius * kSunAngularRadius) * kSunDirection.y +
        glm::vec3(2.2f, 2.5f, 3.0f);
    const float haze = std::clamp((distance - 4.0f) / 120.0f, 0.0f, 0.6f);
    return glm::mix(albedo * irradiance / kPi, glm::vec3(1.0f, 1.1f, 1.25f), haze);
}

}  // namespace

int main(int argc, char** argv) try {
    const std::string usage =
        "usage: make_environment OUT.hdr [--width W] [--preview PREVIEW.png]\n";
    std::string out, preview;
    int width = 2048;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--width" && i + 1 < argc) {
            width = pbr::parseIntFlag("--width", argv[++i], 64, 16384);
            if (width % 2) throw pbr::UsageError("--width must be even", usage);
        } else if (arg == "--preview" && i + 1 < argc) {
            preview = argv[++i];
        } else if (out.empty() && arg.rfind("--", 0) != 0) {
            out = arg;
        } else {
            throw pbr::UsageError("unexpected argument '" + arg + "'", usage);
        }
    }
    if (out.empty()) throw pbr::UsageError("no output file", usage);

    const int height = width / 2;
    pbr::HdrImage image{width, height, std::vector<float>(size_t(width) * size_t(height) * 3)};
    constexpr int kSamples = 4;  // 4 x 4 sub-texel samples: a smooth sun edge and tile borders
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            glm::vec3 sum(0.0f);
            for (int sy = 0; sy < kSamples; ++sy) {
                for (int sx = 0; sx < kSamples; ++sx) {
                    // LearnOpenGL's equirectangular convention: u = atan2(z, x) / (2 pi) + 0.5,
                    // v = asin(y) / pi + 0.5; v = 1 (straight up) is the file's top row
                    const float u = (float(x) + (float(sx) + 0.5f) / kSamples) / float(width);
                    const float v =
                        1.0f - (float(y) + (float(sy) + 0.5f) / kSamples) / float(height);
                    const float phi = (u - 0.5f) * 2.0f * kPi, theta = (v - 0.5f) * kPi;
                    const glm::vec3 d(std::cos(theta) * std::cos(phi), std::sin(theta),
                                      std::cos(theta) * std::sin(phi));
                    sum += d.y >= 0.0f ? sky(d) : ground(d);
                }
            }
            const glm::vec3 color = sum / float(kSamples * kSamples);
            const size_t i = (size_t(y) * size_t(width) + size_t(x)) * 3;
            image.pixels[i] = color.r;
            image.pixels[i + 1] = color.g;
            image.pixels[i + 2] = color.b;
        }
    }
    if (const std::filesystem::path folder = std::filesystem::path(out).parent_path();
        !folder.empty()) {
        std::filesystem::create_directories(folder);  // the build's own folder
    }
    pbr::writeHdr(out, image);
    if (!preview.empty()) {
        pbr::Image png{width, height, 3, std::vector<std::uint8_t>(image.pixels.size())};
        for (size_t i = 0; i < image.pixels.size(); ++i) {
            const float c = image.pixels[i];
            png.pixels[i] =
                std::uint8_t(std::lround(std::pow(c / (c + 1.0f), 1.0f / 2.2f) * 255.0f));
        }
        pbr::writePng(preview, png, pbr::PngEncoding::Small);
    }
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
