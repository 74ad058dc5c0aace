#pragma once
// The frame around a sample: command line, context (window or offscreen), input, time, the
// render target, screenshots, headless capture, GL error checks and the benchmark.
//
//     int main(int argc, char** argv) try {
//         pbr::App app(argc, argv, {.name = "01_lighting", .cameraPosition = {0, 0, 23}});
//         pbr::Shader& pbr = app.shader("01_lighting/pbr.vert", "01_lighting/pbr.frag");
//         while (app.nextFrame()) { ... draw ... }
//     } catch (...) {
//         return pbr::reportFailure();
//     }
#include <chrono>
#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "app/options.h"
#include "app/panel.h"
#include "app/panel_script.h"
#include "app/views.h"
#include "context/context.h"
#include "gl/framebuffer.h"
#include "gl/shader.h"
#include "math/camera.h"
#include "math/sphere_grid.h"

namespace pbr {

struct AppConfig {
    std::string name{};   // "01_lighting": the default output file and window title
    std::string title{};  // window title; empty: the name
    glm::vec3 cameraPosition{0.0f, 0.0f, 3.0f};  // default start, unless --camera says otherwise
    float cameraYaw = FlyCamera::kDefaultYaw;
    float cameraPitch = FlyCamera::kDefaultPitch;
    std::vector<FlagSpec> flags{};  // the sample's own flags
    // The render target stores sRGB and the GL encodes (see framebuffer.h): the sample's shaders
    // write linear values and blending happens in linear light.
    bool srgbTarget = false;
    // The sample looks at a model through an OrbitCamera (App::useOrbitCamera): the cursor stays
    // free in a window (left drag orbits, scroll dollies, WASD does nothing), and --camera takes
    // x,y,z only: yaw and pitch are refused as a bad flag, before any context exists, since the
    // orbit camera always looks at the model's centre.
    bool orbitCamera = false;
    // The sample draws a fixed picture with no camera (06's LUT): in a window the cursor stays
    // free and neither keys nor mouse move anything; the command line names no --camera.
    bool fixedView = false;
};

class GpuMesh;

class App {
public:
    App(int argc, char** argv, AppConfig config);
    ~App();
    App(const App&) = delete;
    App& operator=(const App&) = delete;

    // Ends the previous frame (resolve, show or capture) and starts the next one (input, time,
    // render target bound, viewport set). Returns false when the run is over: the window was
    // closed, or --frames were drawn; headless, the last frame has been written by then.
    bool nextFrame();

    const Options& options() const { return options_; }
    // The value of one of the sample's own flags, when given (already checked against its
    // FlagSpec when the App was made).
    std::optional<std::string> flag(const std::string& name) const;
    // A flag that names a file or folder, as a path: its text is UTF-8 on every platform (on
    // Windows by the samples' manifest), and std::filesystem::path reads a narrow string there in
    // another encoding, so every path from the command line is made here (or by pathFromUtf8).
    std::optional<std::filesystem::path> flagPath(const std::string& name) const;
    // --output as a path; empty when not given.
    std::filesystem::path outputPath() const;
    // A sample flag's value converted: a Choice flag's word (its first choice when not given),
    // an Integer or Number flag's value (its FlagSpec's default when not given).
    std::string flagChoice(const std::string& name) const;
    int flagInt(const std::string& name) const;
    float flagNumber(const std::string& name) const;
    // A Number flag's value when given, or its default when it has one (FlagSpec::withoutDefault).
    std::optional<float> flagNumberIfAny(const std::string& name) const;
    // A Numbers flag's values (its FlagSpec's count of them), when given or when it has a
    // default; a flag of three numbers with a default as a vector.
    std::optional<std::vector<float>> flagNumbers(const std::string& name) const;
    glm::vec3 flagVec3(const std::string& name) const;

    // A file to write together with the picture at the end of the run: the picture (when one is
    // written) and every such file appear together, or none does (see output.h).
    void addOutputFile(std::filesystem::path path, std::string bytes);

