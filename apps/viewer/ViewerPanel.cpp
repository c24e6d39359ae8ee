#include "apps/viewer/ViewerPanel.h"

#include "apps/viewer/TransferFunctionEditor.h"

#ifdef TEXSPLAT_VIEWER_PANEL
#include <epoxy/gl.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>
#endif

namespace texsplat::apps {

#ifdef TEXSPLAT_VIEWER_PANEL

namespace {

// The opacity curve of the selected function over a histogram of the data under its range (log
// counts): drag a point to move it, double-click to add one, right-click a point to remove it.
// True while a point is dragged or when one was added or removed.
bool drawOpacityCurve(TransferFunctionEditor& editor) {
    const ImVec2 size(std::max(ImGui::CalcItemWidth(), 64.0f), 100.0f); // never 0: it divides
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("opacity curve", size,
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    const bool hovered = ImGui::IsItemHovered();
    const bool active = ImGui::IsItemActive();
    ImGui::SameLine();
    ImGui::TextUnformatted("opacity\ncurve");
    ImGuiStorage& storage = *ImGui::GetStateStorage();
    const ImGuiID draggedKey = ImGui::GetID("dragged point");
    const ImGuiID topKey = ImGui::GetID("curve top");
    ImDrawList& draw = *ImGui::GetWindowDrawList();
    draw.AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y),
                       IM_COL32(16, 16, 20, 255));

    // Per column: the colour map along the bottom edge, and the histogram bar above it in the
    // same colour, dimmed.
    const glm::vec2 range = editor.range();
    const glm::vec2 data = editor.dataRange();
    constexpr std::size_t kBins = 256;
    constexpr float kStrip = 5.0f;
    const std::vector<std::uint64_t>& counts = editor.histogram(kBins);
    const std::uint64_t most = *std::max_element(counts.begin(), counts.end());
    const auto columns = static_cast<int>(size.x);
    for (int column = 0; column < columns; ++column) {
        const float t = (static_cast<float>(column) + 0.5f) / size.x;
        const glm::vec3 colour = editor.colorAt(t);
        const auto encoded = [&](float dim) {
            const auto byte = [dim](float value) {
                return static_cast<int>(255.0f * std::clamp(value * dim, 0.0f, 1.0f) + 0.5f);
            };
            return IM_COL32(byte(colour.r), byte(colour.g), byte(colour.b), 255);
        };
        const float x = origin.x + static_cast<float>(column);
        draw.AddLine(ImVec2(x, origin.y + size.y), ImVec2(x, origin.y + size.y - kStrip),
                     encoded(1.0f));
        const float value = range.x + t * (range.y - range.x);
        const float bin = (value - data.x) / (data.y - data.x) * static_cast<float>(kBins);
        if (most == 0 || bin < 0.0f || bin >= static_cast<float>(kBins)) {
            continue;
        }
        const auto count = static_cast<double>(counts[static_cast<std::size_t>(bin)]);
        const auto height =
            static_cast<float>(std::log1p(count) / std::log1p(static_cast<double>(most)));
        draw.AddLine(ImVec2(x, origin.y + size.y - kStrip),
                     ImVec2(x, origin.y + (size.y - kStrip) * (1.0f - height)), encoded(0.35f));
    }

    // The vertical scale: the largest opacity in effect, kept while a point is dragged so that
    // the point stays under the pointer.
    const std::vector<glm::vec2>& points = editor.opacityPoints();
    const float factor = editor.opacityFactor();
    int dragged = storage.GetInt(draggedKey, -1);
    if (dragged >= static_cast<int>(points.size())) {
        dragged = -1; // the points changed under it (reset, another function)
    }
    float top = storage.GetFloat(topKey, 1.0f);
    if (dragged < 0) {
        top = 0.0f;
        for (const glm::vec2 point : points) {
            top = std::max(top, point.y * factor);
        }
        top = top > 0.0f ? 1.1f * top : 1.0f;
    }
    const auto screen = [&](glm::vec2 point) {
        return ImVec2(origin.x + point.x * size.x,
                      origin.y + size.y * (1.0f - point.y * factor / top));
    };
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const glm::vec2 atMouse((mouse.x - origin.x) / size.x,
                            (1.0f - (mouse.y - origin.y) / size.y) * top / factor);
    // The point within 6 pixels of the pointer, if any.
    int near = -1;
    float nearest = 36.0f;
    for (std::size_t index = 0; index < points.size(); ++index) {
        const ImVec2 at = screen(points[index]);
        const float dx = at.x - mouse.x;
        const float dy = at.y - mouse.y;
        const float distance = dx * dx + dy * dy;
        if (distance <= nearest) {
            nearest = distance;
            near = static_cast<int>(index);
        }
    }

    bool changed = false;
    if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        if (near < 0 && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
            near = static_cast<int>(editor.addOpacityPoint(atMouse));
            changed = true;
        }
        dragged = near;
    }
    if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Right) && near >= 0) {
        editor.removeOpacityPoint(static_cast<std::size_t>(near));
        near = -1;
        dragged = -1;
        changed = true;
    }
    if (dragged >= 0 && active && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        const glm::vec2 before = points[static_cast<std::size_t>(dragged)];
        editor.moveOpacityPoint(static_cast<std::size_t>(dragged), atMouse);
        changed = changed || points[static_cast<std::size_t>(dragged)] != before;
    } else {
        dragged = -1;
    }
    storage.SetInt(draggedKey, dragged);
    storage.SetFloat(topKey, top);

    // The curve, constant beyond its first and last point, and its points.
    if (!points.empty()) {
        std::vector<ImVec2> line{screen({0.0f, points.front().y})};
        for (const glm::vec2 point : points) {
            line.push_back(screen(point));
        }
        line.push_back(screen({1.0f, points.back().y}));
        draw.AddPolyline(line.data(), static_cast<int>(line.size()), IM_COL32(240, 200, 90, 255),
                         ImDrawFlags_None, 1.5f);
        for (std::size_t index = 0; index < points.size(); ++index) {
            const bool marked = static_cast<int>(index) == (dragged >= 0 ? dragged : near);
            const ImU32 colour =
                marked ? IM_COL32(255, 255, 255, 255) : IM_COL32(240, 200, 90, 255);
            draw.AddCircleFilled(screen(points[index]), marked ? 5.0f : 3.5f, colour);
        }
    }
    const int shown = dragged >= 0 ? dragged : near;
    if (shown >= 0 && (hovered || active)) {
        const glm::vec2 point = points[static_cast<std::size_t>(shown)];
        ImGui::SetTooltip("value %.4g\nopacity %.3g", range.x + point.x * (range.y - range.x),
                          point.y * factor);
    }
    return changed || (active && dragged >= 0);
}

// The transfer-function section; true while one of its controls is held or changed a field.
bool drawTransferFunction(TransferFunctionEditor& editor) {
    if (editor.isEmpty() ||
        !ImGui::CollapsingHeader("transfer function", ImGuiTreeNodeFlags_DefaultOpen)) {
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
        editing = drawOpacityCurve(editor) || editing;
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
    if (ImGui::Button("copy as text")) {
        // For the scene file: on the clipboard and on stdout (a terminal keeps it).
        const std::string text = editor.sceneText();
        ImGui::SetClipboardText(text.c_str());
        std::printf("%s", text.c_str());
        std::fflush(stdout);
    }
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("the function as scene-file text, to the clipboard and stdout");
    }
    if (editor.isEdited()) {
        ImGui::SameLine();
        if (ImGui::Button("reset")) {
            editor.reset();
            editing = true;
        }
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
