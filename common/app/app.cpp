#include "app/app.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "base/error.h"
#include "base/output.h"
#include "base/paths.h"
#include "context/web.h"
#include "files/image.h"

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

}  // namespace

App::App(int argc, char** argv, AppConfig config) : config_(std::move(config)) {
    if (config_.title.empty()) config_.title = config_.name;
    usage_ =
        usageText(argc > 0 ? fs::path(argv[0]).filename().string() : config_.name, config_.flags,
                  config_.orbitCamera);
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
    if (!options_.output.empty()) requireWritableFilePath(options_.output, options_.output);
    for (const FlagSpec& spec : config_.flags) {
        const auto value = flag(spec.name);
        if (spec.kind == FlagSpec::Kind::OutputFolder && value) {
            requireOutputFolder(*value, spec.name + " " + *value);
        }
    }

    if (!options_.headless) {
        std::string whyNot;
        context_ = createGlfwContext(config_.title, options_.width, options_.height,
                                     !options_.benchmark, !config_.orbitCamera, whyNot);
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

    if (options_.benchmark) {
        // One more than measured: the first frame compiles shader variants and is not counted.
        framesWanted_ = options_.frames.value_or(kBenchmarkFrames) + 1;
    } else if (options_.frames) {
        framesWanted_ = *options_.frames;
    } else {
        framesWanted_ = headless() ? 1 : 0;
    }
    if (options_.benchmark) context_->setVsync(false);
    checkGlErrors("start-up");
}

void App::useOrbitCamera(const glm::vec3& boundsMin, const glm::vec3& boundsMax) {
    if (!config_.orbitCamera) {
        throw Error(config_.name +
                    ": useOrbitCamera needs AppConfig::orbitCamera = true (so that --camera is "
                    "checked before any context, and the window leaves the cursor free)");
    }
    if (options_.camera) {
        const CameraStart& start = *options_.camera;
        orbit_ = OrbitCamera::fromPosition(boundsMin, boundsMax, {start.x, start.y, start.z});
    } else {
        orbit_ = OrbitCamera::framing(boundsMin, boundsMax, aspect());
    }
}

App::~App() {
    // An App is the run: ending by an exception is a failure (exit code 1), else a success.
    web::exitWithAfterMain(std::uncaught_exceptions() > 0 ? 1 : 0);
    shaders_.clear();
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

int App::flagInt(const std::string& name, int fallback) const {
    const FlagSpec& spec = sampleFlag(name);
    const auto value = flag(name);
    return value ? parseIntFlag(name, *value, int(spec.min), int(spec.max)) : fallback;
}

float App::flagNumber(const std::string& name, float fallback) const {
    const FlagSpec& spec = sampleFlag(name);
    const auto value = flag(name);
    return value ? float(parseNumberFlag(name, *value, spec.min, spec.max)) : fallback;
}

std::optional<std::vector<float>> App::flagNumbers(const std::string& name) const {
    const FlagSpec& spec = sampleFlag(name);
    if (spec.kind != FlagSpec::Kind::Numbers) throw Error(name + " is not a list of numbers");
    const auto value = flag(name);
    if (!value) return std::nullopt;
    std::vector<float> numbers;
    for (const double n : parseNumbersFlag(spec, *value)) numbers.push_back(float(n));
    return numbers;
}

void App::addOutputFile(fs::path path, std::string bytes) {
    outputFiles_.emplace_back(std::move(path), std::move(bytes));
}

Shader& App::shader(const std::string& vertex, const std::string& fragment,
                    std::vector<std::string> defines) {
    return shaders_.emplace_back(vertex, fragment, std::move(defines));
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

    const double now = context_->seconds();
    if (frameIndex_ == 0) {
        startupSeconds_ =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - constructed_).count();
    }
    deltaTime_ = frameIndex_ == 0 ? 0.0f : float(now - lastSeconds_);
    lastSeconds_ = now;
    if (options_.time) {
        time_ = float(*options_.time);
    } else {
        time_ = headless() ? 0.0f : float(now - startSeconds_);
    }

    if (orbit_) {
        // Left drag orbits, scroll dollies; the cursor is free (AppConfig::orbitCamera).
        if (input.dragDelta != glm::vec2(0.0f)) orbit_->orbit(input.dragDelta.x, input.dragDelta.y);
        if (input.scroll != 0.0f) orbit_->dolly(input.scroll);
    } else if (!config_.orbitCamera) {  // (an orbit sample before useOrbitCamera: no camera moves)
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

void App::endFrame() {
    target_->resolve();
    if (screenshotCount_ > 0 && context_->windowed()) {
        writeScreenshot("screenshot-" + config_.name + "-" + std::to_string(frameIndex_) + ".png");
        screenshotCount_ = 0;
    }
    if (context_->windowed()) {
        const glm::ivec2 size = context_->framebufferSize();
        target_->blitToDefault(size.x, size.y);
        context_->swapBuffers();
    }
    if (options_.benchmark) {
        // Whole frames, end to end: the GPU's work (glFinish), the blit to the window and the
        // swap included, as a frame counter on screen would see them.
        finishGl();
        const double now = context_->seconds();
        if (frameIndex_ == 0) {
            firstFrameSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                                               processStart())
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
    return (ec ? path : absolute).string();
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
            picture = options_.output.empty() ? config_.name + ".png" : options_.output;
            batch.add(picture, encodePng(target_->readPixels()));
        }
    }
    for (auto& [path, bytes] : outputFiles_) batch.add(path, std::move(bytes));
    outputFiles_.clear();
    batch.commit();
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
