#include "apps/viewer/ViewerPanel.h"

#include "apps/viewer/TransferFunctionEditor.h"

#ifdef TEXSPLAT_VIEWER_PANEL
#include <epoxy/gl.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <string>
#include <vector>
#endif

namespace texsplat::apps {

#ifdef TEXSPLAT_VIEWER_PANEL

namespace {

// The transfer-function section; true while one of its controls is held or changed a field.
bool drawTransferFunction(TransferFunctionEditor& editor) {
    if (editor.isEmpty() || !ImGui::CollapsingHeader("transfer function", ImGuiTreeNodeFlags_DefaultOpen)) {
        return false;
    }
    bool editing = false;
    if (editor.count() > 1) {
        std::vector<std::string> labels;
        std::vector<const char*> items;
        for (std::size_t index = 0; index < editor.count(); ++index) {
            labels.push_back(editor.label(index));
        }
        for (const std::string& label : labels) {
            items.push_back(label.c_str());
        }
        int selected = static_cast<int>(editor.selected());
        if (ImGui::Combo("function", &selected, items.data(), static_cast<int>(items.size()))) {
            editor.select(static_cast<std::size_t>(selected));
        }
    }
    if (editor.editsRange()) {
        glm::vec2 range = editor.range();
        const glm::vec2 bounds = editor.rangeBounds();
        // Dragging across the control's width sweeps about the whole data range.
        const float speed = (bounds.y - bounds.x) / 300.0f;
        if (ImGui::DragFloatRange2("range", &range.x, &range.y, speed, bounds.x, bounds.y, "%.4g",
                                   "%.4g", ImGuiSliderFlags_AlwaysClamp) &&
            range.x < range.y) {
            editor.setRange(range);
            editing = true;
        }
        editing = editing || ImGui::IsItemActive();
    }
    if (editor.editsOpacity()) {
        float factor = editor.opacityFactor();
        if (ImGui::SliderFloat("opacity", &factor, 0.01f, 100.0f, "%.3gx",
                               ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp)) {
            editor.setOpacityFactor(factor);
            editing = true;
        }
        editing = editing || ImGui::IsItemActive();
    }
    if (editor.editsPreset()) {
        const int preset = static_cast<int>(editor.preset());
        const std::string* current = nodes::kColorPresetNames.name(preset);
        if (ImGui::BeginCombo("colour map", current ? current->c_str() : "")) {
            for (int value = 0; const std::string* name = nodes::kColorPresetNames.name(value);
                 ++value) {
                if (ImGui::Selectable(name->c_str(), value == preset) && value != preset) {
                    editor.setPreset(static_cast<nodes::ColorPreset>(value));
                    editing = true;
                }
            }
            ImGui::EndCombo();
        }
    }
    if (editor.isEdited() && ImGui::Button("reset")) {
        editor.reset();
        editing = true;
    }
    return editing;
}

} // namespace

ViewerPanel::ViewerPanel(GLFWwindow* window) : mWindow(window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini next to the user's files
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(mWindow, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
}

ViewerPanel::~ViewerPanel() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

bool ViewerPanel::isAvailable() { return true; }

bool ViewerPanel::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }

bool ViewerPanel::wantsKeyboard() const { return ImGui::GetIO().WantTextInput; }

bool ViewerPanel::draw(const PanelReport& report, ProgressiveRefinement& refinement,
                       sg::AnimationSpeed& animation, TransferFunctionEditor& transfer) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::Begin("texsplat", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::TextUnformatted(report.renderer.c_str());
    ImGui::Text("frame %.1f ms", 1000.0 * report.frameSeconds);
    ImGui::Text("splats %zu, triangles %zu", report.splats, report.triangles);
    ImGui::Text("%s", ProgressiveRefinement::toString(report.stage));
    if (report.budget > 0) {
        ImGui::SameLine();
        ImGui::Text("(budget %d)", report.budget);
    }
    if (refinement.hasSplatNodes()) {
        int budget = refinement.interactiveBudget();
        if (ImGui::SliderInt("interactive splats", &budget, 1000, 1000000, "%d",
                             ImGuiSliderFlags_Logarithmic)) {
            refinement.setInteractiveBudget(budget);
        }
    }
    if (!animation.isEmpty()) {
        // Crawfis & Max's "Slider ... attached to the Timer": a factor on every ElapsedTime's
        // own speed, so engines keep their relative rates.
        bool paused = animation.isPaused();
        if (ImGui::Checkbox("pause", &paused)) {
            animation.setPaused(paused);
        }
        ImGui::SameLine();
        float factor = animation.factor();
        if (ImGui::SliderFloat("animation speed", &factor, 0.1f, 10.0f, "%.2fx",
                               ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp)) {
            animation.setFactor(factor);
        }
    }
    const bool editing = drawTransferFunction(transfer);
    ImGui::TextUnformatted(animation.isEmpty()
                               ? "drag: orbit  right/middle drag: pan  wheel: zoom  r: reset  "
                                 "q: quit"
                               : "drag: orbit  right/middle drag: pan  wheel: zoom  r: reset  "
                                 "space: pause  q: quit");
    ImGui::End();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    return editing;
}

#else

ViewerPanel::ViewerPanel(GLFWwindow* window) : mWindow(window) {}
ViewerPanel::~ViewerPanel() = default;
bool ViewerPanel::isAvailable() { return false; }
bool ViewerPanel::wantsMouse() const { return false; }
bool ViewerPanel::wantsKeyboard() const { return false; }
bool ViewerPanel::draw(const PanelReport&, ProgressiveRefinement&, sg::AnimationSpeed&,
                       TransferFunctionEditor&) {
    return false;
}

#endif

} // namespace texsplat::apps
