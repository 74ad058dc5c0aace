// ibl_accuracy: how close this project's IBL maps come to the integrals they stand for, next to
// the method of LearnOpenGL's text, both measured against an independent CPU reference in double
// precision. Prints a markdown table and the timings. Run by hand, not in CI (a minute or two on
// llvmpipe):
//
//     build/release/bin/ibl_accuracy [--hdr FILE] [--constant]
//
// Every reference is computed from the same 512^2 environment cube the GPU maps read (read back),
// so the table measures the precomputation, not the equirectangular-to-cube step.
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "app/app.h"
#include "base/error.h"
#include "base/paths.h"
#include "files/image.h"
#include "gl/framebuffer.h"
#include "gl/mesh.h"
#include "gl/shader.h"
#include "gl/texture.h"
#include "ibl/ibl.h"
#include "math/brdf.h"
#include "math/cube_geometry.h"

namespace {

using glm::dvec3;
namespace fs = std::filesystem;

constexpr double kPi = 3.14159265358979323846;
constexpr int kEnvironmentSize = 512;
constexpr int kIrradianceSize = 32;
constexpr int kPrefilterSize = 128, kPrefilterLevels = 5,
              kPrefilterSamples = pbr::kPrefilterSamples;
constexpr int kLutSize = 512, kLutSamples = 1024;
constexpr double kLearnOpenGlDelta = 0.025;

double luminance(const dvec3& c) {
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

// One mip level of a cube map, read back to the CPU.
struct CubeLevel {
    int size = 0;
    std::array<std::vector<float>, 6> faces;  // RGB, row 0 at t = 0

    dvec3 at(int face, int i, int j) const {
        const size_t k = (size_t(j) * size_t(size) + size_t(i)) * 3;
        const std::vector<float>& f = faces[size_t(face)];
        return {f[k], f[k + 1], f[k + 2]};
    }

    // A bilinear read at face coordinates (s, t) in [-1, 1], within the face (texels clamped at
    // its border; the points read here are all well inside).
    dvec3 bilinear(int face, double s, double t) const {
        const double x = (s + 1.0) * 0.5 * size - 0.5, y = (t + 1.0) * 0.5 * size - 0.5;
        const int i0 = int(std::floor(x)), j0 = int(std::floor(y));
        const double fx = x - i0, fy = y - j0;
        auto texel = [&](int i, int j) {
            return at(face, std::clamp(i, 0, size - 1), std::clamp(j, 0, size - 1));
        };
        return glm::mix(glm::mix(texel(i0, j0), texel(i0 + 1, j0), fx),
                        glm::mix(texel(i0, j0 + 1), texel(i0 + 1, j0 + 1), fx), fy);
    }
};

CubeLevel readLevel(const pbr::TextureCube& cube, int level) {
    CubeLevel out;
    out.size = std::max(1, cube.size() >> level);
    for (int face = 0; face < 6; ++face) out.faces[size_t(face)] = cube.readFace(face, level);
    return out;
}

// Every texel of a cube level as a quadrature point of the sphere: the integrals of the
// references are sums over these.
struct SphereQuadrature {
    std::vector<dvec3> direction, radiance;
    std::vector<double> solidAngle;
};

SphereQuadrature quadrature(const CubeLevel& level) {
    SphereQuadrature q;
    const int n = level.size;
    for (int face = 0; face < 6; ++face) {
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i) {
                q.direction.push_back(pbr::cubeFaceDirection(face, pbr::cubeTexelCentre(i, n),
                                                             pbr::cubeTexelCentre(j, n)));
                q.radiance.push_back(level.at(face, i, j));
                q.solidAngle.push_back(pbr::cubeTexelSolidAngle(i, j, n));
            }
        }
    }
    return q;
}

// A texel of an n^2 cube map.
struct Texel {
    int face, i, j, n;
    dvec3 direction() const {
        return pbr::cubeFaceDirection(face, pbr::cubeTexelCentre(i, n), pbr::cubeTexelCentre(j, n));
    }
};

