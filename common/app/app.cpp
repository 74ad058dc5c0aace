#include "app/app.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "app/panel_script.h"
#include "base/error.h"
#include "base/output.h"
#include "base/paths.h"
#include "context/web.h"
#include "files/image.h"
#include "gl/mesh.h"

namespace pbr {

namespace fs = std::filesystem;

namespace {

constexpr int kBenchmarkFrames = 30;

// When the program started, near enough: the clock is read while statics are initialised, before
// main (the dynamic loader's few milliseconds come before it). --benchmark's first_frame_s counts
// from here, as a user waiting for the first picture would.
const std::chrono::steady_clock::time_point kProcessStart = std::chrono::steady_clock::now();
std::chrono::steady_clock::time_point processStart() {
    return kProcessStart;
}

double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    // Nearest rank: the smallest value with at least p of the samples at or below it.
    const size_t rank = size_t(std::ceil(p * double(values.size())));
    return values[std::clamp<size_t>(rank, 1, values.size()) - 1];
}

std::string jsonEscape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) continue;
        out += c;
    }
    return out;
}

// PBR_PANEL_SCRIPT (see panel_script.h): the tests drive the panel headless with it.
std::vector<ScriptFrame> readPanelScript(const fs::path& path) {
    std::ifstream in(path);
    if (!in) throw Error(utf8Path(path) + ": cannot read the panel script (PBR_PANEL_SCRIPT)");
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    return parsePanelScript(text, utf8Path(path));
}

#ifdef PBR_WEBGL
// The sample's flag declarations for the page's controls (web::declareFlags), their values now.
std::string flagsJson(const std::vector<FlagSpec>& flags, const Options& options) {
    auto text = [](const std::string& value) { return "\"" + jsonEscape(value) + "\""; };
    std::string json = "[";
    for (const FlagSpec& spec : flags) {
        static const char* const kKinds[] = {"switch", "text",    "folder", "integer",
                                             "number", "numbers", "choice"};
        std::string choices;
        for (const std::string& choice : spec.choices)
            choices += (choices.empty() ? "" : ",") + text(choice);
        const auto value = options.sampleFlags.find(spec.name);
        json += std::string(json.size() > 1 ? "," : "") + "{\"name\":" + text(spec.name) +
                ",\"kind\":\"" + kKinds[int(spec.kind)] + "\",\"help\":" + text(spec.help) +
                ",\"min\":" + flagNumberText(spec.min) + ",\"max\":" + flagNumberText(spec.max) +
                ",\"count\":" + std::to_string(spec.count) + ",\"choices\":[" + choices +
                "],\"default\":" + text(spec.defaultValue) +
                ",\"live\":" + (spec.live ? "true" : "false") + ",\"value\":" +
                (value == options.sampleFlags.end() ? std::string("null") : text(value->second)) +
                "}";
    }
    return json + "]";
}
#endif

}  // namespace

