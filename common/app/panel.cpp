#include "app/panel.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#ifdef PBR_HAVE_IMGUI
#include <imgui.h>
#include <imgui_impl_opengl3.h>
#endif

namespace pbr {

#ifndef PBR_HAVE_IMGUI

struct Panel::State {};
bool Panel::available() {
    return false;
}
Panel::Panel(std::vector<FlagSpec>, std::function<void(const std::string&)>) {}
Panel::~Panel() = default;
std::vector<std::string> Panel::begin(const PanelInput&, glm::ivec2,
                                      std::map<std::string, std::string>&, PanelStatus&, bool) {
    return {};
}
void Panel::label(glm::vec2, const std::string&) {}
void Panel::caption(const std::string&, ViewScale, float) {}
void Panel::end() {}
bool Panel::wantsMouse() const {
    return false;
}
void Panel::draw() const {}
std::string Panel::layout() const {
    return {};
}

#else

namespace {

constexpr float kPanelWidth = 430.0f;
constexpr float kMargin = 10.0f;
constexpr float kStops = 8.0f;  // a slider in stops spans 2^-8 to 2^8
// A slider's text for a flag without a default that is not given.
constexpr const char* kNotGiven = "(not given)";

// A slider's value as the flag's text: three significant digits, so that the command line stays
// readable (and the value the sample reads is the text's, as from the command line).
std::string sliderText(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return flagNumberText(std::strtod(text, nullptr));
}

// The value a control shows: the flag's text when given, else its default.
std::string currentText(const FlagSpec& spec, const std::map<std::string, std::string>& values) {
    const auto found = values.find(spec.name);
    if (found != values.end()) return found->second;
    if (spec.kind == FlagSpec::Kind::Choice && !spec.choices.empty()) return spec.choices.front();
    return spec.defaultValue;
}

}  // namespace

struct Panel::State {
    std::vector<FlagSpec> flags;
    std::function<void(const std::string&)> copy;
    std::string copied;  // the last command line copied: said beside the button while it shows
    ImGuiContext* context = nullptr;
    std::ostringstream layout;
    bool wantsMouse = false;
    bool laidOut = false;

