#pragma once

#include "apps/viewer/ProgressiveRefinement.h"
#include "scenegraph/engines/AnimationSpeed.h"

#include <cstddef>
#include <string>

struct GLFWwindow;

namespace texsplat::apps {

class TransferFunctionEditor;

/// @brief What the viewer's panel shows about the last frame.
struct PanelReport {
    std::string renderer;     ///< what draws the frames: the CPU backend or the GL context
    double frameSeconds = 0.0; ///< time of the last scene render (traversal to glFinish)
    std::size_t splats = 0;    ///< splats of the last render
    std::size_t triangles = 0; ///< opaque triangles of the last render
    ProgressiveRefinement::Stage stage = ProgressiveRefinement::Stage::FullQuality;
    std::int32_t budget = 0; ///< splat budget in force (0: the scene's own settings)
};

/// @brief The viewer's ImGui overlay: the last frame's statistics, the refinement state, a
/// slider for the interactive splat budget, the transfer functions' range, opacity and colour map
/// (TransferFunctionEditor) and, for a scene with ElapsedTime engines, the animation's pause and
/// speed. Built only when the ImGui GLFW and OpenGL 3
/// backends are available (Debian ships them as sources with libimgui-dev); otherwise every
/// call does nothing and the viewer runs without a panel.
class ViewerPanel {
public:
    /// @brief Sets ImGui up on `window` (its context current); installs ImGui's input
    /// callbacks, which chain to those the window had.
    explicit ViewerPanel(GLFWwindow* window);
    ~ViewerPanel();

    ViewerPanel(const ViewerPanel&) = delete;
    ViewerPanel& operator=(const ViewerPanel&) = delete;

    /// @brief True when the panel is built into this texsplat.
    static bool isAvailable();

    /// @brief True while the pointer is over the panel (the view must not take the drag).
    bool wantsMouse() const;

    /// @brief True while the panel takes typed keys (a slider's text entry: ctrl+click).
    bool wantsKeyboard() const;

    /// @brief Draws the panel over the frame; may change the refinement's interactive budget,
    /// the animation's pause and speed factor (hidden when it controls no engine) and the
    /// transfer functions (hidden when the scene has none). Returns true while a transfer-function
    /// control is held or changed a field: the viewer draws coarse frames meanwhile, as while the
    /// view moves.
    bool draw(const PanelReport& report, ProgressiveRefinement& refinement,
              sg::AnimationSpeed& animation, TransferFunctionEditor& transfer);

private:
    GLFWwindow* mWindow;
};

} // namespace texsplat::apps