App::App(int argc, char** argv, AppConfig config) : config_(std::move(config)) {
    if (config_.title.empty()) config_.title = config_.name;
    program_ = argc > 0 ? utf8Path(pathFromUtf8(argv[0]).filename()) : config_.name;
    usage_ = usageText(program_, config_.flags, config_.orbitCamera);
    std::vector<std::string> args(argv + std::min(argc, 1), argv + argc);
    try {
        options_ = parseOptions(args, config_.flags);
    } catch (const UsageError& e) {
        throw UsageError(e.what(), usage_);
    }
    if (options_.help) {
        std::fputs(usage_.c_str(), stdout);
        throw ExitRequest{0};
    }
    if (config_.orbitCamera && options_.camera && options_.camera->yaw) {
        throw UsageError(
            "--camera: this sample's orbit camera looks at the model's centre: give x,y,z only, "
            "without yaw and pitch",
            usage_);
    }
    // Where files will go, checked before any window opens or anything is computed: a picture
    // that cannot be written should not cost a render first.
    if (!options_.output.empty()) requireWritableFilePath(outputPath(), options_.output);
    for (const FlagSpec& spec : config_.flags) {
        const auto value = flag(spec.name);
        if (spec.kind == FlagSpec::Kind::OutputFolder && value) {
            requireOutputFolder(pathFromUtf8(*value), spec.name + " " + *value);
        }
    }

    // A page's header has said which bundle it loaded: now the program sets up (nothing natively).
    web::status("starting");

    if (!options_.headless) {
        std::string whyNot;
        context_ =
            createGlfwContext(config_.title, options_.width, options_.height, !options_.benchmark,
                              !config_.orbitCamera && !config_.fixedView, whyNot);
        if (!context_ && offscreenBackends().empty()) {
            throw Error(config_.name + ": " + whyNot +
                        ", and this build has no offscreen backend (built without OSMesa and EGL)");
        }
        if (!context_) {
            // The main command must still show something: render offscreen and say where.
            std::fprintf(stderr, "%s: %s; rendering offscreen instead\n", config_.name.c_str(),
                         whyNot.c_str());
            noDisplayFallback_ = true;
        }
    }
    // A debug context, so that KHR_debug reports every error, except for --benchmark: a real
    // driver checks more in one, and the frame times would show it.
    if (!context_) {
        context_ = createOffscreenContext(options_.backend, options_.width, options_.height,
                                          !options_.benchmark);
    }
    startSeconds_ = context_->seconds();
    forgetCurrentProgram();  // a new context: no program of ours is current in it

    installDebugOutput();
#ifndef PBR_WEBGL
    // Cube maps filter across face edges (GL 3.2 core): every IBL map relies on it, whether it
    // was just computed or loaded from the cache. (OpenGL ES 3 always does, with no switch.)
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
#endif
    const glm::ivec2 size = context_->windowed() ? context_->framebufferSize()
                                                 : glm::ivec2(options_.width, options_.height);
    target_ = std::make_unique<RenderTarget>(std::max(size.x, 1), std::max(size.y, 1),
                                             options_.msaa, config_.srgbTarget);

    if (options_.camera) {
        const CameraStart& start = *options_.camera;
        camera_ = FlyCamera({start.x, start.y, start.z}, start.yaw.value_or(config_.cameraYaw),
                            start.pitch.value_or(config_.cameraPitch));
    } else {
        camera_ = FlyCamera(config_.cameraPosition, config_.cameraYaw, config_.cameraPitch);
    }
    if (options_.fov) camera_.setZoom(float(*options_.fov));

    if (options_.benchmark) {
        // One more than measured: the first frame compiles shader variants and is not counted.
        framesWanted_ = options_.frames.value_or(kBenchmarkFrames) + 1;
    } else if (options_.frames) {
        framesWanted_ = *options_.frames;
    } else {
        framesWanted_ = headless() ? 1 : 0;
    }
    if (options_.benchmark) context_->setVsync(false);

    // The live panel: in a window (hidden at first for --benchmark, whose frames are the
    // sample's), with --panel, and when a script drives it.
    const char* script = std::getenv("PBR_PANEL_SCRIPT");
    scripted_ = script && *script;
    if (scripted_) {
        scriptPath_ = script;
        script_ = readPanelScript(pathFromUtf8(scriptPath_));
    }
    if (Panel::available() &&
        (context_->windowed() || options_.panel || options_.caption || scripted_)) {
        panel_ = std::make_unique<Panel>(config_.flags, [this](const std::string& text) {
            context_->setClipboard(text);
            if (!context_->windowed())
                std::printf("%s: copied: %s\n", config_.name.c_str(), text.c_str());
        });
        // (--caption alone draws the overlay's labels and caption without the panel)
        panelShown_ = context_->windowed() ? !options_.benchmark : options_.panel || scripted_;
    }
    if (context_->windowed() && !config_.orbitCamera && !config_.fixedView) {
        context_->setCursorCaptured(mouseLook());
    }
#ifdef PBR_WEBGL
    web::declareFlags(flagsJson(config_.flags, options_));  // the page's own controls
    web::mouseHint(config_.orbitCamera
                       ? "drag the picture to orbit the model, scroll dollies, Esc ends the run"
                   : config_.fixedView
                       ? "Esc ends the run"
                       : "click the picture to look around (WASD moves, scroll zooms, Esc ends "
                         "the run)");
#endif
    checkGlErrors("start-up");
}

bool App::mouseLook() const {
    return !(panel_ && panelShown_);
}

void App::useOrbitCamera(const glm::vec3& boundsMin, const glm::vec3& boundsMax,
                         std::optional<glm::vec3> start) {
    if (!config_.orbitCamera) {
        throw Error(config_.name +
                    ": useOrbitCamera needs AppConfig::orbitCamera = true (so that --camera is "
                    "checked before any context, and the window leaves the cursor free)");
    }
    orbitBoundsMin_ = boundsMin;
    orbitBoundsMax_ = boundsMax;
    if (options_.camera) {
        const CameraStart& given = *options_.camera;
        orbitEye_ = glm::vec3(given.x, given.y, given.z);
    } else if (start) {
        orbitEye_ = *start;
    }
    orbit_ = orbitEye_ ? OrbitCamera::fromPosition(boundsMin, boundsMax, *orbitEye_)
                       : OrbitCamera::framing(boundsMin, boundsMax, aspect());
}

