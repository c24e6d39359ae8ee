#pragma once

#include "scenegraph/actions/Action.h"
#include "scenegraph/actions/RenderStatistics.h"
#include "scenegraph/gl/Framebuffer.h"

#include <glm/vec4.hpp>

#include <cstddef>
#include <functional>
#include <vector>

namespace texsplat::sg {

/// @brief Draws a scene with OpenGL into an off-screen float framebuffer (docs/design.md, "Data
/// flow of one frame").
///
/// The traversal only *collects* work: node methods registered in `methods()` (by the nodes
/// library) read the traversal state (camera, transform, transfer function, volume) and hand
/// the action closures with everything they need, in two ordered lists. `render()` then draws:
/// 1. the opaque list in traversal order, depth test and depth write on, no blending;
/// 2. the splats, depth-tested against pass 1 but not writing depth, blended with
///    premultiplied-alpha "over" (glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA)), each splat
///    node's batch already back to front (Crawfis & Max 1993, section 3: "the splats are built
///    up in back to front order"). Batches of different nodes are composited in one depth order
///    across nodes: the batches are merged by the depths of their splats (detail::
///    depthOrderedRuns), so two volumes in the same space (the paper's figure 8: clouds and
///    winds) interleave instead of one lying over the other.
/// So a splat behind an opaque surface is hidden and one in front blends over it, whatever
/// the order of the nodes in the graph.
///
/// The action needs a current GL context for its whole life; it owns the framebuffer and
/// keeps it between frames (the viewer re-renders into the same one).
class RenderAction : public Action {
public:
    /// @brief A unit of work a node hands to the action; called once, with the framebuffer
    /// bound and the pass's GL state set.
    using DrawFunction = std::function<void()>;

    /// @brief One node's back-to-front splats for the splat pass.
    struct SplatWork {
        /// @brief Number of splats.
        std::size_t count = 0;
        /// @brief The distance from the eye of each splat (any measure common to the frame's
        /// batches: camera-space depth), asked for only when the frame has several batches.
        std::function<std::vector<float>()> depths;
        /// @brief Draws splats [begin, end), in their order; called with increasing ranges.
        std::function<void(std::size_t begin, std::size_t end)> drawRange;
    };

    /// @brief An action drawing into a new `width` x `height` framebuffer of `color` storage
    /// and 32-bit float depth.
    /// @throws GlError when no context is current or the size is beyond the driver's limit.
    RenderAction(int width, int height,
                 gl::FramebufferColor color = gl::FramebufferColor::Rgba32F);

    /// @brief Throws the GlError the constructor would for this size, without allocating
    /// (gl::Framebuffer::checkSize()): commands ask it before any work.
    static void checkSize(int width, int height,
                          gl::FramebufferColor color = gl::FramebufferColor::Rgba32F);

    /// @brief The table of this action; the nodes library adds its node types' render methods
    /// (`nodes::registerNodeTypes()`). Unregistered nodes use `Node::doAction()`.
    static MethodTable& methods();

    /// @brief Traverses `root` to collect work, clears the framebuffer to the background and
    /// runs the opaque pass, then the splat pass. Statistics start from zero.
    /// @throws GlError when the GL reports an error during the frame.
    void render(Node& root);

    /// @brief Queues opaque geometry for pass 1 (during traversal).
    void addOpaque(DrawFunction draw) { mOpaque.push_back(std::move(draw)); }

    /// @brief Queues a node's back-to-front splats for pass 2 (during traversal).
    void addSplats(SplatWork work) { mSplats.push_back(std::move(work)); }

    /// @brief Queues splat drawing of no known depth for pass 2: one piece drawn whole, before
    /// any splat with a depth (it counts as the farthest).
    void addSplats(DrawFunction draw);

    /// @brief The premultiplied color the framebuffer is cleared to; default transparent black.
    void setBackground(const glm::vec4& color) { mBackground = color; }

    /// @brief The clear color.
    const glm::vec4& background() const { return mBackground; }

    /// @brief The render target (color and depth of the last frame).
    const gl::Framebuffer& framebuffer() const { return mFramebuffer; }

    /// @brief Width over height of the framebuffer, what cameras need for their projection.
    float aspectRatio() const;

    /// @brief The last frame's statistics; nodes add their times and counts while traversing.
    RenderStatistics& statistics() { return mStatistics; }

    /// @brief Adds `seconds` to `phase` of the current frame's statistics.
    void addTime(RenderPhase phase, double seconds);

    /// @brief The color of the last frame, premultiplied RGBA floats, top row first, its light
    /// scaled back from what GL drew (gl/LightScale.h; +Inf beyond FLT_MAX); the time counts as
    /// RenderPhase::ReadBack. The framebuffer() itself holds the light scaled.
    std::vector<float> readColor();

    /// @brief Window-space depth in [0, 1] of the last frame (1: nothing opaque), top row
    /// first; the time counts as RenderPhase::ReadBack.
    std::vector<float> readDepth();

protected:
    /// @brief Empties the work lists.
    void beginTraversal(Node& root) override;

private:
    void drawPasses();
    void drawSplats();

    gl::Framebuffer mFramebuffer;
    glm::vec4 mBackground{0.0f};
    std::vector<DrawFunction> mOpaque;
    std::vector<SplatWork> mSplats;
    RenderStatistics mStatistics;
};

} // namespace texsplat::sg