    // The frame of the item about to be laid out (a slider, a combo box), for layout().
    void noteFrame(const std::string& id, float width) {
        const ImVec2 at = ImGui::GetCursorScreenPos();
        note(id, at, ImVec2(at.x + width, at.y + ImGui::GetFrameHeight()));
    }
    // The item just laid out.
    void noteItem(const std::string& id) {
        note(id, ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
    }
    void note(const std::string& id, ImVec2 min, ImVec2 max) {
        layout << id << ' ' << int(std::lround(min.x)) << ' ' << int(std::lround(min.y)) << ' '
               << int(std::lround(max.x - min.x)) << ' ' << int(std::lround(max.y - min.y)) << '\n';
    }

    // One flag's control; true when it changed the value.
    bool control(const FlagSpec& spec, std::map<std::string, std::string>& values);
};

bool Panel::State::control(const FlagSpec& spec, std::map<std::string, std::string>& values) {
    const std::string text = currentText(spec, values);
    const char* label = spec.name.c_str();
    if (!spec.live) {
        // Read once at start-up: the value, no control (a restart with the flag changes it).
        ImGui::BeginDisabled();
        if (spec.kind == FlagSpec::Kind::Switch) {
            bool on = values.count(spec.name) != 0;
            ImGui::Checkbox(label, &on);
        } else {
            ImGui::Text("%s %s", label, text.empty() ? "(not given)" : text.c_str());
        }
        ImGui::EndDisabled();
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
            ImGui::SetTooltip("%s\n(read at start-up: restart with %s to change it)",
                              spec.help.c_str(), label);
        }
        return false;
    }
    bool changed = false;
    const float width = ImGui::CalcItemWidth();
    switch (spec.kind) {
        case FlagSpec::Kind::Switch: {
            bool on = values.count(spec.name) != 0;
            if (ImGui::Checkbox(label, &on)) {
                if (on) {
                    values[spec.name] = "";
                } else {
                    values.erase(spec.name);
                }
                changed = true;
            }
            noteItem(spec.name);
            break;
        }
        case FlagSpec::Kind::Integer: {
            const int value = int(std::strtol(text.c_str(), nullptr, 10));
            int next = value;
            ImGui::PushID(label);
            if (ImGui::Button("-")) next = std::max(value - 1, int(spec.min));
            noteItem(spec.name + " -");
            ImGui::SameLine();
            if (ImGui::Button("+")) next = std::min(value + 1, int(spec.max));
            noteItem(spec.name + " +");
            ImGui::PopID();
            ImGui::SameLine();
            ImGui::Text("%d  %s", value, label);
            if (next != value) {
                values[spec.name] = std::to_string(next);
                changed = true;
            }
            break;
        }
        case FlagSpec::Kind::Number: {
            // a flag without a default, not given: the slider at its low end, saying so
            const bool unset = text.empty();
            float value = unset ? float(spec.min) : float(std::strtod(text.c_str(), nullptr));
            const ImGuiSliderFlags flags = ImGuiSliderFlags_NoInput | ImGuiSliderFlags_AlwaysClamp;
            noteFrame(spec.name, width);
            if (spec.min > 0.0 && spec.max / spec.min > 1000.0) {
                // A factor over many decades (an exposure) slides in stops, a tenth at a time,
                // within +-kStops (further on the command line): 0.001-10000 on one slider took
                // 70 pixels from 1 to 159.
                const float least = std::max(float(std::log2(spec.min)), -kStops);
                const float most = std::min(float(std::log2(spec.max)), kStops);
                float stops = std::clamp(std::log2(value), least, most);
                if (ImGui::SliderFloat(label, &stops, least, most,
                                       unset ? kNotGiven : "%+.1f stops", flags)) {
                    const std::string next =
                        flagNumberText(float(std::exp2(std::round(stops * 10.0f) / 10.0f)));
                    if (next != text) {
                        values[spec.name] = next;
                        changed = true;
                    }
                }
                break;
            }
            if (ImGui::SliderFloat(label, &value, float(spec.min), float(spec.max),
                                   unset ? kNotGiven : "%.3g", flags)) {
                const std::string next = sliderText(value);
                if (next != text) {
                    values[spec.name] = next;
                    changed = true;
                }
            }
            break;
        }
        case FlagSpec::Kind::Numbers: {
            // (the flag's text passed its checks: given, the default, or taken by setLiveFlag)
            // (or, for a flag without a default, not given: each at its low end, saying so)
            const bool unset = text.empty();
            std::vector<double> numbers = unset ? std::vector<double>(size_t(spec.count), spec.min)
                                                : parseNumbersFlag(spec, text);
            std::vector<float> floats(numbers.begin(), numbers.end());
            const float min = float(spec.min), max = float(spec.max);
            noteFrame(spec.name, width);
            if (ImGui::SliderScalarN(label, ImGuiDataType_Float, floats.data(), int(floats.size()),
                                     &min, &max, unset ? "-" : "%.3g",
                                     ImGuiSliderFlags_NoInput | ImGuiSliderFlags_AlwaysClamp)) {
                std::string next;
                for (const float f : floats) next += (next.empty() ? "" : ",") + sliderText(f);
                if (next != text) {
                    values[spec.name] = next;
                    changed = true;
                }
            }
            break;
        }
        case FlagSpec::Kind::Choice: {
            noteFrame(spec.name, width);
            if (ImGui::BeginCombo(label, text.c_str())) {
                for (const std::string& choice : spec.choices) {
                    const bool selected = choice == text;
                    if (ImGui::Selectable(choice.c_str(), selected) && !selected) {
                        values[spec.name] = choice;
                        changed = true;
                    }
                    noteItem(spec.name + "=" + choice);
                }
                ImGui::EndCombo();
            }
            break;
        }
        case FlagSpec::Kind::Text:
        case FlagSpec::Kind::OutputFolder:
            ImGui::Text("%s %s", label, text.empty() ? "(not given)" : text.c_str());
            break;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", spec.help.c_str());
    // A number flag without a default, given: a button that takes it back to not given.
    const bool numeric =
        spec.kind == FlagSpec::Kind::Number || spec.kind == FlagSpec::Kind::Numbers;
    if (numeric && spec.defaultValue.empty() && values.count(spec.name)) {
        ImGui::SameLine();
        ImGui::PushID(label);
        if (ImGui::SmallButton("unset")) {
            values.erase(spec.name);
            changed = true;
        }
        noteItem(spec.name + " unset");
        ImGui::PopID();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("back to not given: %s", spec.help.c_str());
    }
    return changed;
}

bool Panel::available() {
    return true;
}

Panel::Panel(std::vector<FlagSpec> flags, std::function<void(const std::string&)> copy)
    : state_(std::make_unique<State>()) {
    state_->flags = std::move(flags);
    state_->copy = std::move(copy);
    IMGUI_CHECKVERSION();
    state_->context = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini: the suite writes no file it was not asked for
    io.LogFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGui::GetStyle().Alpha = 0.92f;
    ImGui_ImplOpenGL3_Init("#version 330 core");
}

Panel::~Panel() {
    ImGui::SetCurrentContext(state_->context);
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext(state_->context);
}

std::vector<std::string> Panel::begin(const PanelInput& input, glm::ivec2 size,
                                      std::map<std::string, std::string>& values,
                                      PanelStatus& status, bool showPanel) {
    // Dear ImGui sizes a new window in its first frame and shows it from the second: the first
    // frame lays the panel out twice, so that a one-frame headless picture (--panel) shows it.
    if (!state_->laidOut && showPanel) {
        state_->laidOut = true;
        PanelStatus first = status;
        PanelInput still = input;
        still.leftButton = false;
        still.leftPresses = 0;
        layoutFrame(still, size, values, first, true);
        end();
    }
    return layoutFrame(input, size, values, status, showPanel);
}

void Panel::label(glm::vec2 pixel, const std::string& text) {
    ImGui::SetCurrentContext(state_->context);
    ImDrawList* list = ImGui::GetBackgroundDrawList();  // under the panel
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    const ImVec2 at(std::round(pixel.x - 0.5f * size.x), std::round(pixel.y - 0.5f * size.y));
    // light text on a dark box, readable over any picture
    list->AddRectFilled(ImVec2(at.x - 3.0f, at.y - 1.0f),
                        ImVec2(at.x + size.x + 3.0f, at.y + size.y + 1.0f), IM_COL32(0, 0, 0, 150),
                        3.0f);
    list->AddText(at, IM_COL32(235, 235, 235, 255), text.c_str());
}

void Panel::caption(const std::string& text, ViewScale scale, float gain) {
    ImGui::SetCurrentContext(state_->context);
    ImDrawList* list = ImGui::GetBackgroundDrawList();  // under the panel, over the picture
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float wrap = std::max(display.x - 2.0f * kMargin - 8.0f, 40.0f);
    const ImVec2 size = ImGui::CalcTextSize(text.c_str(), nullptr, false, wrap);
    const float barHeight = scale == ViewScale::None ? 0.0f : 26.0f;
    const float barWidth = std::min(256.0f, wrap);
    // at the top left: the texts' subjects fill the pictures' middles and bottoms, and the panel
    // sits at the top right
    const ImVec2 at(kMargin + 4.0f, kMargin + 3.0f);
    list->AddRectFilled(ImVec2(at.x - 4.0f, at.y - 3.0f),
                        ImVec2(at.x + std::max(size.x, barHeight > 0.0f ? barWidth : 0.0f) + 4.0f,
                               at.y + size.y + barHeight + 1.0f),
                        IM_COL32(0, 0, 0, 190), 3.0f);
    list->AddText(ImGui::GetFont(), ImGui::GetFontSize(), at, IM_COL32(235, 235, 235, 255),
                  text.c_str(), nullptr, wrap);
    if (scale == ViewScale::None) return;
    // the bar: the picture's levels 0 to 255, left to right (a view's value v is level 255 v)
    const ImVec2 bar(at.x, at.y + size.y + 3.0f);
    list->AddRectFilledMultiColor(bar, ImVec2(bar.x + barWidth, bar.y + 8.0f),
                                  IM_COL32(0, 0, 0, 255), IM_COL32(255, 255, 255, 255),
                                  IM_COL32(255, 255, 255, 255), IM_COL32(0, 0, 0, 255));
    for (const ScaleTick& tick : viewScaleTicks(scale, gain)) {
        const float x = std::round(bar.x + tick.at * barWidth);
        list->AddLine(ImVec2(x, bar.y + 8.0f), ImVec2(x, bar.y + 11.0f),
                      IM_COL32(235, 235, 235, 255));
        const float w = ImGui::CalcTextSize(tick.value.c_str()).x;
        list->AddText(ImVec2(std::clamp(x - 0.5f * w, bar.x, bar.x + barWidth - w), bar.y + 11.0f),
                      IM_COL32(235, 235, 235, 255), tick.value.c_str());
    }
}

void Panel::end() {
    ImGui::SetCurrentContext(state_->context);
    ImGui::Render();
}

std::vector<std::string> Panel::layoutFrame(const PanelInput& input, glm::ivec2 size,
                                            std::map<std::string, std::string>& values,
                                            PanelStatus& status, bool showPanel) {
    ImGui::SetCurrentContext(state_->context);
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(std::max(size.x, 1)), float(std::max(size.y, 1)));
    io.DeltaTime = std::max(input.deltaSeconds, 1.0e-4f);
    io.MousePos = input.cursor.x < 0.0f || input.cursor.y < 0.0f
                      ? ImVec2(-FLT_MAX, -FLT_MAX)
                      : ImVec2(input.cursor.x, input.cursor.y);
    // A click between two frames is down in this one and up in the next: Dear ImGui 1.86 reads
    // the button's state once a frame, and would see neither.
    io.MouseDown[0] = input.leftButton || input.leftPresses > 0;
    io.MouseWheel = input.scroll;

    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    state_->layout.str("");
    std::vector<std::string> changed;
    state_->wantsMouse = showPanel && io.WantCaptureMouse;
    if (!showPanel) return changed;

