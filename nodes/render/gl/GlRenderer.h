#pragma once

#include "nodes/image/Image.h"
#include "nodes/render/Frame.h"
#include "scenegraph/actions/RenderStatistics.h"
#include "scenegraph/gl/Framebuffer.h"

#include <memory>
#include <optional>

namespace texsplat::render {
namespace detail {
class SplatBatchCache;
} // namespace detail

/// @brief The GL backend (docs/design.md, "Backends"): draws a Frame with OpenGL into an
/// off-screen float framebuffer, the paper's way — instanced textured quads.
///
/// A frame is drawn in two passes after clearing to the frame's background:
/// 1. the meshes (a MeshBatch each, uploaded per frame: they are small next to the volumes), in
///    the frame's order, depth test and depth write on, no blending;
/// 2. the splats, depth-tested against pass 1 but not writing depth, blended with
///    premultiplied-alpha "over" (glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA)), each batch
///    already back to front (Crawfis & Max 1993, section 3: "the splats are built up in back to
///    front order"). Batches of several nodes are composited in one depth order across nodes
///    (detail::depthOrderedRuns), so two volumes in the same space (the paper's figure 8: clouds
///    and winds) interleave instead of one lying over the other.
///
/// The SplatBatch of each footprint (its shaders and textures) is kept while the footprint is
/// (nodes make a new one when a field that shapes their splats changes), per GL context; its
/// instances are uploaded when the frame brings a new splat list.
///
/// Namespace render, not render::gl: that one would hide texsplat::gl, the GL object layer that
/// every file of this backend uses. Created and used with one GL context current.
class GlRenderer {
public:
    /// @brief A renderer for the current context; its framebuffer is made with the first frame
    /// and again when the frame size changes.
    /// @throws GlError when no context is current.
    GlRenderer();
    ~GlRenderer();
    GlRenderer(GlRenderer&&) noexcept;
    GlRenderer& operator=(GlRenderer&&) noexcept;

    /// @brief Throws the GlError drawing a `width` x `height` frame would, without allocating
    /// (gl::Framebuffer::checkSize()): commands ask it before any work.
    static void checkSize(int width, int height);

    /// @brief Draws `frame` into framebuffer(), as the class notes say. Times count as
    /// RenderPhase::Upload (meshes, new batches, instances), Order (merging several batches) and
    /// Draw (both passes until glFinish()); the batches' texture bytes add to `memory.textures`
    /// and the batches made to `builds.splatBatches`.
    /// @throws GlError when the framebuffer cannot be made or the GL reports an error.
    void render(const Frame& frame, sg::RenderStatistics& statistics);

    /// @brief render(), then the framebuffer read back as the CPU backend's draw() returns its
    /// image: premultiplied float RGBA, top row first, the light scaled back from what GL drew
    /// (gl/LightScale.h) and clamped to ±FLT_MAX (NaN stays NaN); with `withDepth`, the
    /// window-space depth in [0, 1] of the meshes (1 where there is none; splats write none).
    /// The read-back counts as RenderPhase::ReadBack.
    image::Image draw(const Frame& frame, sg::RenderStatistics& statistics,
                      bool withDepth = false);

    /// @brief The render target of the last frame (the viewer shows it); it holds the light
    /// scaled by gl::kLightScale.
    /// @throws GlError when no frame was drawn yet.
    const gl::Framebuffer& framebuffer() const;

private:
    image::Image readBack(sg::RenderStatistics& statistics, bool withDepth) const;

    std::optional<gl::Framebuffer> mFramebuffer;
    std::unique_ptr<detail::SplatBatchCache> mBatches;
};

} // namespace texsplat::render