// `perAxis`^2 texels on each of the six faces of an n^2 cube map, at the centres of equal blocks
// of rows and columns: an even spread over the sphere.
std::vector<Texel> spread(int n, int perAxis) {
    std::vector<Texel> texels;
    const int block = n / perAxis;
    for (int face = 0; face < 6; ++face) {
        for (int b = 0; b < perAxis; ++b) {
            for (int a = 0; a < perAxis; ++a) {
                texels.push_back({face, a * block + block / 2, b * block + block / 2, n});
            }
        }
    }
    return texels;
}

// ---------------------------------------------------------------------------------------------
// CPU references (double precision)

// body(k) for every k in [0, n), on every hardware thread: the references are independent sums.
void parallelFor(size_t n, const std::function<void(size_t)>& body) {
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    std::atomic<size_t> next{0};
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t) {
        pool.emplace_back([&] {
            for (size_t k = next++; k < n; k = next++) body(k);
        });
    }
    for (std::thread& thread : pool) thread.join();
}

// Irradiance / pi at N: (1 / pi) * sum of L(w) max(0, N.w) dOmega over the whole sphere.
dvec3 referenceIrradiance(const SphereQuadrature& env, const dvec3& N) {
    dvec3 sum(0.0);
    for (size_t k = 0; k < env.direction.size(); ++k) {
        const double cosine = glm::dot(N, env.direction[k]);
        if (cosine > 0.0) sum += env.radiance[k] * (cosine * env.solidAngle[k]);
    }
    return sum / kPi;
}

// The prefiltered radiance at N (= V = R): the environment weighted by NdotL * D_GGX(h) over the
// hemisphere, normalised. It is what sum(L NdotL) / sum(NdotL) over GGX half-vector samples (of
// density D(h) NdotH, turned into L) converges to.
dvec3 referencePrefiltered(const SphereQuadrature& env, const dvec3& N, double roughness) {
    const double a = roughness * roughness, a2 = a * a;
    dvec3 sum(0.0);
    double weightSum = 0.0;
    for (size_t k = 0; k < env.direction.size(); ++k) {
        const dvec3& L = env.direction[k];
        const double NdotL = glm::dot(N, L);
        if (NdotL <= 0.0) continue;
        const double NdotH = glm::dot(N, glm::normalize(N + L));
        const double denominator = NdotH * NdotH * (a2 - 1.0) + 1.0;
        const double D = a2 / (kPi * denominator * denominator);
        const double weight = NdotL * D * env.solidAngle[k];
        sum += env.radiance[k] * weight;
        weightSum += weight;
    }
    return sum / weightSum;
}

// ---------------------------------------------------------------------------------------------
// GPU: LearnOpenGL's irradiance, rendered the way common/ibl/ibl.cpp renders ours

pbr::TextureCube learnOpenGlIrradiance(const pbr::TextureCube& environment, int size) {
    pbr::TextureCube irradiance(size, 1);
    pbr::Shader shader("ibl/cubemap.vert", fs::path(PBR_TOOLS_DIR) / "learnopengl_irradiance.frag");
    shader.set("environmentMap", 0);
    environment.bind(0);
    pbr::renderCubeFaces(shader, irradiance, 0);
    return irradiance;
}

// ---------------------------------------------------------------------------------------------
// Measuring and reporting

// Runs `work`, waits until the GPU has finished it, and stores the wall time in `seconds`.
template <class F>
auto timed(double& seconds, F&& work) {
    const auto start = std::chrono::steady_clock::now();
    auto result = work();
    glFinish();
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The App's debug callback prints GL errors but only its frames count them; no frame is drawn
// here, so check after each step.
void requireNoGlError(const char* step) {
    if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
        throw pbr::Error(std::string(step) + ": " + pbr::glErrorName(error));
    }
}

struct ErrorStats {
    double mean = 0.0, max = 0.0;
};

ErrorStats summarise(const std::vector<double>& errors) {
    ErrorStats stats;
    for (double e : errors) {
        stats.mean += e;
        stats.max = std::max(stats.max, e);
    }
    if (!errors.empty()) stats.mean /= double(errors.size());
    return stats;
}

