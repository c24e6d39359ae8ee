#pragma once

#include "apps/viewer/FramePresenter.h"
#include "nodes/render/BackendChoice.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/cpu/CpuRenderer.h"
#include "nodes/render/gl/GlRenderer.h"
#include "scenegraph/WorkProgress.h"
#include "scenegraph/gl/Texture2D.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <optional>
#include <string>

namespace texsplat::apps {

/// @brief The viewer's frames, collected by a FrameAction and drawn by the backend the user asked
/// for: GL (GlRenderer's framebuffer, shown as it is) or the CPU (CpuRenderer's image, uploaded as
/// one float texture per frame), so progressive viewing is interactive on a machine whose GL is a
/// software rasterizer too. `auto` takes the CPU when the window's GL renderer is llvmpipe,
/// softpipe or swrast.
///
/// Created and used with the window's context current.
class ViewerFrames {
public:
    /// @brief Frames for `request` in a window whose GL renderer is `renderer`, cleared to the
    /// opaque `background`; the CPU backend uses `threads` threads (0: all).
    ViewerFrames(render::BackendRequest request, const std::string& renderer,
                 const glm::vec3& background, int threads);

    /// @brief Makes the render target `size` pixels; answers whether it changed (then the
    /// scene must be drawn again).
    bool resize(const glm::ivec2& size);

    /// @brief Where the frames' long steps (classification, the octree build) report, and may
    /// be cancelled (then render() throws sg::Cancelled and the next frame starts them again).
    void setWorkProgress(sg::WorkProgress progress);

    /// @brief Draws `root` into the target, an `interactive` frame or not
    /// (render::FrameAction::setInteractive()); answers the frame's statistics.
    /// @throws sg::Cancelled when the work progress cancelled a step.
    const sg::RenderStatistics& render(sg::Node& root, bool interactive);

    /// @brief Whether a frame was drawn since the last resize().
    bool hasFrame() const { return mHasFrame; }

    /// @brief Shows the last frame through `presenter` in a window of `windowSize`.
    void present(FramePresenter& presenter, const glm::vec3& background,
                 const glm::ivec2& windowSize) const;

    /// @brief What draws the frames, for the panel: "CPU (AVX2, 2 threads)" or the GL summary.
    std::string description() const;

private:
    std::string mRenderer;
    glm::vec4 mBackground;
    glm::ivec2 mSize{0, 0};
    bool mHasFrame = false;
    sg::WorkProgress mProgress;
    std::unique_ptr<render::FrameAction> mFrameAction;
    // GL backend.
    std::optional<render::GlRenderer> mGl;
    // CPU backend.
    std::optional<render::cpu::CpuRenderer> mCpu;
    std::unique_ptr<gl::Texture2D> mTexture;
};

} // namespace texsplat::apps
