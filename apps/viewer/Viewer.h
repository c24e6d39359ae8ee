#pragma once

#include "apps/SceneSetup.h"
#include "nodes/render/BackendChoice.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <string>

namespace texsplat::apps {

/// @brief What `texsplat view` was asked for.
struct ViewerOptions {
    std::string scene;                  ///< scene file; empty: the built-in default scene
    Framing framing;                    ///< camera for a scene without one
    glm::ivec2 size{960, 720};          ///< initial window size in pixels
    int frames = 0;                     ///< stop after this many frames (0: when closed)
    std::string screenshot;             ///< write the last frame here (PNG or EXR) at the end
    std::int32_t interactiveBudget = 50000; ///< splats per node while the view moves
    glm::vec3 background{0.02f, 0.02f, 0.025f}; ///< RGB behind the scene
    render::BackendRequest backend = render::BackendRequest::Auto; ///< what draws the frames
    int threads = 0; ///< CPU backend threads (0: one per hardware thread)
    bool timeReport = false; ///< a line per rendered frame on stderr: stage, splats, phases
};

/// @brief The interactive viewer: a GLFW window showing the scene as a backend draws it
/// (ViewerFrames: GL, or the CPU where GL is a software rasterizer),
/// with an examiner-style camera (OrbitController), Laur–Hanrahan progressive refinement
/// (ProgressiveRefinement: coarse while the view moves, refined while idle), animation through
/// a SensorQueue on the wall clock (the scene's engines follow its time), and an ImGui panel.
///
/// The loop sleeps until an event or the next timer when nothing changes, and re-renders the
/// scene only after a change (a NodeSensor on the root), so an idle viewer costs nothing.
class Viewer {
public:
    /// @brief Reads the scene file (before any window opens, so a bad file is reported first).
    /// @throws what loadScene() throws.
    explicit Viewer(ViewerOptions options);

    /// @brief Opens the window, frames the scene (withCamera(), which may read its volumes: Esc or
    /// q cancels that as it cancels a frame's long steps, and the viewer quits), and runs until
    /// the window is closed (or `frames` frames were shown), then writes the screenshot if one was
    /// asked for.
    /// @throws GlError when no window can be opened; what withCamera() and rendering throw.
    void run();

private:
    ViewerOptions mOptions;
    sg::Node::Ptr mScene;
};

} // namespace texsplat::apps