double relativeLuminanceError(const dvec3& value, const dvec3& reference) {
    return std::abs(luminance(value) - luminance(reference)) / luminance(reference);
}

struct Row {
    std::string map, method, samples;
    std::optional<double> seconds;  // none: shares the time of another row, or not run
    std::string mean, max;
};

std::string percent(double fraction) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f %%", 100.0 * fraction);
    return text;
}

std::string scientific(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2e", value);
    return text;
}

void printTable(const std::vector<Row>& rows) {
    std::printf("| map | method | samples per texel | GPU time s | mean error | max error |\n");
    std::printf("| --- | --- | ---: | ---: | ---: | ---: |\n");
    for (const Row& row : rows) {
        char seconds[32] = "-";
        if (row.seconds) std::snprintf(seconds, sizeof seconds, "%.2f", *row.seconds);
        std::printf("| %s | %s | %s | %s | %s | %s |\n", row.map.c_str(), row.method.c_str(),
                    row.samples.c_str(), seconds, row.mean.c_str(), row.max.c_str());
    }
}

// What the table is made of, gathered step by step.
struct Report {
    std::vector<Row> rows;
    double environmentSeconds = 0.0;   // GPU: the equirectangular image to the cube
    double solidAngleDeviation = 0.0;  // |sum of the texel solid angles / 4 pi - 1|
    size_t irradianceTexels = 0;
    // CPU seconds of the references (their check over level 0 included), and that check: the
    // largest relative change of a reference summed over level 0 instead of level 1.
    double irradianceCpuSeconds = 0.0, prefilterCpuSeconds = 0.0, lutCpuSeconds = 0.0;
    double irradianceCheck = 0.0, prefilterCheck = 0.0;
};

// The environment cube and the texels every reference sums over.
struct Environment {
    pbr::TextureCube cube;
    CubeLevel level0, level2;
    // Level 1 for the references; level 0 (4 times the texels) to show how far their own
    // discretisation is from converged.
    SphereQuadrature sphere, fineSphere;
};

Environment makeEnvironment(const pbr::HdrImage& hdr, Report& report) {
    pbr::TextureCube cube = timed(report.environmentSeconds, [&] {
        return pbr::equirectangularToCubemap(pbr::Texture2D(hdr), kEnvironmentSize);
    });
    requireNoGlError("environment cube");
    CubeLevel level0 = readLevel(cube, 0), level2 = readLevel(cube, 2);
    SphereQuadrature sphere = quadrature(readLevel(cube, 1)), fineSphere = quadrature(level0);
    Environment env{.cube = std::move(cube),
                    .level0 = std::move(level0),
                    .level2 = std::move(level2),
                    .sphere = std::move(sphere),
                    .fineSphere = std::move(fineSphere)};

    double total = 0.0;
    for (double omega : env.sphere.solidAngle) total += omega;
    report.solidAngleDeviation = std::abs(total / (4.0 * kPi) - 1.0);
    if (report.solidAngleDeviation > 1e-6) {
        throw pbr::Error("texel solid angles sum to " + std::to_string(total) + ", not 4 pi");
    }
    return env;
}

