#include "apps/viewer/ViewerPanel.h"

#ifdef TEXSPLAT_VIEWER_PANEL
#include <epoxy/gl.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#endif

namespace texsplat::apps {

#ifdef TEXSPLAT_VIEWER_PANEL

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

void ViewerPanel::draw(const PanelReport& report, ProgressiveRefinement& refinement,
                       sg::AnimationSpeed& animation) {
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
    ImGui::TextUnformatted(animation.isEmpty()
                               ? "drag: orbit  right/middle drag: pan  wheel: zoom  r: reset  "
                                 "q: quit"
                               : "drag: orbit  right/middle drag: pan  wheel: zoom  r: reset  "
                                 "space: pause  q: quit");
    ImGui::End();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

#else

ViewerPanel::ViewerPanel(GLFWwindow* window) : mWindow(window) {}
ViewerPanel::~ViewerPanel() = default;
bool ViewerPanel::isAvailable() { return false; }
bool ViewerPanel::wantsMouse() const { return false; }
bool ViewerPanel::wantsKeyboard() const { return false; }
void ViewerPanel::draw(const PanelReport&, ProgressiveRefinement&, sg::AnimationSpeed&) {}

#endif

} // namespace texsplat::apps