App::~App() {
    panel_.reset();
    shaders_.clear();
    groundQuad_.reset();
    target_.reset();
    // Everything a sample made was declared after the App and is gone by now: whatever GL still
    // knows of is a leak. (Skipped while unwinding from an error: that run already failed.)
    if (context_ && !std::uncaught_exceptions()) {
        useProgram(0);  // a deleted program stays alive while it is current
        const GlObjectCensus census = takeGlObjectCensus();
        if (census.total() > 0) {
            std::fprintf(stderr, "%s: error: GL objects leaked: %s\n", config_.name.c_str(),
                         census.describe().c_str());
        }
    }
}

std::optional<std::string> App::flag(const std::string& name) const {
    auto found = options_.sampleFlags.find(name);
    if (found == options_.sampleFlags.end()) return std::nullopt;
    return found->second;
}

std::optional<fs::path> App::flagPath(const std::string& name) const {
    const std::optional<std::string> text = flag(name);
    if (!text) return std::nullopt;
    return pathFromUtf8(*text);
}

fs::path App::outputPath() const {
    return pathFromUtf8(options_.output);
}

const FlagSpec& App::sampleFlag(const std::string& name) const {
    for (const FlagSpec& spec : config_.flags) {
        if (spec.name == name) return spec;
    }
    throw Error("the sample asks for a flag it does not declare: " + name);
}

std::string App::flagChoice(const std::string& name) const {
    const FlagSpec& spec = sampleFlag(name);
    if (spec.kind != FlagSpec::Kind::Choice || spec.choices.empty())
        throw Error(name + " is not a choice flag");
    return flag(name).value_or(spec.choices.front());
}

int App::flagInt(const std::string& name) const {
    const FlagSpec& spec = sampleFlag(name);
    if (spec.kind != FlagSpec::Kind::Integer) throw Error(name + " is not a whole-number flag");
    return parseIntFlag(name, flag(name).value_or(spec.defaultValue), int(spec.min), int(spec.max));
}

float App::flagNumber(const std::string& name) const {
    const std::optional<float> value = flagNumberIfAny(name);
    if (!value) throw Error(name + " has no default: the sample must ask whether it was given");
    return *value;
}

std::optional<float> App::flagNumberIfAny(const std::string& name) const {
    const FlagSpec& spec = sampleFlag(name);
    if (spec.kind != FlagSpec::Kind::Number) throw Error(name + " is not a number flag");
    const auto value = flag(name);
    if (!value && spec.defaultValue.empty()) return std::nullopt;
    return float(parseNumberFlag(name, value.value_or(spec.defaultValue), spec.min, spec.max));
}

std::optional<std::vector<float>> App::flagNumbers(const std::string& name) const {
    const FlagSpec& spec = sampleFlag(name);
    if (spec.kind != FlagSpec::Kind::Numbers) throw Error(name + " is not a list of numbers");
    const auto value = flag(name);
    if (!value && spec.defaultValue.empty()) return std::nullopt;
    std::vector<float> numbers;
    for (const double n : parseNumbersFlag(spec, value.value_or(spec.defaultValue))) {
        numbers.push_back(float(n));
    }
    return numbers;
}

glm::vec3 App::flagVec3(const std::string& name) const {
    const auto numbers = flagNumbers(name);
    if (!numbers || numbers->size() != 3)
        throw Error(name + " is not three numbers with a default");
    return {(*numbers)[0], (*numbers)[1], (*numbers)[2]};
}

void App::addOutputFile(fs::path path, std::string bytes) {
    outputFiles_.emplace_back(std::move(path), std::move(bytes));
}

Shader& App::shader(const std::string& vertex, const std::string& fragment,
                    std::vector<std::string> defines) {
    std::string key = vertex + '\n' + fragment;
    for (const std::string& define : defines) key += '\n' + define;
    for (size_t i = 0; i < shaderKeys_.size(); ++i) {
        if (shaderKeys_[i] == key) return shaders_[i];
    }
    Shader& made = shaders_.emplace_back(vertex, fragment, std::move(defines));
    shaderKeys_.push_back(std::move(key));
    return made;
}