// Irradiance: ours at several step sizes and LearnOpenGL's, against the reference.
void measureIrradiance(const Environment& env, Report& report) {
    struct Run {
        std::string method;
        long samples = 0;
        double seconds = 0.0;
        CubeLevel map;
    };
    std::vector<Run> runs;
    for (const float delta : {0.1f, 0.075f, 0.05f}) {
        Run run;
        char method[64];
        std::snprintf(method, sizeof method, "ours, delta %.3g (midpoints, LOD per sample)",
                      double(delta));
        run.method = method;
        // The shader's own step counts: a whole number of steps over each range.
        run.samples =
            std::lround(2.0 * kPi / double(delta)) * std::lround(0.5 * kPi / double(delta));
        const pbr::TextureCube map = timed(
            run.seconds, [&] { return pbr::convolveIrradiance(env.cube, kIrradianceSize, delta); });
        requireNoGlError("irradiance (ours)");
        run.map = readLevel(map, 0);
        runs.push_back(std::move(run));
    }
    {
        Run run;
        run.method = "LearnOpenGL, delta 0.025 (left endpoints, level 0)";
        // The text's loops step while below the bound: ceil(range / delta) steps each.
        run.samples = long(std::ceil(2.0 * kPi / kLearnOpenGlDelta)) *
                      long(std::ceil(0.5 * kPi / kLearnOpenGlDelta));
        const pbr::TextureCube map =
            timed(run.seconds, [&] { return learnOpenGlIrradiance(env.cube, kIrradianceSize); });
        requireNoGlError("irradiance (LearnOpenGL)");
        run.map = readLevel(map, 0);
        runs.push_back(std::move(run));
    }

    const auto start = std::chrono::steady_clock::now();
    const std::vector<Texel> texels = spread(kIrradianceSize, 8);
    std::vector<dvec3> reference(texels.size());
    std::vector<double> check(texels.size());
    parallelFor(texels.size(), [&](size_t k) {
        const dvec3 N = texels[k].direction();
        reference[k] = referenceIrradiance(env.sphere, N);
        check[k] = relativeLuminanceError(reference[k], referenceIrradiance(env.fineSphere, N));
    });
    report.irradianceCpuSeconds = secondsSince(start);
    report.irradianceCheck = summarise(check).max;
    report.irradianceTexels = texels.size();

    for (const Run& run : runs) {
        std::vector<double> errors;
        for (size_t k = 0; k < texels.size(); ++k) {
            const Texel& t = texels[k];
            errors.push_back(relativeLuminanceError(run.map.at(t.face, t.i, t.j), reference[k]));
        }
        const ErrorStats stats = summarise(errors);
        report.rows.push_back({"irradiance 32^2", run.method, std::to_string(run.samples),
                               run.seconds, percent(stats.mean), percent(stats.max)});
    }
}

// The prefiltered specular map: levels 1-4 against the reference; level 0 (a mirror) against
// the two readings of "the environment in that direction".
void measurePrefiltered(const Environment& env, Report& report) {
    double seconds = 0.0;
    const pbr::TextureCube prefiltered = timed(seconds, [&] {
        return pbr::prefilterSpecular(env.cube, kPrefilterSize, kPrefilterLevels,
                                      kPrefilterSamples);
    });
    requireNoGlError("prefiltered map");

    const CubeLevel level0 = readLevel(prefiltered, 0);
    std::vector<double> oursVsBox, oursVsPoint, pointVsBox;
    for (const Texel& t : spread(kPrefilterSize, 4)) {
        const dvec3 ours = level0.at(t.face, t.i, t.j);
        // (a) the level-2 texel: the box average of the 4x4 level-0 texels under this one
        const dvec3 box = env.level2.at(t.face, t.i, t.j);
        // (b) a bilinear read of level 0 at the centre: also LearnOpenGL's mirror level, whose
        // GGX samples at roughness 0 all fall on N and read level 0
        const dvec3 point = env.level0.bilinear(t.face, pbr::cubeTexelCentre(t.i, t.n),
                                                pbr::cubeTexelCentre(t.j, t.n));
        oursVsBox.push_back(relativeLuminanceError(ours, box));
        oursVsPoint.push_back(relativeLuminanceError(ours, point));
        pointVsBox.push_back(relativeLuminanceError(point, box));
    }
    const ErrorStats a = summarise(oursVsBox), b = summarise(oursVsPoint),
                     c = summarise(pointVsBox);
    const std::string ours0 = "ours (read at footprint LOD 2)";
    const std::string learnOpenGl0 = "LearnOpenGL (point read of level 0)";
    report.rows.push_back(
        {"prefiltered L0 (r 0) vs (a)", ours0, "1", seconds, percent(a.mean), percent(a.max)});
    report.rows.push_back(
        {"prefiltered L0 (r 0) vs (b)", ours0, "1", std::nullopt, percent(b.mean), percent(b.max)});
    report.rows.push_back({"prefiltered L0 (r 0) vs (a)", learnOpenGl0, "1", std::nullopt,
                           percent(c.mean), percent(c.max)});
    report.rows.push_back({"prefiltered L0 (r 0) vs (b)", learnOpenGl0, "1", std::nullopt,
                           "0 (is (b))", "0 (is (b))"});

    const auto start = std::chrono::steady_clock::now();
    std::vector<double> checks;
    for (int level = 1; level < kPrefilterLevels; ++level) {
        const double roughness = double(level) / double(kPrefilterLevels - 1);
        const int size = kPrefilterSize >> level;
        const CubeLevel map = readLevel(prefiltered, level);
        const std::vector<Texel> texels = spread(size, 4);
        std::vector<double> errors(texels.size()), check(texels.size());
        parallelFor(texels.size(), [&](size_t k) {
            const Texel& t = texels[k];
            const dvec3 N = t.direction();
            const dvec3 reference = referencePrefiltered(env.sphere, N, roughness);
            errors[k] = relativeLuminanceError(map.at(t.face, t.i, t.j), reference);
            check[k] = relativeLuminanceError(reference,
                                              referencePrefiltered(env.fineSphere, N, roughness));
        });
        checks.insert(checks.end(), check.begin(), check.end());
        const ErrorStats stats = summarise(errors);
        char name[64];
        std::snprintf(name, sizeof name, "prefiltered L%d (r %.2f) %d^2", level, roughness, size);
        report.rows.push_back({name, "ours (GGX importance sampling, LOD per sample)",
                               std::to_string(kPrefilterSamples), std::nullopt, percent(stats.mean),
                               percent(stats.max)});
    }
    report.prefilterCpuSeconds = secondsSince(start);
    report.prefilterCheck = summarise(checks).max;
}

