#include "support/golden.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

namespace pbr::test {

namespace fs = std::filesystem;

GoldenVerdict judge(const Image& actual, const Image& expected, const GoldenGate& gate) {
    GoldenVerdict verdict;
    verdict.diff = compareImages(actual, expected, gate.channelThreshold);
    const ImageDiff& d = verdict.diff;
    verdict.pass = d.fractionOverThreshold <= gate.maxFractionOver && d.psnr >= gate.minPsnr;
    std::ostringstream summary;
    summary << "max channel diff " << d.maxChannelDiff << "; pixels off by more than "
            << gate.channelThreshold << ": " << d.pixelsOverThreshold << " ("
            << d.fractionOverThreshold * 100.0 << " %, limit " << gate.maxFractionOver * 100.0
            << " %); PSNR " << d.psnr << " dB (limit " << gate.minPsnr << " dB)";
    verdict.summary = summary.str();
    return verdict;
}

SampleRender renderSample(const std::string& sample, const fs::path& output,
                          const std::vector<std::string>& args) {
    std::vector<std::string> argv = {sample, "--headless", "--output", output.string()};
    argv.insert(argv.end(), args.begin(), args.end());
    SampleRender render;
    render.run = runSample(argv);
    render.image = output;
    static const std::regex wrote(R"(wrote .* \(\d+x\d+, msaa \d+, (.*)\)\s*$)");
    std::istringstream lines(render.run.out);
    std::string line;
    while (std::getline(lines, line)) {
        std::smatch match;
        if (std::regex_search(line, match, wrote)) render.renderer = match[1].str();
    }
    return render;
}

namespace {
bool updating() {
    const char* value = std::getenv("PBR_UPDATE_GOLDENS");
    return value && std::string(value) == "1";
}

void writeMetadata(const fs::path& path, const std::string& name, const Image& image,
                   const std::string& renderer, const GoldenGate& gate) {
    std::ofstream out(path);
    out << "{\n  \"sample\": \"" << name << "\",\n  \"size\": \"" << image.width << "x"
        << image.height << "\",\n  \"renderer\": \"" << renderer << "\",\n  \"gate\": {"
        << "\"channel_threshold\": " << gate.channelThreshold
        << ", \"max_fraction_over\": " << gate.maxFractionOver
        << ", \"min_psnr_db\": " << gate.minPsnr << "}\n}\n";
}
}  // namespace

::testing::AssertionResult matchesGolden(const std::string& name, const fs::path& actualPath,
                                         const std::string& renderer, const GoldenGate& gate) {
    const fs::path goldenPath = fs::path(PBR_GOLDEN_DIR) / (name + ".png");
    Image actual;
    try {
        actual = readImage(actualPath, 3);
    } catch (const std::exception& e) {
        return ::testing::AssertionFailure() << "no actual image: " << e.what();
    }
    if (updating()) {
        fs::copy_file(actualPath, goldenPath, fs::copy_options::overwrite_existing);
        writeMetadata(fs::path(PBR_GOLDEN_DIR) / (name + ".json"), name, actual, renderer, gate);
        std::printf("updated golden %s: look at it before committing\n", goldenPath.c_str());
        return ::testing::AssertionSuccess();
    }
    Image expected;
    try {
        expected = readImage(goldenPath, 3);
    } catch (const std::exception& e) {
        return ::testing::AssertionFailure()
               << "no golden image (" << e.what() << "); create it with PBR_UPDATE_GOLDENS=1";
    }
    if (actual.width != expected.width || actual.height != expected.height) {
        return ::testing::AssertionFailure()
               << name << ": size " << actual.width << "x" << actual.height << " but the golden is "
               << expected.width << "x" << expected.height;
    }
    const GoldenVerdict verdict = judge(actual, expected, gate);
    if (verdict.pass) return ::testing::AssertionSuccess() << name << ": " << verdict.summary;

    // Leave the pictures beside each other for a person to look at.
    const fs::path dir = actualPath.parent_path();
    const fs::path keptActual = dir / (name + ".actual.png");
    const fs::path keptExpected = dir / (name + ".expected.png");
    const fs::path diffPath = dir / (name + ".diff.png");
    if (fs::absolute(actualPath) != fs::absolute(keptActual)) {
        fs::copy_file(actualPath, keptActual, fs::copy_options::overwrite_existing);
    }
    fs::copy_file(goldenPath, keptExpected, fs::copy_options::overwrite_existing);
    writePng(diffPath, differenceImage(actual, expected, 16));
    return ::testing::AssertionFailure() << name << " differs from its golden: " << verdict.summary
                                         << "\n  actual:     " << keptActual.string()
                                         << "\n  expected:   " << keptExpected.string()
                                         << "\n  difference: " << diffPath.string() << " (x16)";
}

}  // namespace pbr::test