    FlyCamera& camera() { return camera_; }
    // A start pose found after the App was made (framing a model, say); --camera still wins.
    void setDefaultCamera(const glm::vec3& position, float yaw = FlyCamera::kDefaultYaw,
                          float pitch = FlyCamera::kDefaultPitch) {
        if (options_.camera) return;
        camera_ = FlyCamera(position, yaw, pitch);
        if (options_.fov) camera_.setZoom(float(*options_.fov));
    }
    // Switches to an orbit camera around these bounds (in the model's own units): framing them
    // (OrbitCamera::framing at the current aspect), or, when --camera x,y,z was given, from that
    // position looking at their centre (OrbitCamera::fromPosition). Needs AppConfig::orbitCamera;
    // may be called again (another model): the view starts afresh. `start`: where the camera
    // starts without --camera, looking at the centre, instead of the framing.
    void useOrbitCamera(const glm::vec3& boundsMin, const glm::vec3& boundsMax,
                        std::optional<glm::vec3> start = std::nullopt);
    // The orbit camera once useOrbitCamera was called, else nullptr.
    const OrbitCamera* orbitCamera() const { return orbit_ ? &*orbit_ : nullptr; }

    // The active camera's (orbit or fly).
    glm::mat4 view() const { return orbit_ ? orbit_->viewMatrix() : camera_.viewMatrix(); }
    glm::mat4 projection() const {
        return orbit_ ? orbit_->projectionMatrix(aspect()) : camera_.projectionMatrix(aspect());
    }
    glm::vec3 cameraPosition() const { return orbit_ ? orbit_->position() : camera_.position(); }
    // The active camera's view volume: what lies wholly outside it need not be drawn.
    Frustum frustum() const { return Frustum(projection() * view()); }

    // A program from shaders/<vertex> and shaders/<fragment>, owned by the App so that R can
    // reload it. The reference stays valid for the App's life. Asked again for the same files and
    // defines (a sample that picks its program every frame, by a live flag), it is the same one.
    Shader& shader(const std::string& vertex, const std::string& fragment,
                   std::vector<std::string> defines = {});
    // Clears the frame to draw `view` on: the picture on `pictureColor` (what its sky or
    // background leaves), a term view on a neutral checker of two greys, levels 56 and 72 (16
    // pixels a cell), not on the sky or the tone-mapped scene, so that pale terms (g, NdotL, the
    // irradiance) and dark ones both stand out and no flat value melts into it.
    void clearFrame(View view, const glm::vec3& pictureColor);

    // A label over the picture, drawn by the panel's layer (in a window; headless with --panel
    // only): at a pixel from the top-left, or at a point of the scene, centred there. Call it
    // between nextFrame() and the end of the frame.
    void label(const glm::vec2& pixel, const std::string& text);
    void label(const glm::vec3& world, const std::string& text);

    // The command that draws what is on screen now: the program, the size, the camera, the time
    // when it is paused or fixed, and the sample's flags as they stand (the panel's changes
    // included). The panel shows it; a scripted run prints it.
    std::string commandLine() const;

    // Rebinds the frame's render target (after drawing into a framebuffer of your own).
    void bindRenderTarget() const;

    bool headless() const { return !context_->windowed(); }
    int width() const { return target_->width(); }
    int height() const { return target_->height(); }
    float aspect() const { return float(width()) / float(height()); }
    float time() const { return time_; }  // seconds; fixed when headless
    // The mouse over the picture this frame, in pixels from the top-left (a window's, or a
    // panel script's), when it is over the picture and not over the panel.
    std::optional<glm::vec2> cursor() const { return cursor_; }
    float deltaTime() const { return deltaTime_; }  // seconds since the last frame
    int frameIndex() const { return frameIndex_; }  // 0 for the first frame
    std::string renderer() const;
    // R was pressed this frame and the App's shaders were built again: what a sample computed
    // with shaders of its own (the IBL maps) is to be made again too, from the files as they are.
    bool shadersReloaded() const { return shadersReloaded_; }
    // Adds to the precompute time --benchmark reports (IBL maps and the like, cache off).
    void addPrecomputeSeconds(double seconds) { precomputeSeconds_ += seconds; }

private:
    void beginFrame();
    void endFrame();
    void finish();
    void installDebugOutput();
    void checkGlErrors(const char* where);
    void writeScreenshot(const std::string& path);
    // The view the sample's --view shows now (nullopt: the sample has no views).
    std::optional<View> currentView() const;
    // The panel's (or a page's) pause and step buttons: time stops, runs on, or steps 1/60 s.
    void pauseOrStep(bool pause, bool step);
    void updatePanel(const InputFrame& input);
    // A live flag's new value from the panel or the page (nullopt: a switch turned off), taken
    // through the command line's checks; a refused one is one line, and the flag keeps its
    // value. False for a value refused or a flag that is not live.
    bool setLiveFlag(const std::string& name, const std::optional<std::string>& value);
    bool mouseLook() const;  // the fly camera looks with the captured cursor (no panel shown)
    std::string frameDescription() const;
    std::string program_;  // the executable's name, for commandLine
    const FlagSpec& sampleFlag(const std::string& name) const;

