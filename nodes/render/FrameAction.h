#pragma once

#include "nodes/render/Frame.h"
#include "scenegraph/actions/Action.h"
#include "scenegraph/actions/RenderStatistics.h"

#include <cstdint>

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

    /// @brief Marks the frames collected from now on as drawn while the user interacts (the
    /// viewer's coarse frames): a scalar splat node whose transfer function changed since its
    /// last classification, over a grid storing at least previewMinimumVoxels() voxels, then
    /// draws a preview of the edit, its blocks' means from their value histograms, instead of
    /// classifying the grid again (docs/octree.md, "Transfer-function edits"). Off by default:
    /// every other frame is exact.
    void setInteractive(bool interactive) { mInteractive = interactive; }

    /// @brief Whether the frames are interactive (setInteractive()).
    bool isInteractive() const { return mInteractive; }

    /// @brief Below this many stored voxels an interactive frame classifies an edit exactly:
    /// on two cores that takes a few tens of milliseconds (Marschner–Lobb 128³, 2^21 voxels: a
    /// 50 000-splat frame after an edit in 0.07 s), and the preview, 8 times coarser, would
    /// lose more than it saves (docs/results/big-volumes.md).
    static constexpr std::uint64_t kPreviewMinimumVoxels = std::uint64_t{1} << 22;

    /// @brief Sets the grid size from which interactive frames preview edits (0: every grid).
    void setPreviewMinimumVoxels(std::uint64_t voxels) { mPreviewMinimumVoxels = voxels; }

    /// @brief The grid size from which interactive frames preview edits.
    std::uint64_t previewMinimumVoxels() const { return mPreviewMinimumVoxels; }

protected:
    /// @brief Empties the frame (keeping size and background).
    void beginTraversal(sg::Node& root) override;

private:
    Frame mFrame;
    sg::RenderStatistics mStatistics;
    bool mInteractive = false;
    std::uint64_t mPreviewMinimumVoxels = kPreviewMinimumVoxels;
};

} // namespace texsplat::render
