#include "support/golden.h"

#include <sys/file.h>
#include <unistd.h>

#include <fcntl.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "base/output.h"
#include "base/paths.h"
#include "support/build_paths.h"

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

std::optional<std::string> backendUnavailable(const RunResult& run, const std::string& backend) {
    const auto lines = run.errLines();
    if (run.exitCode == 0 || lines.empty()) return std::nullopt;
    const std::string prefix = "error: " + backend + ":";
    if (lines.back().rfind(prefix, 0) != 0) return std::nullopt;
    return "the " + backend + " backend cannot start here: " + lines.back().substr(7);
}

SampleRender renderSample(const std::string& sample, const fs::path& output,
                          const std::vector<std::string>& args, const RunOptions& options) {
    std::vector<std::string> argv = {sample, "--headless", "--output", output.string()};
    argv.insert(argv.end(), args.begin(), args.end());
    SampleRender render;
    render.run = runSample(argv, options);
    render.image = output;
    // "<sample>: wrote <path> (<W>x<H>, msaa <N>, <backend>, <renderer>)"
    std::istringstream lines(render.run.out);
    std::string line;
    while (std::getline(lines, line)) {
        const size_t msaa = line.find(", msaa ");
        if (line.find(": wrote ") == std::string::npos || msaa == std::string::npos) continue;
        const size_t backendStart = line.find(", ", msaa + 1);
        const size_t backendEnd = line.find(", ", backendStart + 2);
        if (backendStart == std::string::npos || backendEnd == std::string::npos) continue;
        render.backend = line.substr(backendStart + 2, backendEnd - backendStart - 2);
        render.renderer = line.substr(backendEnd + 2);
        if (!render.renderer.empty() && render.renderer.back() == ')') render.renderer.pop_back();
    }
    return render;
}

ViewRenders renderViews(const std::string& sample, const std::vector<std::string>& views,
                        const std::vector<std::string>& args, const fs::path& dir) {
    fs::create_directories(dir);
    const fs::path scriptPath = dir / (sample + "_views.script");
    {
        std::ofstream script(scriptPath);
        for (const std::string& view : views) script << "set --view " << view << "\nF12\n";
    }
    std::vector<std::string> argv = {sample,     "--headless",
                                     "--frames", std::to_string(views.size()),
                                     "--output", (dir / (sample + "_last_view.png")).string()};
    argv.insert(argv.end(), args.begin(), args.end());
    ViewRenders renders;
    renders.run = runSample(
        argv, {.setEnv = {{"PBR_PANEL_SCRIPT", scriptPath.string()}}, .workingDirectory = dir});
    if (renders.run.exitCode != 0) return renders;
    for (size_t i = 0; i < views.size(); ++i) {
        // frame i's F12 (frames from 0)
        const fs::path shot = dir / ("screenshot-" + sample + "-" + std::to_string(i) + ".png");
        const fs::path named = dir / (views[i] + ".png");
        std::error_code ec;
        fs::rename(shot, named, ec);
        if (!ec) renders.images[views[i]] = named;
    }
    return renders;
}

fs::path goldenReportDir() {
    return fs::path(PBR_PATH(PBR_TEST_OUTPUT_DIR)) / "golden-report";
}
fs::path goldenReportPage() {
    return goldenReportDir() / "index.html";
}