    AppConfig config_;
    Options options_;
    std::string usage_;
    std::unique_ptr<Context> context_;  // first member: destroyed last
    std::unique_ptr<RenderTarget> target_;
    std::unique_ptr<GpuMesh> groundQuad_;  // clearFrame's, made at its first view
    std::deque<Shader> shaders_;
    std::vector<std::string> shaderKeys_;  // shaders_[i]'s files and defines
    std::unique_ptr<Panel> panel_;  // made when the build has Dear ImGui and a panel is wanted
    bool panelShown_ = false;
    bool shadersReloaded_ = false;
    bool panelHasMouse_ = false;  // this frame's mouse is the panel's, not the camera's
    std::optional<glm::vec2> cursor_;
    bool scripted_ = false;
    std::string scriptPath_;
    std::vector<ScriptFrame> script_;  // PBR_PANEL_SCRIPT: each frame's mouse and flags, headless
    double shownFrameMilliseconds_ = 0.0;
    bool paused_ = false;
    float pausedTime_ = 0.0f;
    FlyCamera camera_;
    std::optional<OrbitCamera> orbit_;
    // The orbit camera's bounds, and the eye its state was made from (OrbitCamera::fromPosition):
    // the --camera its command line gives, which makes the very same state again. None while it
    // frames the model as it does without --camera.
    glm::vec3 orbitBoundsMin_{0.0f}, orbitBoundsMax_{0.0f};
    std::optional<glm::vec3> orbitEye_;

    int framesWanted_ = 0;  // 0: until the window closes
    int frameIndex_ = -1;
    float time_ = 0.0f, deltaTime_ = 0.0f;
    double lastSeconds_ = 0.0;
    double startSeconds_ = 0.0;  // context clock when the context was made: scene time 0
    std::chrono::steady_clock::time_point constructed_ = std::chrono::steady_clock::now();
    double startupSeconds_ = 0.0;     // App constructed (context creation included) -> first frame
    double lastFrameEnd_ = 0.0;       // --benchmark: context clock when the last frame ended
    double firstFrameSeconds_ = 0.0;  // --benchmark: process start -> first frame finished
    double precomputeSeconds_ = 0.0;
    std::vector<double> frameMilliseconds_;
    std::vector<std::pair<std::filesystem::path, std::string>> outputFiles_;
    int screenshotCount_ = 0;
    bool noDisplayFallback_ = false;
    bool finished_ = false;
    int glErrorCount_ = 0;
    int debugErrorsSinceCheck_ = 0;  // errors KHR_debug reported since the last glGetError loop
    std::string firstGlError_;

#ifndef PBR_WEBGL
    static void GLAD_API_PTR onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity,
                                            GLsizei length, const GLchar* message,
                                            const void* user);
#endif
};

// The axes of the text's grid, as labels beside it: metallic up the rows (row / rows + the
// offset, in [0, 1]), roughness across the columns (column / columns + the offset, in [0.05, 1]:
// the samples' own clamps).
void labelSphereGrid(App& app, const SphereGrid& grid, float roughnessOffset = 0.0f,
                     float metallicOffset = 0.0f);

// The grid samples' four point lights (01, 04, 05): --lights N, the first N of them, and
// --light K, light K alone (1-4; 0, the default: as --lights says), both read every frame; and
// the lights those flags leave, in kGridLightPositions' order.
std::vector<FlagSpec> gridLightFlags();
std::span<const glm::vec3> gridLights(const App& app);

}  // namespace pbr
