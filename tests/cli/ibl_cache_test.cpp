// The IBL cache on disk, through sample 05 run as a user runs it: the first start computes and
// stores every map, the second loads them and draws the same bytes, --no-cache computes again
// without touching the files, and a damaged or stale file is named in one line, recomputed,
// replaced, and never drawn. And sample 06's KTX files: what they hold and which way round.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <regex>

#include "base/paths.h"
#include "files/image.h"
#include "files/ktx.h"
#include "math/brdf.h"
#include "support/golden.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

// The maps made from the environment; the BRDF LUT depends on none and comes from the build
// (resources/ibl), so it never enters the cache.
const char* const kMaps[] = {"sunny_courtyard.environment.ktx", "sunny_courtyard.irradiance.ktx",
                             "sunny_courtyard.prefiltered.ktx"};

// Runs 05 (320x180, one frame, --benchmark for its precompute figure) with `cache` as the cache.
struct Run05 {
    RunResult run;
    std::string image;    // the PNG's bytes
    double precompute_s;  // seconds spent computing maps (0 when all came from the cache)
};
Run05 run05(const fs::path& cache, const fs::path& output, std::vector<std::string> extra = {}) {
    std::vector<std::string> argv = {"05_ibl_specular", "--headless", "--size", "320x180",
                                     "--benchmark",     "--frames",   "1",      "--output",
                                     output.string()};
    argv.insert(argv.end(), extra.begin(), extra.end());
    Run05 r{runSample(argv, {.setEnv = {{"PBR_CACHE_DIR", cache.string()}}}), "", -1.0};
    EXPECT_EQ(r.run.exitCode, 0) << r.run.err;
    r.image = readBytes(output);
    std::smatch match;
    if (std::regex_search(r.run.out, match, std::regex("\"precompute_s\":([0-9.]+)"))) {
        r.precompute_s = std::stod(match[1]);
    }
    return r;
}

std::map<std::string, std::string> cacheFiles(const fs::path& cache) {
    std::map<std::string, std::string> files;
    for (const char* name : kMaps) files[name] = readBytes(cache / name);
    return files;
}

TEST(IblCache, SecondStartLoadsWhatTheFirstStored) {
    const fs::path dir = testOutputDir("ibl_cache_warm"), cache = dir / "cache";
    const Run05 cold = run05(cache, dir / "cold.png");
    ASSERT_FALSE(cold.image.empty());
    EXPECT_GT(cold.precompute_s, 0.0);
    const auto stored = cacheFiles(cache);
    for (const auto& [name, bytes] : stored) EXPECT_GT(bytes.size(), 1000u) << name;
    EXPECT_FALSE(fs::exists(cache / "brdf_lut_512.ktx")) << "the LUT the build baked was not used";
    std::map<std::string, fs::file_time_type> written;
    for (const char* name : kMaps) written[name] = fs::last_write_time(cache / name);

    const Run05 warm = run05(cache, dir / "warm.png");
    EXPECT_EQ(warm.precompute_s, 0.0) << "a map was computed although the cache held it";
    EXPECT_TRUE(warm.image == cold.image) << "a start from the cache draws differently";
    EXPECT_EQ(warm.run.err, "");
    for (const char* name : kMaps) EXPECT_EQ(fs::last_write_time(cache / name), written[name]);

    const Run05 uncached = run05(cache, dir / "uncached.png", {"--no-cache"});
    EXPECT_GT(uncached.precompute_s, 0.0);
    EXPECT_TRUE(uncached.image == cold.image);
    for (const char* name : kMaps) EXPECT_EQ(fs::last_write_time(cache / name), written[name]);
}