    // At the top right: the texts' subjects start at the left (01's and 05's smooth metals, 07's
    // leaf). Its title bar moves it (drag) and folds it (the arrow, or a double click).
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - kMargin, kMargin), ImGuiCond_FirstUseEver,
                            ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, 0.0f), ImGuiCond_FirstUseEver);
    const bool open =
        ImGui::Begin(status.title.c_str(), nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    {
        const ImVec2 at = ImGui::GetWindowPos();
        state_->note("title", at,
                     ImVec2(at.x + ImGui::GetWindowWidth(), at.y + ImGui::GetFrameHeight()));
    }
    if (!open) {  // folded: the title bar alone
        ImGui::End();
        return changed;
    }
    ImGui::PushItemWidth(kPanelWidth * 0.55f);
    if (status.frameMilliseconds >= 0.0) {
        ImGui::Text("%.1f ms a frame   (Tab hides this panel)", status.frameMilliseconds);
    } else {
        ImGui::TextUnformatted("headless   (Tab hides this panel in a window)");
    }
    status.pauseClicked = ImGui::Button(status.paused ? "run" : "pause");
    state_->noteItem("pause");
    ImGui::SameLine();
    ImGui::BeginDisabled(!status.paused);
    status.stepClicked = ImGui::Button("step");
    ImGui::EndDisabled();
    state_->noteItem("step");
    ImGui::SameLine();
    ImGui::TextUnformatted("time");
    ImGui::Separator();
    for (const FlagSpec& spec : state_->flags) {
        if (state_->control(spec, values)) changed.push_back(spec.name);
    }
    ImGui::Separator();
    ImGui::TextUnformatted("the command line of this view:");
    ImGui::PushTextWrapPos(kPanelWidth - kMargin);
    ImGui::TextUnformatted(status.commandLine.c_str());
    ImGui::PopTextWrapPos();
    if (ImGui::Button("copy")) {
        state_->copy(status.commandLine);
        state_->copied = status.commandLine;
    }
    state_->noteItem("copy");
    if (state_->copied == status.commandLine) {
        ImGui::SameLine();
        ImGui::TextUnformatted("copied to the clipboard");
        state_->noteItem("copied");
    }
    ImGui::PopItemWidth();
    ImGui::End();
    return changed;
}

bool Panel::wantsMouse() const {
    return state_->wantsMouse;
}

void Panel::draw() const {
    ImGui::SetCurrentContext(state_->context);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

std::string Panel::layout() const {
    return state_->layout.str();
}

#endif

}  // namespace pbr