namespace {

bool updating() {
    const char* value = std::getenv("PBR_UPDATE_GOLDENS");
    return value && std::string(value) == "1";
}

void writeMetadata(const fs::path& path, const std::string& name, const Image& image,
                   const std::string& renderer, const GoldenGate& gate) {
    std::ostringstream out;
    out << "{\n  \"sample\": \"" << name << "\",\n  \"size\": \"" << image.width << "x"
        << image.height << "\",\n  \"renderer\": \"" << renderer << "\",\n  \"gate\": {"
        << "\"channel_threshold\": " << gate.channelThreshold
        << ", \"max_fraction_over\": " << gate.maxFractionOver
        << ", \"min_psnr_db\": " << gate.minPsnr << "}\n}\n";
    writeFileAtomically(path, out.str());
}

// A copy that is whole or absent, like every file the suite writes.
void copyFile(const fs::path& from, const fs::path& to) {
    writeFileAtomically(to, readBytes(from));
}

std::string htmlEscape(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '&':
                out += "&amp;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::string number(double value, int digits) {
    if (std::isinf(value)) return "&infin;";
    std::ostringstream out;
    out.setf(std::ios::fixed);
    out.precision(digits);
    out << value;
    return out.str();
}

struct ReportEntry {
    std::string id;      // "01_lighting.osmesa"
    std::string status;  // "pass", "fail", "updated"
    std::string sample, backend, renderer, size;
    GoldenGate gate;
    ImageDiff diff;
};

std::string entryHtml(const ReportEntry& e) {
    const std::string verdict = e.status == "pass"   ? "PASS"
                                : e.status == "fail" ? "FAIL"
                                                     : "UPDATED";
    // ok: 1 within the limit, 0 over it, -1 informative (no limit). An update is judged by no
    // gate: its rows say what changed against the old golden.
    const bool judged = e.status != "updated";
    auto row = [judged](const std::string& metric, const std::string& value,
                        const std::string& limit, int ok) {
        if (!judged) ok = -1;
        const std::string verdict = ok < 0 ? "<td></td>"
                                    : ok   ? "<td class=\"ok\">ok</td>"
                                           : "<td class=\"bad\">over</td>";
        return "<tr><td>" + metric + "</td><td>" + value + "</td><td>" + limit + "</td>" + verdict +
               "</tr>\n";
    };
    std::ostringstream html;
    html << "<!-- status: " << e.status << " -->\n"
         << "<section class=\"" << e.status << "\" id=\"" << htmlEscape(e.id) << "\">\n"
         << "<h2>" << htmlEscape(e.sample) << " <small>" << htmlEscape(e.backend)
         << "</small> <span class=\"verdict\">" << verdict << "</span></h2>\n"
         << "<p>" << htmlEscape(e.size) << " &middot; renderer: <code>" << htmlEscape(e.renderer)
         << "</code></p>\n"
         << "<table><tr><th>metric</th><th>value</th><th>limit</th><th></th></tr>\n"
         << row("pixels with a channel off by more than " + std::to_string(e.gate.channelThreshold),
                std::to_string(e.diff.pixelsOverThreshold) + " (" +
                    number(e.diff.fractionOverThreshold * 100.0, 4) + " %)",
                "&le; " + number(e.gate.maxFractionOver * 100.0, 4) + " %",
                e.diff.fractionOverThreshold <= e.gate.maxFractionOver)
         << row("PSNR", number(e.diff.psnr, 2) + " dB", "&ge; " + number(e.gate.minPsnr, 1) + " dB",
                e.diff.psnr >= e.gate.minPsnr)
         << row("largest channel difference", std::to_string(e.diff.maxChannelDiff) + " / 255", "",
                -1)
         << row("mean channel difference", number(e.diff.meanAbsDiff, 4) + " / 255", "", -1)
         << "</table>\n<div class=\"pictures\">\n";
    for (const char* kind : {"expected", "actual", "diff"}) {
        const std::string src = "img/" + e.id + "." + kind + ".png";
        html << "<figure><a href=\"" << htmlEscape(src) << "\"><img src=\"" << htmlEscape(src)
             << "\" alt=\"" << kind << "\"></a><figcaption>"
             << (std::string(kind) == "diff"       ? "difference &times;16"
                 : judged                          ? kind
                 : std::string(kind) == "expected" ? "old golden"
                                                   : "new golden")
             << "</figcaption></figure>\n";
    }
    html << "</div>\n</section>\n";
    return html.str();
}

// Rebuilds index.html from every entry written so far. Tests run in parallel processes, so the
// read-and-write happens under an exclusive lock; the last writer sees every entry.
void rebuildReport() {
    const fs::path dir = goldenReportDir();
    const int lock = ::open((dir / ".lock").c_str(), O_CREAT | O_RDWR, 0644);
    if (lock >= 0) ::flock(lock, LOCK_EX);
    // Only finished entries: another test's hidden temporary (".<id>.html.<digits>.tmp", see
    // output.h) may be listed here and renamed away before it could be read.
    std::set<fs::path> entries;
    for (const auto& file : fs::directory_iterator(dir / "entries")) {
        const std::string name = file.path().filename().string();
        if (name.front() != '.' && file.path().extension() == ".html") entries.insert(file.path());
    }
    int passed = 0, failed = 0, updated = 0;
    std::string failures, others;  // failures first: they are what a reader opens the page for
    for (const fs::path& entry : entries) {
        const std::string html = readTextFile(entry);
        if (html.rfind("<!-- status: pass", 0) == 0)
            ++passed;
        else if (html.rfind("<!-- status: fail", 0) == 0)
            ++failed;
        else
            ++updated;
        (html.rfind("<!-- status: fail", 0) == 0 ? failures : others) += html;
    }
    const std::string body = failures + others;
    std::ostringstream page;
    page << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
         << "<title>Golden report: " << failed << " failed</title>\n<style>\n"
         << "body{font:14px/1.4 sans-serif;margin:1.5em;background:#fafafa;color:#222}\n"
         << "section{background:#fff;border:1px solid #ccc;border-left:8px solid #2a2;margin:1em "
            "0;padding:.5em 1em}\n"
         << "section.fail{border-left-color:#d22}section.updated{border-left-color:#d90}\n"
         << ".verdict{font-size:.8em;padding:.1em "
            ".5em;border-radius:3px;background:#2a2;color:#fff}\n"
         << ".fail .verdict{background:#d22}.updated .verdict{background:#d90}\n"
         << "table{border-collapse:collapse}td,th{border:1px solid #ddd;padding:.2em "
            ".6em;text-align:left}\n"
         << "td.ok{color:#2a2}td.bad{color:#d22;font-weight:bold}\n"
         << ".pictures{display:flex;gap:.8em;flex-wrap:wrap}figure{margin:.5em 0}\n"
         << "img{width:420px;border:1px solid #999;image-rendering:pixelated;background:#000}\n"
         << "</style></head><body>\n<h1>Golden report</h1>\n<p>" << passed << " passed, " << failed
         << " failed, " << updated
         << " updated. Each entry: the golden (expected), this run (actual) and "
         << "their difference amplified 16 times; the gate's limits beside the metrics.</p>\n"
         << body << "</body></html>\n";
    writeFileAtomically(dir / "index.html", page.str());
    if (lock >= 0) ::close(lock);
}

void addReportEntry(const ReportEntry& entry, const fs::path& expected, const fs::path& actual,
                    const Image& diffImage) {
    const fs::path dir = goldenReportDir();
    fs::create_directories(dir / "img");
    fs::create_directories(dir / "entries");
    copyFile(expected, dir / "img" / (entry.id + ".expected.png"));
    copyFile(actual, dir / "img" / (entry.id + ".actual.png"));
    writePng(dir / "img" / (entry.id + ".diff.png"), diffImage);
    writeFileAtomically(dir / "entries" / (entry.id + ".html"), entryHtml(entry));
    rebuildReport();
}

}  // namespace