TEST(IblCache, DamagedOrStaleFilesAreRecomputedNotDrawn) {
    const fs::path dir = testOutputDir("ibl_cache_damaged"), cache = dir / "cache";
    const Run05 cold = run05(cache, dir / "cold.png");
    const auto stored = cacheFiles(cache);

    // Cut short, and not a KTX file at all.
    const std::string prefiltered = stored.at("sunny_courtyard.prefiltered.ktx");
    std::ofstream(cache / "sunny_courtyard.prefiltered.ktx", std::ios::binary)
        .write(prefiltered.data(), std::streamsize(prefiltered.size() / 2));
    std::ofstream(cache / "sunny_courtyard.irradiance.ktx", std::ios::binary) << "not a KTX file";
    const Run05 damaged = run05(cache, dir / "damaged.png");
    EXPECT_TRUE(damaged.image == cold.image) << "a damaged cache file changed the picture";
    const auto notes = damaged.run.errLines();
    ASSERT_EQ(notes.size(), 2u) << damaged.run.err;
    EXPECT_NE(damaged.run.err.find("sunny_courtyard.prefiltered.ktx"), std::string::npos);
    EXPECT_NE(damaged.run.err.find("sunny_courtyard.irradiance.ktx"), std::string::npos);
    for (const std::string& note : notes) {
        EXPECT_NE(note.find("recomputing"), std::string::npos) << note;
    }
    EXPECT_TRUE(cacheFiles(cache) == stored) << "the damaged files were not replaced";

    // A header that lies: a level count of 0xFFFFFFFF (once read as -1, and a crash), a face
    // count of 0xFFFFFFFF. Named, recomputed, replaced; the picture unchanged.
    for (const auto& [offset, name] : {std::pair{56, "sunny_courtyard.prefiltered.ktx"},
                                       std::pair{52, "sunny_courtyard.environment.ktx"}}) {
        std::string lying = stored.at(name);
        for (int i = 0; i < 4; ++i) lying[size_t(offset + i)] = char(0xff);
        std::ofstream(cache / name, std::ios::binary)
            .write(lying.data(), std::streamsize(lying.size()));
    }
    const Run05 lying = run05(cache, dir / "lying.png");
    EXPECT_EQ(lying.run.exitCode, 0) << lying.run.err;
    EXPECT_TRUE(lying.image == cold.image);
    EXPECT_NE(lying.run.err.find("prefiltered.ktx: bad mip level count 4294967295"),
              std::string::npos)
        << lying.run.err;
    EXPECT_NE(lying.run.err.find("environment.ktx: faces must be 1 or 6"), std::string::npos)
        << lying.run.err;
    EXPECT_TRUE(cacheFiles(cache) == stored) << "the lying files were not replaced";

    // Stale: another environment under the same file name leaves its maps under the same cache
    // names; going back to the first one finds keys that do not match.
    const fs::path other = dir / "other" / "sunny_courtyard.hdr";
    fs::create_directories(other.parent_path());
    HdrImage grey{64, 32, std::vector<float>(64 * 32 * 3, 0.25f)};
    writeHdr(other, grey);
    const Run05 elsewhere = run05(cache, dir / "other.png", {"--hdr", other.string()});
    EXPECT_FALSE(elsewhere.image == cold.image);
    EXPECT_EQ(elsewhere.run.errLines().size(), 3u) << elsewhere.run.err;
    const Run05 back = run05(cache, dir / "back.png");
    EXPECT_TRUE(back.image == cold.image);
    EXPECT_EQ(back.run.errLines().size(), 3u) << back.run.err;
    EXPECT_NE(back.run.err.find("stale"), std::string::npos) << back.run.err;
    EXPECT_TRUE(cacheFiles(cache) == stored);
}

