#pragma once

#include "nodes/render/Frame.h"
#include "scenegraph/actions/Action.h"
#include "scenegraph/actions/RenderStatistics.h"

namespace texsplat::render {

/// @brief Traverses a scene and collects its backend-neutral Frame (docs/design.md, "Data flow of
/// one frame"): meshes with their lighting, and per splat node its classified, ordered and emitted
/// splats with their footprint. No GL: a backend draws what it collects (GlRenderer,
/// cpu::CpuRenderer).
class FrameAction : public sg::Action {
public:
    /// @brief An action collecting frames of `width` x `height` pixels (what the cameras'
    /// aspect ratio follows) cleared to `background`.
    FrameAction(int width, int height, const glm::vec4& background = glm::vec4(0.0f));

    /// @brief The table of this action; the nodes library adds its node types' methods
    /// (`nodes::registerNodeTypes()`). Unregistered nodes use `Node::doAction()`.
    static sg::MethodTable& methods();

    /// @brief Traverses `root` and returns its frame; statistics() start from zero and hold
    /// the load, classify and order times and the counts.
    const Frame& collect(sg::Node& root);

    /// @brief The frame being collected, or the last one.
    Frame& frame() { return mFrame; }

    /// @brief Width over height of the frame.
    float aspectRatio() const;

    /// @brief This frame's times and counts; node methods add to them.
    sg::RenderStatistics& statistics() { return mStatistics; }

protected:
    /// @brief Empties the frame (keeping size and background).
    void beginTraversal(sg::Node& root) override;

private:
    Frame mFrame;
    sg::RenderStatistics mStatistics;
};

} // namespace texsplat::render