// The BRDF LUT against the same estimator with 64 times the samples.
void measureBrdfLut(Report& report) {
    double seconds = 0.0;
    const pbr::Texture2D lut =
        timed(seconds, [&] { return pbr::computeBrdfLut(kLutSize, kLutSamples); });
    requireNoGlError("BRDF LUT");
    const std::vector<float> texels = lut.readFloats(2);

    const auto start = std::chrono::steady_clock::now();
    constexpr int kPerAxis = 16, kBlock = kLutSize / kPerAxis;
    std::vector<double> scaleErrors(kPerAxis * kPerAxis), biasErrors(kPerAxis * kPerAxis);
    parallelFor(scaleErrors.size(), [&](size_t k) {
        const int i = int(k % kPerAxis) * kBlock + kBlock / 2;
        const int j = int(k / kPerAxis) * kBlock + kBlock / 2;
        const double NdotV = (i + 0.5) / kLutSize, roughness = (j + 0.5) / kLutSize;
        const glm::dvec2 reference = pbr::cpu::splitSumQuadrature(NdotV, roughness);
        const size_t at = (size_t(j) * kLutSize + size_t(i)) * 2;
        scaleErrors[k] = std::abs(double(texels[at]) - reference.x);
        biasErrors[k] = std::abs(double(texels[at + 1]) - reference.y);
    });
    report.lutCpuSeconds = secondsSince(start);

    const ErrorStats scale = summarise(scaleErrors), bias = summarise(biasErrors);
    const std::string method = "ours = LearnOpenGL's estimator (RG16F)";
    report.rows.push_back({"BRDF LUT 512^2, R (scale), abs.", method, std::to_string(kLutSamples),
                           seconds, scientific(scale.mean), scientific(scale.max)});
    report.rows.push_back({"BRDF LUT 512^2, G (bias), abs.", method, std::to_string(kLutSamples),
                           std::nullopt, scientific(bias.mean), scientific(bias.max)});
}

