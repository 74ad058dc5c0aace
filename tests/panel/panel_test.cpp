// The live panel (common/app/panel.h) driven headless through Dear ImGui's input, as a window
// drives it: PBR_PANEL_SCRIPT gives the mouse of each frame (position and left button). A drag
// on a slider, clicks on a stepper's buttons, a combo box's choice: after each, the last frame
// must equal, byte for byte, a headless run started with the flag at the value the change gave,
// the command line the panel shows must be that run's, and the change must be the control's own
// flag, near the value under the mouse.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/golden.h"
#include "support/process.h"

namespace pbr::test {
namespace {

namespace fs = std::filesystem;

struct Rect {
    int x = 0, y = 0, w = 0, h = 0;
    // A point inside, as fractions of the width and height.
    std::string at(double fx, double fy = 0.5) const {
        return std::to_string(int(x + fx * w)) + " " + std::to_string(int(y + fy * h));
    }
};

struct PanelRun {
    RunResult run;
    fs::path image;
    std::map<std::string, Rect> controls;  // the panel's layout in the last frame
    std::string command;                   // the command line it showed at the end
};

// The mouse in one frame: over a point with the left button up or held.
std::string hover(const std::string& point) {
    return point + " 0";
}
std::string hold(const std::string& point) {
    return point + " 1";
}
// A click made between two frames (pressed and released since the last one), as a learner clicks
// at a software GL's 1-3 frames a second.
std::string click(const std::string& point) {
    return point + " 2";
}

// single-sampled: what a panel test checks (the panel, the flags, the camera) shows without it
const std::vector<std::string> kRunSize = {"--size", "640x360", "--msaa", "0"};

// The frames of a script: a line each, but for the flags' lines ("set", "unset"), which change the
// next frame (one more after the last).
size_t framesOf(const std::vector<std::string>& script) {
    size_t frames = 0;
    bool changes = false;
    for (const std::string& line : script) {
        changes = line.rfind("set ", 0) == 0 || line.rfind("unset ", 0) == 0;
        frames += changes ? 0 : 1;
    }
    return frames + (changes ? 1 : 0);
}

// `sample` headless with the panel driven by `script` (a frame a line, then one frame more
// without the mouse: the frame after the last change).
PanelRun runScripted(const std::string& sample, const std::vector<std::string>& script,
                     const fs::path& dir, const std::string& name,
                     const std::vector<std::string>& args = {}) {
    const fs::path scriptPath = dir / (name + ".script");
    {
        std::ofstream out(scriptPath);
        for (const std::string& line : script) out << line << "\n";
    }
    PanelRun result;
    result.image = dir / (name + ".png");
    std::vector<std::string> argv = {sample,     "--headless",
                                     "--frames", std::to_string(framesOf(script) + 1),
                                     "--output", result.image.string()};
    argv.insert(argv.end(), kRunSize.begin(), kRunSize.end());
    argv.insert(argv.end(), args.begin(), args.end());
    // (in `dir`: an F12 line writes its picture there)
    result.run = runSample(
        argv, {.setEnv = {{"PBR_PANEL_SCRIPT", scriptPath.string()}}, .workingDirectory = dir});
    std::istringstream out(result.run.out);
    const std::string panelMark = sample + ": panel: ", commandMark = sample + ": command: ";
    for (std::string line; std::getline(out, line);) {
        if (line.rfind(panelMark, 0) == 0) {
            // "<id> x y w h", the id possibly with spaces ("--lights -")
            std::istringstream fields(line.substr(panelMark.size()));
            std::vector<std::string> words;
            for (std::string word; fields >> word;) words.push_back(word);
            if (words.size() < 5) continue;
            Rect rect{std::stoi(words[words.size() - 4]), std::stoi(words[words.size() - 3]),
                      std::stoi(words[words.size() - 2]), std::stoi(words[words.size() - 1])};
            std::string id;
            for (size_t i = 0; i + 4 < words.size(); ++i) id += (i ? " " : "") + words[i];
            result.controls[id] = rect;
        } else if (line.rfind(commandMark, 0) == 0) {
            result.command = line.substr(commandMark.size());
        }
    }
    return result;
}

std::vector<std::string> wordsOf(const std::string& command) {
    std::istringstream in(command);
    std::vector<std::string> words;
    for (std::string word; in >> word;) words.push_back(word);
    return words;
}

// The value the command line gives a flag ("" when it names the flag without one, nullopt when
// it does not name it).
std::optional<std::string> valueIn(const std::string& command, const std::string& flag) {
    const std::vector<std::string> words = wordsOf(command);
    for (size_t i = 0; i < words.size(); ++i) {
        if (words[i] != flag) continue;
        if (i + 1 < words.size() && words[i + 1].rfind("--", 0) != 0) return words[i + 1];
        return std::string();
    }
    return std::nullopt;
}

// Runs the command the panel showed, headless, into `output`; the bytes of its picture.
std::string drawCommand(const std::string& command, const fs::path& output) {
    std::vector<std::string> argv = wordsOf(command);
    EXPECT_FALSE(argv.empty());
    if (argv.empty()) return {};
    argv.insert(argv.end(), {"--headless", "--output", output.string()});
    const RunResult run = runSample(argv);
    EXPECT_EQ(run.exitCode, 0) << command << "\n" << run.err;
    return readBytes(output);
}

// The panel's layout at the start: one frame, no mouse.
std::map<std::string, Rect> layoutOf(const std::string& sample, const fs::path& dir,
                                     const std::vector<std::string>& args = {}) {
    const PanelRun run = runScripted(sample, {"-"}, dir, "layout", args);
    EXPECT_EQ(run.run.exitCode, 0) << run.run.err;
    return run.controls;
}

// The run after a change: clean, its frame that of the command it shows, and not the default
// picture (the change showed).
void expectFrameIsTheCommands(const PanelRun& changed, const fs::path& dir) {
    ASSERT_EQ(changed.run.exitCode, 0) << changed.run.err;
    EXPECT_EQ(changed.run.err.find("GL error"), std::string::npos) << changed.run.err;
    const std::string frame = readBytes(changed.image);
    ASSERT_FALSE(frame.empty());
    EXPECT_TRUE(frame == drawCommand(changed.command, dir / "command.png"))
        << "the frame after the change is not what `" << changed.command << "` draws";
    const PanelRun untouched = runScripted(wordsOf(changed.command)[0], {"-"}, dir, "untouched");
    EXPECT_FALSE(frame == readBytes(untouched.image)) << "the change did not show";
}

TEST(Panel, DraggingASliderIsTheFlagsValue) {
    const fs::path dir = testOutputDir("panel_slider");
    const auto controls = layoutOf("01_lighting", dir);
    ASSERT_TRUE(controls.count("--roughness-offset")) << "no slider for --roughness-offset";
    const Rect slider = controls.at("--roughness-offset");
    // Press on the grab (0 sits in the middle of -1..1) and drag it to 80 % of the way.
    const PanelRun changed =
        runScripted("01_lighting",
                    {"-", hover(slider.at(0.5)), hold(slider.at(0.5)), hold(slider.at(0.65)),
                     hold(slider.at(0.8)), hover(slider.at(0.8))},
                    dir, "dragged");
    std::printf("after the drag: %s\n", changed.command.c_str());
    const auto value = valueIn(changed.command, "--roughness-offset");
    ASSERT_TRUE(value) << "the drag did not set --roughness-offset: " << changed.command;
    // 80 % of the slider's travel from -1 to 1 (the grab's width takes a few pixels off)
    EXPECT_NEAR(std::strtod(value->c_str(), nullptr), 0.6, 0.05);
    EXPECT_FALSE(valueIn(changed.command, "--metallic-offset")) << changed.command;
    expectFrameIsTheCommands(changed, dir);
}

TEST(Panel, AStepperStepsTheFlag) {
    const fs::path dir = testOutputDir("panel_stepper");
    const auto controls = layoutOf("01_lighting", dir);
    ASSERT_TRUE(controls.count("--lights -")) << "no stepper for --lights";
    const std::string minus = controls.at("--lights -").at(0.5);
    // Two clicks on "-": 4 lights, then 3, then 2.
    const PanelRun changed = runScripted(
        "01_lighting", {"-", hover(minus), hold(minus), hover(minus), hold(minus), hover(minus)},
        dir, "stepped");
    std::printf("after two clicks: %s\n", changed.command.c_str());
    EXPECT_EQ(valueIn(changed.command, "--lights"), "2") << changed.command;
    expectFrameIsTheCommands(changed, dir);
    // Down to the flag's least, 0 (no light: the ambient term alone), where "-" stops.
    std::vector<std::string> down = {"-"};
    for (int i = 0; i < 5; ++i) down.insert(down.end(), {hover(minus), hold(minus)});
    down.push_back(hover(minus));
    const PanelRun least = runScripted("01_lighting", down, dir, "least");
    EXPECT_EQ(valueIn(least.command, "--lights"), "0") << least.command;
    expectFrameIsTheCommands(least, dir);
}

TEST(Panel, AComboBoxChoiceIsTheFlagsWord) {
    const fs::path dir = testOutputDir("panel_combo");
    const auto controls = layoutOf("01_lighting", dir);
    ASSERT_TRUE(controls.count("--view")) << "no combo box for --view";
    const std::string combo = controls.at("--view").at(0.5);
    // A click opens the list; its items are laid out in the frame after.
    const std::vector<std::string> open = {"-", hover(combo), hold(combo), hover(combo)};
    const PanelRun opened = runScripted("01_lighting", open, dir, "opened");
    ASSERT_TRUE(opened.controls.count("--view=d")) << "the list did not open:\n" << opened.run.out;
    const std::string item = opened.controls.at("--view=d").at(0.5);
    std::vector<std::string> choose = open;
    choose.insert(choose.end(), {hover(item), hold(item), hover(item)});
    const PanelRun changed = runScripted("01_lighting", choose, dir, "chosen");
    std::printf("after the choice: %s\n", changed.command.c_str());
    EXPECT_EQ(valueIn(changed.command, "--view"), "d") << changed.command;
    expectFrameIsTheCommands(changed, dir);
}

// A click shorter than a frame is not lost: the combo box opens and its item is chosen with
// clicks made between frames, the button up in every frame the panel reads (once, a combo box
// opened only when the button was held across two frames, 0.8 s at a software GL's pace).
TEST(Panel, AClickBetweenTwoFramesIsNotLost) {
    const fs::path dir = testOutputDir("panel_quick_click");
    const auto controls = layoutOf("01_lighting", dir);
    ASSERT_TRUE(controls.count("--view")) << "no combo box for --view";
    const std::string combo = controls.at("--view").at(0.5);
    const std::vector<std::string> open = {"-", hover(combo), click(combo), hover(combo)};
    const PanelRun opened = runScripted("01_lighting", open, dir, "opened");
    ASSERT_TRUE(opened.controls.count("--view=d")) << "the list did not open:\n" << opened.run.out;
    const std::string item = opened.controls.at("--view=d").at(0.5);
    std::vector<std::string> choose = open;
    choose.insert(choose.end(), {hover(item), click(item), hover(item)});
    const PanelRun changed = runScripted("01_lighting", choose, dir, "chosen");
    EXPECT_EQ(valueIn(changed.command, "--view"), "d") << changed.command;
}

// 07: a checkbox, and the orbit camera's place on the command line (x,y,z only).
TEST(Panel, ACheckboxSwitchesTheFlag) {
    const fs::path dir = testOutputDir("panel_checkbox");
    const auto controls = layoutOf("07_gltf_metallic_roughness", dir);
    ASSERT_TRUE(controls.count("--no-punctual")) << "no checkbox for --no-punctual";
    const std::string box = controls.at("--no-punctual").at(0.1);
    const PanelRun changed = runScripted("07_gltf_metallic_roughness",
                                         {"-", hover(box), hold(box), hover(box)}, dir, "switched");
    std::printf("after the click: %s\n", changed.command.c_str());
    EXPECT_EQ(valueIn(changed.command, "--no-punctual"), "") << changed.command;
    EXPECT_FALSE(valueIn(changed.command, "--no-ibl")) << changed.command;
    expectFrameIsTheCommands(changed, dir);
}

// 10's layer factors have no default (each material's own, from its file): given, a button beside
// the slider takes the flag back to not given, and the frame is the file's again.
TEST(Panel, ANumberWithoutADefaultIsTakenBackByItsButton) {
    const fs::path dir = testOutputDir("panel_unset");
    const std::string sample = "10_gltf_advanced_materials";
    const std::vector<std::string> args = {"--size", "960x540", "--msaa", "0"};
    std::vector<std::string> given = args;
    given.insert(given.end(), {"--clearcoat", "0.3"});
    const auto controls = layoutOf(sample, dir, given);
    ASSERT_TRUE(controls.count("--clearcoat unset")) << "no button to take --clearcoat back";
    const std::string button = controls.at("--clearcoat unset").at(0.5);
    const PanelRun taken =
        runScripted(sample, {"-", hover(button), hold(button), hover(button)}, dir, "taken", given);
    ASSERT_EQ(taken.run.exitCode, 0) << taken.run.err;
    std::printf("after the click: %s\n", taken.command.c_str());
    EXPECT_FALSE(valueIn(taken.command, "--clearcoat")) << taken.command;
    EXPECT_FALSE(taken.controls.count("--clearcoat unset")) << "the button stayed";
    const PanelRun untouched = runScripted(sample, {"-"}, dir, "untouched", args);
    const std::string frame = readBytes(taken.image);
    ASSERT_FALSE(frame.empty());
    EXPECT_TRUE(frame == readBytes(untouched.image))
        << "the frame after the click is not the file's own clear coats'";
}

// 07's exposure, a factor from 0.001 to 10000, slides in stops (-8 to +8, a tenth at a time):
// from the middle (1, 0 stops) to three quarters of the way is +4 stops, a factor of 16.
TEST(Panel, ExposureSlidesInStops) {
    const fs::path dir = testOutputDir("panel_exposure");
    const auto controls = layoutOf("07_gltf_metallic_roughness", dir);
    ASSERT_TRUE(controls.count("--exposure")) << "no slider for --exposure";
    const Rect slider = controls.at("--exposure");
    const PanelRun changed =
        runScripted("07_gltf_metallic_roughness",
                    {"-", hover(slider.at(0.5)), hold(slider.at(0.5)), hold(slider.at(0.62)),
                     hold(slider.at(0.75)), hover(slider.at(0.75))},
                    dir, "dragged");
    std::printf("after the drag: %s\n", changed.command.c_str());
    const auto value = valueIn(changed.command, "--exposure");
    ASSERT_TRUE(value) << changed.command;
    // a quarter of the travel is 4 stops (the grab's width takes a few pixels off)
    EXPECT_NEAR(std::log2(std::strtod(value->c_str(), nullptr)), 4.0, 0.35) << *value;
    expectFrameIsTheCommands(changed, dir);
}

// The panel need not hide the subject: it starts at the top right, its title bar drags it
// elsewhere, and the arrow on the title bar folds it to that bar.
TEST(Panel, ThePanelMovesAndFolds) {
    const fs::path dir = testOutputDir("panel_move_fold");
    const auto controls = layoutOf("01_lighting", dir);
    ASSERT_TRUE(controls.count("title") && controls.count("--lights -")) << "no title bar";
    const Rect title = controls.at("title");
    EXPECT_EQ(title.x + title.w, 640 - 10) << "not at the top right";
    const Rect lights = controls.at("--lights -");
    // drag the title bar 300 pixels left and 40 down
    const std::string grab = title.at(0.5);
    const std::string dropped = std::to_string(title.x + title.w / 2 - 300) + " " +
                                std::to_string(title.y + title.h / 2 + 40);
    const PanelRun moved = runScripted(
        "01_lighting", {"-", hover(grab), hold(grab), hold(dropped), hover(dropped)}, dir, "moved");
    ASSERT_TRUE(moved.controls.count("--lights -")) << moved.run.out;
    EXPECT_EQ(moved.controls.at("--lights -").x, lights.x - 300);
    EXPECT_EQ(moved.controls.at("--lights -").y, lights.y + 40);
    EXPECT_EQ(valueIn(moved.command, "--camera"), "0,0,23,-90,0") << "the drag turned the camera";
    // the fold arrow sits at the title bar's left end
    const std::string arrow =
        std::to_string(title.x + title.h / 2) + " " + std::to_string(title.y + title.h / 2);
    const PanelRun folded =
        runScripted("01_lighting", {"-", hover(arrow), click(arrow), hover(arrow)}, dir, "folded");
    EXPECT_TRUE(folded.controls.count("title")) << folded.run.out;
    EXPECT_FALSE(folded.controls.count("--lights -")) << "the panel did not fold";
}

// The copy button says that it copied, beside it, for as long as the command line is the copied
// one; a change of view takes the note away.
TEST(Panel, CopySaysItCopied) {
    const fs::path dir = testOutputDir("panel_copy");
    const auto controls = layoutOf("01_lighting", dir);
    ASSERT_TRUE(controls.count("copy")) << "no copy button";
    EXPECT_FALSE(controls.count("copied"));
    const std::string copy = controls.at("copy").at(0.5);
    const PanelRun copied =
        runScripted("01_lighting", {"-", hover(copy), click(copy), hover(copy)}, dir, "copied");
    EXPECT_TRUE(copied.controls.count("copied")) << copied.run.out;
    EXPECT_NE(copied.run.out.find("01_lighting: copied: " + copied.command), std::string::npos)
        << copied.run.out;
    ASSERT_TRUE(controls.count("--lights -"));
    const std::string minus = controls.at("--lights -").at(0.5);
    const PanelRun changed = runScripted(
        "01_lighting", {"-", hover(copy), click(copy), hover(minus), click(minus), hover(minus)},
        dir, "changed");
    EXPECT_FALSE(changed.controls.count("copied")) << changed.command;
}

// A scroll zooms the fly camera (its field of view), and the command line says so: the frame after
// the scroll is what that command draws (--fov), not the unzoomed picture.
TEST(Panel, AScrolledFieldOfViewIsOnTheCommandLine) {
    const fs::path dir = testOutputDir("panel_scroll");
    const PanelRun zoomed =
        runScripted("01_lighting", {"-", "60 300 0 3", "60 300 0"}, dir, "zoomed");
    ASSERT_EQ(zoomed.run.exitCode, 0) << zoomed.run.err;
    std::printf("after the scroll: %s\n", zoomed.command.c_str());
    const std::optional<std::string> fov = valueIn(zoomed.command, "--fov");
    ASSERT_TRUE(fov) << zoomed.command;
    EXPECT_EQ(*fov, "42") << "45 degrees, 3 steps of 1 degree narrower";
    expectFrameIsTheCommands(zoomed, dir);
}

// The mouse over the panel is the panel's: the same drag outside it turns the camera.
TEST(Panel, TheMouseOverThePanelLeavesTheCameraAlone) {
    const fs::path dir = testOutputDir("panel_camera");
    const auto controls = layoutOf("01_lighting", dir);
    ASSERT_TRUE(controls.count("--roughness-offset"));
    const Rect slider = controls.at("--roughness-offset");
    const PanelRun onPanel = runScripted(
        "01_lighting", {"-", hover(slider.at(0.5)), hold(slider.at(0.5)), hold(slider.at(0.52))},
        dir, "on_panel");
    EXPECT_EQ(valueIn(onPanel.command, "--camera"), "0,0,23,-90,0") << onPanel.command;
    const PanelRun outside =
        // (at the left: the panel sits at the top right)
        runScripted("01_lighting", {"-", "60 300 0", "60 300 1", "100 300 1"}, dir, "outside");
    EXPECT_NE(valueIn(outside.command, "--camera"), "0,0,23,-90,0")
        << "a drag over the picture should turn the camera: " << outside.command;
}

// Tab hides the panel, and the mouse looks again (01's fly camera): the move of the frame in
// which Tab was pressed was made with a free cursor, and must not turn the camera (at a software
// GL's 1-3 frames a second it is the whole way the hand went before Tab; once it turned the
// camera). The next move does.
TEST(Panel, TabHidesThePanelWithoutTurningTheCamera) {
    const fs::path dir = testOutputDir("panel_tab");
    const PanelRun hidden =
        runScripted("01_lighting", {"-", "100 300 0", "300 250 0 0 Tab", "-"}, dir, "hidden");
    ASSERT_EQ(hidden.run.exitCode, 0) << hidden.run.err;
    EXPECT_EQ(valueIn(hidden.command, "--camera"), "0,0,23,-90,0") << hidden.command;
    const PanelRun looked = runScripted(
        "01_lighting", {"-", "100 300 0", "300 250 0 0 Tab", "320 250 0", "-"}, dir, "looked");
    ASSERT_EQ(looked.run.exitCode, 0) << looked.run.err;
    EXPECT_NE(valueIn(looked.command, "--camera"), "0,0,23,-90,0")
        << "after Tab the mouse should look: " << looked.command;
}

// A moved camera's command line draws the very same picture: the fly camera's pose (01) and the
// orbit camera's (07, which once replayed 339 pixels one level off), each number the shortest
// text that reads back to the same float (never "2.200000047683716").
TEST(Panel, AMovedCamerasCommandDrawsTheSamePicture) {
    const fs::path dir = testOutputDir("panel_camera_replay");
    for (const std::string sample : {"01_lighting", "07_gltf_metallic_roughness"}) {
        const PanelRun moved = runScripted(
            sample, {"-", "60 300 0", "60 300 1", "97 289 1", "121 262 1"}, dir, sample);
        ASSERT_EQ(moved.run.exitCode, 0) << moved.run.err;
        const std::optional<std::string> camera = valueIn(moved.command, "--camera");
        ASSERT_TRUE(camera) << "the drag did not move the camera: " << moved.command;
        std::printf("%s after the drag: %s\n", sample.c_str(), moved.command.c_str());
        std::istringstream numbers(*camera);
        for (std::string number; std::getline(numbers, number, ',');) {
            const size_t digits = std::count_if(number.begin(), number.end(),
                                                [](char c) { return c >= '0' && c <= '9'; });
            EXPECT_LE(digits, 9u) << number << " in " << moved.command;
        }
        EXPECT_TRUE(readBytes(moved.image) ==
                    drawCommand(moved.command, dir / (sample + "_command.png")))
            << sample << ": the picture after the drag is not what `" << moved.command << "` draws";
    }
}

// Every live flag, raised and then lowered while the sample runs (PBR_PANEL_SCRIPT's "set" lines,
// the way a page's controls and the panel's change a flag): once all of a case's flags are
// raised, the frame must be, byte for byte, what a run started with them draws; so must it once
// all are lowered from there. 04 once looped over all four lights while --lights said 2, which
// only a lowering shows. Then each flag alone is moved back, live: the picture must change, so
// that each flag is seen in the state the comparison checks (a flag the sample reads once at
// start-up fails here too). Every live control of a sample's panel must be in one of its cases.
struct LiveFlag {
    std::string flag;
    // the values ("" for a switch: on; nullopt: left out, a switch off or a flag at its default)
    std::optional<std::string> raised, lowered;
};
struct LiveCase {
    std::string name;  // the test's
    std::string sample;
    std::vector<std::string> args;  // where the case's flags show
    std::vector<LiveFlag> flags;
};

void PrintTo(const LiveCase& c, std::ostream* out) {
    *out << c.name;
}

const std::optional<std::string> kOn = std::string(), kOff = std::nullopt;

const std::vector<LiveCase>& liveCases() {
    // A case's flags must each show in both states: --light (one light alone) hides --lights,
    // --no-ibl hides the split sum, a term view hides the sky and the tone mapper, and the BRDF's
    // terms (specular, diffuse) leave out the light's colour and attenuation.
    const LiveFlag view = {"--view", "specular", "diffuse"}, gain = {"--gain", "4", "0.5"};
    static std::vector<LiveCase> cases = {
        {"lighting01",
         "01_lighting",
         {},
         {{"--lights", "4", "1"},
          {"--light-color", "600,300,150", "50,100,200"},
          {"--albedo", "0.9,0.6,0.1", "0.1,0.2,0.5"},
          {"--roughness-offset", "0.3", "-0.3"},
          {"--metallic-offset", "0.4", "-0.4"}}},
        {"view01", "01_lighting", {}, {view, gain, {"--light", "3", "0"}}},
        {"maps02",
         "02_lighting_textured",
         {},
         {{"--no-albedo-map", kOn, kOff},
          {"--no-normal-map", kOn, kOff},
          {"--no-metallic-map", kOn, kOff},
          {"--no-roughness-map", kOn, kOff},
          {"--no-ao-map", kOn, kOff}}},
        {"material02",
         "02_lighting_textured",
         {},
         {{"--material", "gold", "grass"},
          {"--tangent-frame", "derivatives", "mesh"},
          {"--view", "specular", "ndotl"},  // (the diffuse term leaves the normal out)
          gain}},
        {"view04", "04_ibl_irradiance", {}, {{"--lights", "4", "1"}, view, gain}},
        {"sky04",
         "04_ibl_irradiance",
         {},
         {{"--no-ibl", kOn, kOff},
          {"--background", "irradiance", "environment"},
          {"--light", "3", "0"}}},
        {"view05", "05_ibl_specular", {}, {{"--lights", "4", "1"}, view, gain}},
        {"sky05",
         "05_ibl_specular",
         {},
         {{"--split-sum", "exact", "text"},
          {"--background", "prefiltered", "environment"},
          {"--background-lod", "3", "0"}}},
        {"light05", "05_ibl_specular", {}, {{"--no-ibl", kOn, kOff}, {"--light", "3", "0"}}},
        {"light09",
         "09_light_types",
         {},
         {{"--only", "point", "all"},
          {"--point-lights", "8", "0"},
          {"--attenuation", "1,0.09,0.032", "1,0.7,1.8"}}},
        {"view09", "09_light_types", {}, {view, gain}},
    };
    // 07, 08 and 10: the same viewer, the same flags (10's with a program a material's layers:
    // each live change must reach every one of them)
    static const bool viewers = [&] {
        for (const auto& [number, sample] : {std::pair{"07", "07_gltf_metallic_roughness"},
                                             {"08", "08_gltf_specular_glossiness"},
                                             {"10", "10_gltf_advanced_materials"}}) {
            cases.push_back({std::string("light") + number,
                             sample,
                             {},
                             {{"--tonemap", "aces", "none"},
                              {"--exposure", "4", "0.25"},
                              {"--light", "2", "0"},
                              {"--single-scattering", kOn, kOff}}});
            cases.push_back({std::string("sources") + number,
                             sample,
                             {},
                             {{"--no-ibl", kOn, kOff}, {"--no-punctual", kOn, kOff}}});
            cases.push_back({std::string("view") + number, sample, {}, {view, gain}});
        }
        return true;
    }();
    (void)viewers;
    // 10's layers' factors, each given live and taken back to the materials' own (unset)
    static const bool layers = [&] {
        const std::optional<std::string> own;  // not given: each material's from the file
        cases.push_back({"coat10",
                         "10_gltf_advanced_materials",
                         {},
                         {{"--clearcoat", "0.3", own},
                          {"--clearcoat-roughness", "0.6", own},
                          {"--sheen-color", "0.1,0.9,0.1", own},
                          {"--sheen-roughness", "0.9", own},
                          {"--ior", "2.2", own},
                          {"--specular", "0.3", own},
                          {"--specular-color", "0.2,0.9,0.9", own},
                          {"--emissive-strength", "3", own}}});
        cases.push_back({"glass10",
                         "10_gltf_advanced_materials",
                         {},
                         {{"--transmission", "0.5", own},
                          {"--thickness", "0.3", own},
                          {"--attenuation-color", "0.9,0.2,0.2", own},
                          {"--attenuation-distance", "0.05", own}}});
        return true;
    }();
    (void)layers;
    return cases;
}

std::string setLine(const std::string& flag, const std::optional<std::string>& value) {
    if (!value) return "unset " + flag;
    return value->empty() ? "set " + flag : "set " + flag + " " + *value;
}

class LiveFlags : public ::testing::TestWithParam<LiveCase> {};

TEST_P(LiveFlags, RaisedAndLoweredLiveEachDrawsWhatItsCommandDraws) {
    const LiveCase& c = GetParam();
    const fs::path dir = testOutputDir("live_flags_" + c.name);
    // The script, and the frame of each picture it takes (F12 writes screenshot-<sample>-<frame>;
    // a flag's line is not a frame, but changes the next).
    std::vector<std::string> script = {"-"};
    size_t frames = 1;
    const auto shot = [&] {
        script.push_back("F12");
        return frames++;
    };
    struct Phase {
        const char* name;
        size_t all = 0;                  // every flag moved
        std::vector<size_t> eachBack{};  // one flag moved back
    };
    Phase phases[2] = {{"raised"}, {"lowered"}};
    for (int p = 0; p < 2; ++p) {
        const auto to = [&](const LiveFlag& f) { return p == 0 ? f.raised : f.lowered; };
        const auto back = [&](const LiveFlag& f) { return p == 0 ? f.lowered : f.raised; };
        for (const LiveFlag& f : c.flags) script.push_back(setLine(f.flag, to(f)));
        phases[p].all = shot();
        for (const LiveFlag& f : c.flags) {
            script.push_back(setLine(f.flag, back(f)));
            phases[p].eachBack.push_back(shot());
            script.push_back(setLine(f.flag, to(f)));
        }
    }
    // small and single-sampled: the frames are many, and a change shows at any size
    const std::vector<std::string> small = {"--size", "160x90", "--msaa", "0"};
    std::vector<std::string> args = small;
    args.insert(args.end(), c.args.begin(), c.args.end());
    const PanelRun live = runScripted(c.sample, script, dir, "live", args);
    const RunResult& run = live.run;
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err.find("GL error"), std::string::npos) << run.err;
    // (02 once set the sampler of a map its switch had compiled out, a note each change)
    EXPECT_EQ(run.err.find("no active uniform"), std::string::npos) << run.err;
    const auto picture = [&](size_t frame) {
        return readBytes(dir / ("screenshot-" + c.sample + "-" + std::to_string(frame) + ".png"));
    };
    for (int p = 0; p < 2; ++p) {
        // A run started with the phase's values.
        std::vector<std::string> argv = {c.sample, "--headless", "--output",
                                         (dir / (std::string(phases[p].name) + ".png")).string()};
        argv.insert(argv.end(), args.begin(), args.end());
        std::string flags;
        for (const LiveFlag& f : c.flags) {
            const std::optional<std::string>& value = p == 0 ? f.raised : f.lowered;
            if (!value) continue;
            argv.push_back(f.flag);
            if (!value->empty()) argv.push_back(*value);
            flags += " " + f.flag + (value->empty() ? "" : " " + *value);
        }
        const RunResult started = runSample(argv);
        ASSERT_EQ(started.exitCode, 0) << started.err;
        const std::string all = picture(phases[p].all);
        ASSERT_FALSE(all.empty()) << "no screenshot of frame " << phases[p].all << "\n" << run.out;
        EXPECT_TRUE(all == readBytes(dir / (std::string(phases[p].name) + ".png")))
            << c.sample << ": the flags " << phases[p].name
            << " live do not draw what a run started with them draws:" << flags;
        for (size_t i = 0; i < c.flags.size(); ++i) {
            EXPECT_FALSE(picture(phases[p].eachBack[i]) == all)
                << c.sample << ": moving " << c.flags[i].flag << " back, live, from the "
                << phases[p].name << " state (" << flags << ") changed nothing";
        }
    }
    // Every live control of the sample's panel is in one of its cases.
    std::set<std::string> covered;
    for (const LiveCase& other : liveCases()) {
        if (other.sample != c.sample) continue;
        for (const LiveFlag& f : other.flags) covered.insert(f.flag);
    }
    for (const auto& [id, rect] : live.controls) {
        if (id.rfind("--", 0) != 0) continue;
        const std::string flag = id.substr(0, id.find_first_of(" ="));
        EXPECT_TRUE(covered.count(flag)) << c.sample << "'s live " << flag << " is in no case";
    }
}

INSTANTIATE_TEST_SUITE_P(Every, LiveFlags, ::testing::ValuesIn(liveCases()),
                         [](const auto& info) { return info.param.name; });

// The samples without a case have no live control.
TEST(LiveFlags, TheSamplesWithoutACaseHaveNoLiveControl) {
    const fs::path dir = testOutputDir("live_flags_none");
    for (const std::string sample : {"03_gltf_unlit", "06_brdf_lut"}) {
        for (const LiveCase& c : liveCases()) ASSERT_NE(c.sample, sample);
        for (const auto& [id, rect] : layoutOf(sample, dir)) {
            EXPECT_NE(id.rfind("--", 0), 0u) << sample << "'s live " << id << " is in no case";
        }
    }
}

}  // namespace
}  // namespace pbr::test
