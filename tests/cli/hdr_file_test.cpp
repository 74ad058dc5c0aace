// --hdr with files that are not whole Radiance images: each IBL sample prints one line naming the
// file and the reason and exits 1, without a crash, a hang or a picture; and nothing of the broken
// file lands in the cache.
#include <gtest/gtest.h>

#include <fstream>

#include "base/paths.h"
#include "support/golden.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

TEST(HdrFile, BrokenFilesAreOneLineErrors) {
    const fs::path dir = testOutputDir("hdr_file"), cache = dir / "cache";
    const std::string hdr = readBytes(environmentDir() / "sunny_courtyard.hdr");
    ASSERT_GT(hdr.size(), 100000u);
    const size_t data = hdr.find("+X 2048\n") + 8;  // the first scanline
    ASSERT_NE(data, std::string::npos + 8);

    std::map<std::string, std::pair<std::string, std::string>> files = {
        {"truncated.hdr", {hdr.substr(0, hdr.size() / 2), "truncated"}},
        {"header_only.hdr", {hdr.substr(0, data), "truncated"}},
        // a zero run count: Debian's stb_image would loop forever here
        {"zero_run.hdr", {hdr.substr(0, data + 4) + '\0' + hdr.substr(data + 5), "bad run-length"}},
        {"picture.hdr", {"\x89PNG\r\n\x1a\n", "not a Radiance .hdr file"}},
        {"empty.hdr", {"", "empty file"}},
    };
    for (const auto& [name, contents] : files) {
        std::ofstream(dir / name, std::ios::binary) << contents.first;
    }
    files["missing.hdr"] = {"", "cannot open"};
    fs::remove(dir / "missing.hdr");

    for (const auto& [name, contents] : files) {
        for (const char* sample : {"04_ibl_irradiance", "05_ibl_specular", "06_brdf_lut"}) {
            const fs::path output = dir / (std::string(sample) + ".png");
            const RunResult run = runSample({sample, "--headless", "--size", "64x36", "--output",
                                             output.string(), "--hdr", (dir / name).string()},
                                            {.setEnv = {{"PBR_CACHE_DIR", cache.string()}}});
            EXPECT_EQ(run.exitCode, 1) << sample << " " << name << ": " << run.err;
            const auto lines = run.errLines();
            ASSERT_EQ(lines.size(), 1u) << sample << " " << name << ": " << run.err;
            EXPECT_NE(lines[0].find(name), std::string::npos) << lines[0];
            EXPECT_NE(lines[0].find(contents.second), std::string::npos) << lines[0];
            EXPECT_FALSE(fs::exists(output)) << sample << " " << name;
        }
    }
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(cache, ec)) {  // none at all is fine
        EXPECT_EQ(entry.path().filename().string().rfind("brdf_lut", 0), 0u)
            << entry.path() << ": a map of a broken file was cached";
    }
}

}  // namespace
}  // namespace pbr::test