// 06 writes the LUT the renderer reads: texel (i, j) of the file, row 0 first, holds NdotV =
// (i + 0.5) / 256 along the row and roughness = (j + 0.5) / 256 down the rows; R, G, B within
// 0.01 of the CPU quadratures. Given --hdr it writes the two cube maps.
TEST(BrdfLutTool, WritesTheMapsAsKtxTheRightWayRound) {
    const fs::path dir = testOutputDir("brdf_lut_files");
    const RunResult run = runSample({"06_brdf_lut", "--headless", "--size", "320x180", "--output",
                                     (dir / "06.png").string(), "--no-cache", "--hdr",
                                     (environmentDir() / "sunny_courtyard.hdr").string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("brdf_lut_sheen_256.ktx"), std::string::npos) << run.out;

    const KtxImage lut = readKtx(dir / "brdf_lut_sheen_256.ktx");
    ASSERT_EQ(lut.format, KtxFormat::RGBA16F);
    ASSERT_EQ(lut.width, 256);
    ASSERT_EQ(lut.height, 256);
    EXPECT_EQ(lut.metadata.at("KTXorientation"), "S=r,T=u");
    auto texel = [&](int i, int j, int channel) {
        std::uint16_t half;
        std::memcpy(&half,
                    &lut.images[0][((size_t(j) * 256 + size_t(i)) * 4 + size_t(channel)) * 2], 2);
        return halfToFloat(half);
    };
    for (const auto& [i, j] : {std::pair{10, 240}, {200, 30}, {128, 128}, {30, 60}, {250, 5}}) {
        const double NdotV = (i + 0.5) / 256.0, roughness = (j + 0.5) / 256.0;
        const glm::dvec2 scaleBias = cpu::splitSumQuadrature(NdotV, roughness);
        EXPECT_NEAR(texel(i, j, 0), scaleBias.x, 0.01) << i << ", " << j;
        EXPECT_NEAR(texel(i, j, 1), scaleBias.y, 0.01) << i << ", " << j;
        EXPECT_NEAR(texel(i, j, 2), cpu::sheenQuadrature(NdotV, roughness), 0.01) << i << ", " << j;
    }

    const KtxImage irradiance = readKtx(dir / "sunny_courtyard.irradiance.ktx");
    EXPECT_EQ(irradiance.faces, 6);
    EXPECT_EQ(irradiance.width, 32);
    EXPECT_EQ(irradiance.levels, 1);
    const KtxImage prefiltered = readKtx(dir / "sunny_courtyard.prefiltered.ktx");
    EXPECT_EQ(prefiltered.faces, 6);
    EXPECT_EQ(prefiltered.width, 128);
    EXPECT_EQ(prefiltered.levels, 5);
    for (const KtxImage* image : {&lut, &irradiance, &prefiltered}) {
        EXPECT_FALSE(image->metadata.at("pbr.contents").empty());
        EXPECT_FALSE(image->metadata.at("pbr.cacheKey").empty());
    }
}

// 05's README promises that 06 writes the maps 05 caches: the same names, the same bytes (the
// LUT differs on purpose: 05 takes LearnOpenGL's 512^2 RG16F, 06 bakes the cookbook's 256^2 with
// sheen, and each is named after its size and channels).
TEST(BrdfLutTool, WritesTheFilesThe05CacheHolds) {
    const fs::path dir = testOutputDir("brdf_lut_same_files");
    fs::create_directory(dir / "baked");
    const RunResult run =
        runSample({"06_brdf_lut", "--headless", "--size", "64x36", "--output",
                   (dir / "06.png").string(), "--ktx-dir", (dir / "baked").string(), "--no-cache",
                   "--hdr", (environmentDir() / "sunny_courtyard.hdr").string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Run05 cached = run05(dir / "cache", dir / "05.png");
    for (const char* name : {"sunny_courtyard.irradiance.ktx", "sunny_courtyard.prefiltered.ktx"}) {
        const std::string baked = readBytes(dir / "baked" / name);
        ASSERT_GT(baked.size(), 1000u) << name;
        EXPECT_TRUE(baked == readBytes(dir / "cache" / name)) << name << " differs";
    }
    EXPECT_TRUE(fs::exists(dir / "baked" / "brdf_lut_sheen_256.ktx"));
    EXPECT_TRUE(fs::exists(iblDir() / "brdf_lut_512.ktx"));  // 05's, baked by the build
}

}  // namespace
}  // namespace pbr::test