::testing::AssertionResult matchesGolden(const std::string& name, const SampleRender& render,
                                         const GoldenGate& gate) {
    const fs::path goldenPath = fs::path(PBR_PATH(PBR_GOLDEN_DIR)) / (name + ".png");
    // `name` may lie in a folder of the goldens ("web/01_lighting"); the pictures kept beside the
    // render go by its last part
    const std::string stem = fs::path(name).filename().string();
    Image actual;
    try {
        actual = readImage(render.image, 3);
    } catch (const std::exception& e) {
        return ::testing::AssertionFailure() << "no actual image: " << e.what();
    }
    ReportEntry entry;
    entry.id = name + "." + (render.backend.empty() ? "unknown" : render.backend);
    std::replace(entry.id.begin(), entry.id.end(), '/', '-');
    entry.sample = name;
    entry.backend = render.backend;
    entry.renderer = render.renderer;
    entry.size = std::to_string(actual.width) + "x" + std::to_string(actual.height);
    entry.gate = gate;

    if (updating()) {
        // The report shows what the update changed: the new picture against the old golden
        // (against itself when there was none, or its size changed).
        Image previous = actual;
        try {
            const Image old = readImage(goldenPath, 3);
            if (old.width == actual.width && old.height == actual.height) previous = old;
        } catch (const std::exception&) {
        }
        entry.diff = compareImages(actual, previous, gate.channelThreshold);
        const Image diffImage = differenceImage(actual, previous, 16);
        const fs::path previousPath = render.image.parent_path() / (stem + ".old-golden.png");
        writeFileAtomically(previousPath, encodePng(previous));
        copyFile(render.image, goldenPath);
        writeMetadata(fs::path(PBR_PATH(PBR_GOLDEN_DIR)) / (name + ".json"), name, actual,
                      render.renderer, gate);
        entry.status = "updated";
        addReportEntry(entry, previousPath, render.image, diffImage);
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
               << name << ": size " << entry.size << " but the golden is " << expected.width << "x"
               << expected.height;
    }
    const GoldenVerdict verdict = judge(actual, expected, gate);
    entry.status = verdict.pass ? "pass" : "fail";
    entry.diff = verdict.diff;
    const Image diffImage = differenceImage(actual, expected, 16);
    addReportEntry(entry, goldenPath, render.image, diffImage);
    if (verdict.pass) return ::testing::AssertionSuccess() << name << ": " << verdict.summary;

    // Leave the pictures beside the render too, for a person to look at.
    const fs::path dir = render.image.parent_path();
    const fs::path keptActual = dir / (stem + ".actual.png");
    const fs::path keptExpected = dir / (stem + ".expected.png");
    const fs::path diffPath = dir / (stem + ".diff.png");
    if (fs::absolute(render.image) != fs::absolute(keptActual)) copyFile(render.image, keptActual);
    copyFile(goldenPath, keptExpected);
    writePng(diffPath, diffImage);
    return ::testing::AssertionFailure()
           << name << " (" << render.backend << ") differs from its golden: " << verdict.summary
           << "\n  actual:     " << keptActual.string()
           << "\n  expected:   " << keptExpected.string() << "\n  difference: " << diffPath.string()
           << " (x16)"
           << "\n  report:     " << goldenReportPage().string();
}

double srgbToLinear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double linearToSrgb(double c) {
    c = std::clamp(c, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

bool unlikeCorner(const Image& image, int x, int y, int threshold) {
    for (int c = 0; c < image.channels; ++c) {
        if (std::abs(int(image.at(x, y, c)) - int(image.at(0, 0, c))) > threshold) return true;
    }
    return false;
}

size_t pixelsUnlikeCorner(const Image& image, int threshold) {
    size_t differing = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x)
            differing += unlikeCorner(image, x, y, threshold) ? 1 : 0;
    }
    return differing;
}

}  // namespace pbr::test