void App::clearFrame(View view, const glm::vec3& pictureColor) {
    glClearColor(pictureColor.r, pictureColor.g, pictureColor.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (view == View::Final) return;
    const SavedGlState saved;
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    Shader& ground = shader("ibl/fullscreen.vert", "common/view_ground.frag");
    // levels 32 and 96 in the picture (an sRGB target encodes what it is given): any flat grey
    // is 32 levels or more from one of them (56 and 72 hid 08's spheres of roughness 0.25)
    const auto level = [&](float byte) {
        const float v = byte / 255.0f;
        return glm::vec3(config_.srgbTarget ? std::pow((v + 0.055f) / 1.055f, 2.4f) : v);
    };
    ground.use();
    ground.set("dark", level(32.0f));
    ground.set("light", level(96.0f));
    if (!groundQuad_) groundQuad_ = std::make_unique<GpuMesh>(quad());
    groundQuad_->draw();
}

void App::label(const glm::vec2& pixel, const std::string& text) {
#ifdef PBR_WEBGL
    if (context_->windowed()) web::label(pixel.x, pixel.y, text);  // the page places them
#else
    if (panel_) panel_->label(pixel, text);
#endif
}

void App::label(const glm::vec3& world, const std::string& text) {
    const glm::vec4 clip = projection() * view() * glm::vec4(world, 1.0f);
    if (clip.w <= 0.0f) return;  // behind the camera
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    label(
        glm::vec2((0.5f + 0.5f * ndc.x) * float(width()), (0.5f - 0.5f * ndc.y) * float(height())),
        text);
}

void labelSphereGrid(App& app, const SphereGrid& grid, float roughnessOffset,
                     float metallicOffset) {
    // Metallic up the rows, at the left; roughness across the columns, underneath.
    auto number = [](float value) {
        char text[16];
        std::snprintf(text, sizeof text, "%.2f", value);
        return std::string(text);
    };
    const float x = grid.position(0, 0).x - 0.9f * grid.spacing;
    for (int row = 0; row < grid.nrRows; ++row) {
        const glm::vec3 at = grid.position(row, 0);
        const float metallic =
            std::clamp(float(row) / float(grid.nrRows) + metallicOffset, 0.0f, 1.0f);
        app.label(glm::vec3(x, at.y, at.z), "metallic " + number(metallic));
    }
    const float y = grid.position(0, 0).y - 0.52f * grid.spacing;  // just under the bottom row
    app.label(glm::vec3(x, y, grid.z), "roughness");
    for (int col = 0; col < grid.nrColumns; ++col) {
        const glm::vec3 at = grid.position(0, col);
        app.label(
            glm::vec3(at.x, y, at.z),
            number(std::clamp(float(col) / float(grid.nrColumns) + roughnessOffset, 0.05f, 1.0f)));
    }
}

std::optional<View> App::currentView() const {
    const bool hasViews = std::any_of(config_.flags.begin(), config_.flags.end(),
                                      [](const FlagSpec& spec) { return spec.name == "--view"; });
    if (!hasViews) return std::nullopt;
    return viewNamed(flagChoice("--view"));
}

std::vector<FlagSpec> gridLightFlags() {
    return {FlagSpec::integer("--lights", "N", "use the first N of the 4 point lights", 0, 4, 4)
                .asLive(),
            FlagSpec::integer("--light", "K",
                              "light K (1-4) alone, its terms alone in a view (0: as --lights "
                              "says)",
                              0, 4, 0)
                .asLive()};
}

std::span<const glm::vec3> gridLights(const App& app) {
    const std::span<const glm::vec3> all(kGridLightPositions);
    if (const int alone = app.flagInt("--light"); alone > 0)
        return all.subspan(size_t(alone - 1), 1);
    return all.first(size_t(app.flagInt("--lights")));
}

std::string App::commandLine() const {
    // A value with characters a shell would take apart is quoted.
    auto quoted = [](const std::string& text) {
        const bool plain =
            !text.empty() && text.find_first_not_of(
                                 "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                 "0123456789-_.,/+=:") == std::string::npos;
        if (plain) return text;
        std::string out = "'";
        for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
        return out + "'";
    };
    std::string line =
        program_ + " --size " + std::to_string(width()) + "x" + std::to_string(height());
    const auto camera = [&](const glm::vec3& eye) {
        line += " --camera " + flagNumberText(eye.x) + "," + flagNumberText(eye.y) + "," +
                flagNumberText(eye.z);
    };
    if (orbit_) {
        if (orbitEye_) camera(*orbitEye_);  // none: the framing, as without --camera
    } else if (!config_.fixedView) {
        camera(camera_.position());
    }
    if (!orbit_ && !config_.orbitCamera && !config_.fixedView) {
        line += "," + flagNumberText(camera_.yaw()) + "," + flagNumberText(camera_.pitch());
    }
    if (!orbit_ && !config_.orbitCamera && !config_.fixedView &&
        camera_.zoom() != FlyCamera::kDefaultZoom) {
        line += " --fov " + flagNumberText(camera_.zoom());  // scrolled
    }
    if (paused_) {
        line += " --time " + flagNumberText(pausedTime_);
    } else if (options_.time) {
        line += " --time " + flagNumberText(*options_.time);
    }
    if (options_.msaa != 4) line += " --msaa " + std::to_string(options_.msaa);
    for (const FlagSpec& spec : config_.flags) {
        const auto value = flag(spec.name);
        if (!value) continue;
        line += " " + spec.name;
        if (spec.kind != FlagSpec::Kind::Switch) line += " " + quoted(*value);
    }
    return line;
}

void App::bindRenderTarget() const {
    target_->bind();
}

std::string App::renderer() const {
    const GLubyte* text = glGetString(GL_RENDERER);
    return text ? reinterpret_cast<const char*>(text) : "unknown";
}

bool App::nextFrame() {
    if (finished_) return false;
    if (frameIndex_ >= 0) endFrame();
    const bool framesDone = framesWanted_ > 0 && frameIndex_ + 1 >= framesWanted_;
    InputFrame input = context_->pollInput();
    if (framesDone || input.quit) {
        finish();
        return false;
    }
    ++frameIndex_;
    if (scripted_) {
        // The script's mouse, and what a window would make of it: the move since the last
        // frame (y up), and the part of it made with the button held.
        const auto scriptedAt = [this](int frame) {
            return frame >= 0 && size_t(frame) < script_.size() ? script_[size_t(frame)].input
                                                                : InputFrame{};
        };
        const InputFrame scripted = scriptedAt(frameIndex_), before = scriptedAt(frameIndex_ - 1);
        if (size_t(frameIndex_) < script_.size()) {
            // Live flags set as a page's controls set them; a script that names another flag, or
            // a value the flag refuses, ends the run (the test that wrote it is wrong).
            for (const ScriptFlagChange& change : script_[size_t(frameIndex_)].changes) {
                if (!setLiveFlag(change.flag, change.value)) {
                    throw Error(scriptPath_ + ": frame " + std::to_string(frameIndex_ + 1) + ": " +
                                change.flag +
                                (change.value ? " " + printable(*change.value) : std::string()) +
                                ": not a live flag of " + config_.name + ", or a value it refuses");
                }
            }
        }
        input.screenshot = scripted.screenshot;
        input.togglePanel = scripted.togglePanel;
        input.cursor = scripted.cursor;
        input.leftButton = scripted.leftButton;
        input.leftPresses = scripted.leftPresses;
        input.scroll = scripted.scroll;
        if (scripted.cursor.x >= 0.0f && before.cursor.x >= 0.0f) {
            input.mouseDelta = {scripted.cursor.x - before.cursor.x,
                                before.cursor.y - scripted.cursor.y};
            if (scripted.leftButton) input.dragDelta = input.mouseDelta;
        }
    }
#ifdef PBR_WEBGL
    // The page's controls: a live flag changes as the panel's would, through the command line's
    // own checks (a value they refuse is one line, and the flag keeps its value).
    for (const web::FlagChange& change : web::takeFlagChanges()) {
        setLiveFlag(change.name,
                    change.present ? std::optional<std::string>(change.value) : std::nullopt);
    }
    // and its pause and step buttons, as the panel's
    const web::ClockPresses presses = web::takeClockPresses();
    pauseOrStep(presses.pause, presses.step);
#endif
    if (input.togglePanel && panel_) {
        panelShown_ = !panelShown_;
        // The frame's move was made in the other mode (a free cursor over the panel, or a look):
        // it neither turns the camera nor works the panel now. At a software GL's 1-3 frames a
        // second it is the whole way the hand went before Tab, which once turned the camera.
        input.mouseDelta = input.dragDelta = glm::vec2(0.0f);
        if (context_->windowed() && !config_.orbitCamera && !config_.fixedView) {
            context_->setCursorCaptured(mouseLook());
        }
    }
    // A page's longest wait is its first frame (a software WebGL draws it for a second or more):
    // its header says so meanwhile (nothing natively).
    if (frameIndex_ == 0) web::announceFirstFrame();

    const double now = context_->seconds();
    if (frameIndex_ == 0) {
        startupSeconds_ =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - constructed_).count();
    }
    deltaTime_ = frameIndex_ == 0 ? 0.0f : float(now - lastSeconds_);
    lastSeconds_ = now;
    // The panel first: a control moved by this frame's input changes what this frame draws.
    updatePanel(input);
    if (paused_) {
        time_ = pausedTime_;
    } else if (options_.time) {
        time_ = float(*options_.time);
    } else {
        time_ = headless() ? 0.0f : float(now - startSeconds_);
    }
    cursor_.reset();
    if (!panelHasMouse_ && input.cursor.x >= 0.0f && input.cursor.y >= 0.0f &&
        input.cursor.x < float(width()) && input.cursor.y < float(height())) {
        cursor_ = input.cursor;
    }
    if (panelHasMouse_) {
        // The mouse works the panel: it neither turns nor moves the camera.
        input.mouseDelta = input.dragDelta = glm::vec2(0.0f);
        input.scroll = 0.0f;
    }
    if (!mouseLook()) input.mouseDelta = input.dragDelta;  // a free cursor looks by dragging

    if (orbit_) {
        // Left drag orbits, scroll dollies; the cursor is free (AppConfig::orbitCamera).
        if (input.dragDelta != glm::vec2(0.0f) || input.scroll != 0.0f) {
            orbit_->orbit(input.dragDelta.x, input.dragDelta.y);
            orbit_->dolly(input.scroll);
            // Made again from its eye, as `--camera` of the command line will make it: that
            // command draws this very view (the eye, a float, is all it gives).
            orbitEye_ = orbit_->position();
            orbit_ = OrbitCamera::fromPosition(orbitBoundsMin_, orbitBoundsMax_, *orbitEye_);
        }
    } else if (!config_.orbitCamera && !config_.fixedView) {
        // (no camera moves in an orbit sample before useOrbitCamera, nor in a fixed view)
        // A held key moves the camera by the frame's time, but by a quarter second's worth at
        // most: a long frame (a shader reload, a busy machine, the browser's first frames) does
        // not throw the camera far past what the learner was looking at.
        const float step = std::min(deltaTime_, 0.25f);
        if (input.forward) camera_.processKeyboard(CameraMove::Forward, step);
        if (input.backward) camera_.processKeyboard(CameraMove::Backward, step);
        if (input.left) camera_.processKeyboard(CameraMove::Left, step);
        if (input.right) camera_.processKeyboard(CameraMove::Right, step);
        if (input.mouseDelta != glm::vec2(0.0f)) {
            camera_.processMouseMovement(input.mouseDelta.x, input.mouseDelta.y);
        }
        if (input.scroll != 0.0f) camera_.processMouseScroll(input.scroll);
    }
    shadersReloaded_ = input.reload;
    if (input.reload) {
        int reloaded = 0;
        for (Shader& shader : shaders_) reloaded += shader.reload() ? 1 : 0;
        std::fprintf(stderr, "reloaded %d of %zu shaders\n", reloaded, shaders_.size());
    }
    if (input.screenshot) {
        // Taken at the end of this frame, once it is drawn.
        ++screenshotCount_;
    }

    if (context_->windowed()) {
        const glm::ivec2 size = context_->framebufferSize();
        if (size.x > 0 && size.y > 0 &&
            (size.x != target_->width() || size.y != target_->height())) {
            target_ =
                std::make_unique<RenderTarget>(size.x, size.y, options_.msaa, config_.srgbTarget);
        }
    }
    target_->bind();
    return true;
}

bool App::setLiveFlag(const std::string& name, const std::optional<std::string>& value) {
    const auto spec = std::find_if(config_.flags.begin(), config_.flags.end(),
                                   [&](const FlagSpec& f) { return f.name == name; });
    if (spec == config_.flags.end() || !spec->live) return false;
    if (!value) {
        options_.sampleFlags.erase(name);
        return true;
    }
    try {
        // The command line's own checks, the sample's `refusing` included.
        const std::vector<std::string> args = spec->kind == FlagSpec::Kind::Switch
                                                  ? std::vector<std::string>{name}
                                                  : std::vector<std::string>{name, *value};
        options_.sampleFlags[name] = parseOptions(args, config_.flags).sampleFlags.at(name);
        return true;
    } catch (const UsageError& e) {
        std::fprintf(stderr, "%s: error: %s\n", config_.name.c_str(), e.what());
        return false;
    }
}

void App::updatePanel(const InputFrame& input) {
    if (deltaTime_ > 0.0f) {
        // What the panel (and a page) says a frame takes: smoothed, so that it can be read.
        const double ms = double(deltaTime_) * 1000.0;
        shownFrameMilliseconds_ =
            shownFrameMilliseconds_ <= 0.0 ? ms : 0.9 * shownFrameMilliseconds_ + 0.1 * ms;
    }
    panelHasMouse_ = false;
    if (!panel_) return;
    PanelStatus status{.title = config_.title,
                       .commandLine = commandLine(),
                       .frameMilliseconds = headless() ? -1.0 : shownFrameMilliseconds_,
                       .paused = paused_};
    // Headless (a script, --panel) the panel's clock is a steady 60 frames a second.
    const float delta = headless() || deltaTime_ <= 0.0f ? 1.0f / 60.0f : deltaTime_;
    // The controls write into a copy; each changed value is taken as the page's are.
    std::map<std::string, std::string> proposed = options_.sampleFlags;
    for (const std::string& name :
         panel_->begin({.cursor = input.cursor,
         .leftButton = input.leftButton,
         .leftPresses = input.leftPresses,
         .scroll = input.scroll,
         .deltaSeconds = delta},
                       {width(), height()}, proposed, status, panelShown_)) {
        const auto value = proposed.find(name);
        setLiveFlag(name, value == proposed.end() ? std::nullopt
                                                  : std::optional<std::string>(value->second));
    }
    panelHasMouse_ = panel_->wantsMouse();
    pauseOrStep(status.pauseClicked, status.stepClicked);
}

void App::pauseOrStep(bool pause, bool step) {
    if (pause) {
        if (paused_) {
            // Time runs on from where it stood.
            startSeconds_ = context_->seconds() - double(pausedTime_);
        } else {
            pausedTime_ = time_;
        }
        paused_ = !paused_;
    }
    if (step && paused_) pausedTime_ += 1.0f / 60.0f;
}

void App::endFrame() {
    for (Shader& shader : shaders_) {
        if (const std::string note = shader.takeInactiveNote(); !note.empty()) {
            std::fprintf(stderr, "%s\n", note.c_str());
        }
    }
    // A view's caption: in a window and a page always, in the picture with --caption (or
    // --panel).
    const bool hasGain = std::any_of(config_.flags.begin(), config_.flags.end(),
                                     [](const FlagSpec& spec) { return spec.name == "--gain"; });
    const float gain = hasGain ? flagNumber("--gain") : 1.0f;
    const std::string caption = currentView() ? viewCaption(*currentView(), gain) : std::string();
    if (panel_ && !caption.empty() && (context_->windowed() || options_.panel || options_.caption))
        panel_->caption(caption, viewScale(*currentView()), gain);
#ifdef PBR_WEBGL
    if (context_->windowed()) {
        std::vector<std::pair<float, std::string>> ticks;
        if (currentView()) {
            for (ScaleTick& tick : viewScaleTicks(viewScale(*currentView()), gain))
                ticks.emplace_back(tick.at, std::move(tick.value));
        }
        web::showCaption(caption, ticks);
    }
#endif
    // --panel: the panel and the labels are part of the picture; in a window they are drawn over
    // the picture shown, and F12 writes what a headless run writes. --caption: the labels and
    // the caption without the panel.
    if (panel_) panel_->end();
    const bool panelInPicture = panel_ && (options_.panel || options_.caption);
    target_->resolve();
    if (panelInPicture) {
        target_->bindResolved();
        panel_->draw();
    }
    if (screenshotCount_ > 0 && (context_->windowed() || scripted_)) {
        writeScreenshot("screenshot-" + config_.name + "-" + std::to_string(frameIndex_) + ".png");
        screenshotCount_ = 0;
    }
    if (context_->windowed()) {
        const glm::ivec2 size = context_->framebufferSize();
        target_->blitToDefault(size.x, size.y);
#ifdef PBR_WEBGL
        web::showLabels(width(), height());
        // the page's bar under the picture: what the panel says natively
        web::showFrame(shownFrameMilliseconds_, commandLine(), paused_);
#endif
        if (panel_ && !panelInPicture) {
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glViewport(0, 0, size.x, size.y);
            panel_->draw();
        }
        context_->swapBuffers();
    }
    if (options_.benchmark) {
        // Whole frames, end to end: the GPU's work (glFinish), the blit to the window and the
        // swap included, as a frame counter on screen would see them.
        finishGl();
        const double now = context_->seconds();
        if (frameIndex_ == 0) {
            firstFrameSeconds_ =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - processStart())
                    .count();
        } else {
            frameMilliseconds_.push_back((now - lastFrameEnd_) * 1000.0);
        }
        lastFrameEnd_ = now;
    }
    checkGlErrors("frame");
}