void printReport(const Report& report, const std::string& environment, const std::string& renderer,
                 double runSeconds) {
    std::printf("# IBL accuracy: %s, environment cube %d^2 (%s)\n\n", environment.c_str(),
                kEnvironmentSize, renderer.c_str());
    std::printf(
        "References, all in double precision on the CPU from the environment cube read back:\n"
        "- irradiance: (1/pi) sum L(w) max(0, N.w) dOmega over every texel of the environment's "
        "mip level 1 (6 x 256^2, exact texel solid angles), at %zu texel centres of the 32^2 map "
        "(every 4th row and column from 2, all faces); relative error of luminance.\n"
        "- prefiltered L1-L4: sum L NdotL D_GGX(h) dOmega / sum NdotL D_GGX(h) dOmega over the "
        "same texels, N = V = R, at 96 texel centres a level (4 x 4 a face); relative error of "
        "luminance.\n"
        "- prefiltered L0 (roughness 0): (a) the environment's mip level 2 texel (box average "
        "over the 128^2 texel's footprint), (b) a bilinear read of level 0 at the texel centre; "
        "96 texels.\n"
        "- BRDF LUT: pbr::cpu::splitSumQuadrature (numerical quadrature, no sampling) at 16 x 16 "
        "texels; absolute error.\n"
        "GPU time: the call, glFinish included (the prefiltered row times all 5 levels).\n"
        "The references summed over level 0 instead (4 times the texels) differ by at most "
        "%.4f %% (irradiance) and %.4f %% (prefiltered L1-L4).\n\n",
        report.irradianceTexels, 100.0 * report.irradianceCheck, 100.0 * report.prefilterCheck);
    printTable(report.rows);
    std::printf(
        "\nTimings: environment cube %.2f s (GPU); CPU references (each checked over level 0 "
        "too): irradiance %.2f s, prefiltered %.2f s, BRDF LUT %.2f s (%u threads); whole run "
        "%.1f s. Texel solid angles sum to 4 pi within %.1e.\n",
        report.environmentSeconds, report.irradianceCpuSeconds, report.prefilterCpuSeconds,
        report.lutCpuSeconds, std::max(1u, std::thread::hardware_concurrency()), runSeconds,
        report.solidAngleDeviation);
    std::fflush(stdout);
}

// The flags of this tool. --hdr as the IBL samples spell it.
std::vector<pbr::FlagSpec> toolFlags() {
    return {pbr::FlagSpec::text("--hdr", "FILE",
                                "an equirectangular .hdr environment (default: the project's)"),
            pbr::FlagSpec::toggle("--constant",
                                  "a constant environment of radiance 1 instead (every error ~0)")};
}

void measure(const pbr::App& app) {
    const auto started = std::chrono::steady_clock::now();
    const bool constant = app.options().has("--constant");
    const fs::path hdrPath = app.flag("--hdr") ? fs::path(*app.flag("--hdr"))
                                               : pbr::environmentDir() / "sunny_courtyard.hdr";
    const pbr::HdrImage hdr = constant
                                  ? pbr::HdrImage{.width = 64,
                                                  .height = 32,
                                                  .pixels = std::vector<float>(64 * 32 * 3, 1.0f)}
                                  : pbr::readHdr(hdrPath);

    Report report;
    const Environment env = makeEnvironment(hdr, report);
    measureIrradiance(env, report);
    measurePrefiltered(env, report);
    measureBrdfLut(report);
    printReport(report, constant ? "constant environment, radiance 1" : hdrPath.string(),
                app.renderer(), secondsSince(started));
}

}  // namespace

int main(int argc, char** argv) try {
    // A headless App for its GL context (and its leak check at exit); no frame is ever drawn.
    std::vector<std::string> args = {argc > 0 ? argv[0] : "ibl_accuracy", "--headless", "--size",
                                     "64x36"};
    args.insert(args.end(), argv + std::min(argc, 1), argv + argc);
    std::vector<char*> argp;
    for (std::string& arg : args) argp.push_back(arg.data());
    pbr::App app(int(argp.size()), argp.data(), {.name = "ibl_accuracy", .flags = toolFlags()});
    measure(app);  // every GL object it makes is gone when it returns, before the App
    requireNoGlError("end of run");
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