std::string App::frameDescription() const {
    char text[64];
    std::snprintf(text, sizeof text, "%dx%d, msaa %d", target_->width(), target_->height(),
                  target_->samples());
    return std::string(text) + ", " + context_->backend() + ", " + renderer();
}

namespace {
std::string absoluteForMessage(const fs::path& path) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec);
    return utf8Path(ec ? path : absolute);
}
}  // namespace

void App::writeScreenshot(const std::string& path) {
    // A failed screenshot is reported and the window goes on.
    try {
        writePng(path, target_->readPixels());
        web::handOver(path);
        std::printf("%s: screenshot %s (%s)\n", config_.name.c_str(),
                    absoluteForMessage(path).c_str(), frameDescription().c_str());
    } catch (const Error& e) {
        std::fprintf(stderr, "%s: screenshot not written: %s\n", config_.name.c_str(), e.what());
    }
}

void App::finish() {
    finished_ = true;
    // A run with GL errors fails before it writes anything: nothing it made is to be trusted.
    checkGlErrors("end of run");
    if (glErrorCount_ > 0) {
        throw Error(std::to_string(glErrorCount_) +
                    " OpenGL error(s) during the run; first: " + firstGlError_);
    }
    // The picture and the sample's own files, together or not at all.
    OutputBatch batch;
    fs::path picture;
    if (frameIndex_ >= 0) {
        const bool wantImage = !options_.output.empty() || (headless() && !options_.benchmark);
        if (wantImage) {
            picture = options_.output.empty() ? fs::path(config_.name + ".png") : outputPath();
            batch.add(picture, encodePng(target_->readPixels()));
        }
    }
    for (auto& [path, bytes] : outputFiles_) batch.add(path, std::move(bytes));
    outputFiles_.clear();
    batch.commit();
    if (scripted_) {
        // For the test that drove the panel: where its controls were, and what is on screen.
        if (panel_) {
            std::istringstream layout(panel_->layout());
            for (std::string line; std::getline(layout, line);) {
                std::printf("%s: panel: %s\n", config_.name.c_str(), line.c_str());
            }
        }
        std::printf("%s: command: %s\n", config_.name.c_str(), commandLine().c_str());
    }
    for (const fs::path& path : batch.paths()) web::handOver(path);
    if (!picture.empty()) {
        std::printf("%s: wrote %s (%s)\n", config_.name.c_str(),
                    absoluteForMessage(picture).c_str(), frameDescription().c_str());
    }
    for (const fs::path& path : batch.paths()) {
        if (path != picture) {
            std::printf("%s: wrote %s\n", config_.name.c_str(), absoluteForMessage(path).c_str());
        }
    }
    if (options_.benchmark) {
        std::printf(
            "{\"sample\":\"%s\",\"backend\":\"%s\",\"renderer\":\"%s\",\"width\":%d,\"height\":%d,"
            "\"msaa\":%d,\"frames\":%zu,\"median_ms\":%.2f,\"p95_ms\":%.2f,\"precompute_s\":%.3f,"
            "\"startup_s\":%.3f,\"first_frame_s\":%.3f}\n",
            config_.name.c_str(), context_->backend().c_str(), jsonEscape(renderer()).c_str(),
            target_->width(), target_->height(), target_->samples(), frameMilliseconds_.size(),
            percentile(frameMilliseconds_, 0.5), percentile(frameMilliseconds_, 0.95),
            precomputeSeconds_, startupSeconds_, firstFrameSeconds_);
    }
    std::fflush(stdout);
}

#ifndef PBR_WEBGL
void GLAD_API_PTR App::onDebugMessage(GLenum source, GLenum type, GLuint, GLenum severity, GLsizei,
                                      const GLchar* message, const void* user) {
    // The compiler's messages come back mapped to file:line through Shader; not here.
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
    App* app = static_cast<App*>(const_cast<void*>(user));
    if (type == GL_DEBUG_TYPE_ERROR) {
        if (app->glErrorCount_++ == 0) app->firstGlError_ = message;
        ++app->debugErrorsSinceCheck_;
        std::fprintf(stderr, "GL error: %s\n", message);
    } else if (severity == GL_DEBUG_SEVERITY_HIGH) {
        std::fprintf(stderr, "GL warning: %s\n", message);
    }
}
#endif

void App::installDebugOutput() {
    // KHR_debug says where an error happened, as it happens; glGetError after each frame is the
    // fallback (and catches what a driver does not report through the callback). WebGL has no
    // KHR_debug: glGetError alone, and the browser's console.
#ifndef PBR_WEBGL
    if (!GLAD_GL_KHR_debug) return;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, this);
#endif
}

void App::checkGlErrors(const char* where) {
    // glGetError is the authority: KHR_debug may be muted, or say nothing in a context that is
    // not a debug context. Each flag it returns stands for at least one error; those the debug
    // callback did not already report are counted here. (GL keeps one flag per kind of error, so
    // three GL_INVALID_ENUMs may come back as one; the run fails either way.)
    int flagged = 0;
    for (GLenum error = glGetError(); error != GL_NO_ERROR; error = glGetError()) {
        if (++flagged <= debugErrorsSinceCheck_) continue;
        const std::string text = glErrorName(error) + " (found at " + where + ")";
        if (glErrorCount_++ == 0) firstGlError_ = text;
        std::fprintf(stderr, "GL error: %s\n", text.c_str());
    }
    debugErrorsSinceCheck_ = 0;
}

}  // namespace pbr
