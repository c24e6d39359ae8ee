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
/// A frame larger than the device's largest framebuffer (gl::Framebuffer::largestSquare(), e.g.
/// 10032² RGBA32F on llvmpipe) is drawn in tiles by draw(): every clip-space matrix of the frame
/// (the splats' SplatView::localToClip, the meshes' MeshLighting::localToClip) is multiplied by
/// a tile matrix that scales and moves the tile's part of the image onto the viewport, and each
/// tile is read back into its place. A frame that fits is drawn in one piece, with the frame's
/// matrices as they are.
///
/// Namespace render, not render::gl: that one would hide texsplat::gl, the GL object layer that
/// every file of this backend uses. Created and used with one GL context current.
class GlRenderer {
public:
    /// @brief A renderer for the current context; its framebuffer is made with the first frame
    /// and again when the frame (or tile) size changes.
    /// @throws GlError when no context is current.
    GlRenderer();
    ~GlRenderer();
    GlRenderer(GlRenderer&&) noexcept;
    GlRenderer& operator=(GlRenderer&&) noexcept;

    /// @brief Draws `frame` into framebuffer(), whole, as the class notes say. Times count as
    /// RenderPhase::Upload (meshes, new batches, instances), Order (merging several batches) and
    /// Draw (both passes until glFinish()); the batches' texture bytes add to `memory.textures`
    /// and the batches made to `builds.splatBatches`.
    /// @throws GlError when the device cannot hold a framebuffer of the frame's size or the GL
    /// reports an error.
    void render(const Frame& frame, sg::RenderStatistics& statistics);

    /// @brief Draws `frame` as render() does, in tiles where it is larger than maxTileSize(), and
    /// reads it back as the CPU backend's draw() returns its image: premultiplied float RGBA, top
    /// row first, the light scaled back from what GL drew (gl/LightScale.h) and clamped to
    /// ±FLT_MAX (NaN stays NaN); with `withDepth`, the window-space depth in [0, 1] of the meshes
    /// (1 where there is none; splats write none). The read-back counts as RenderPhase::ReadBack.
    /// As for the CPU backend, the caller asks the memory limit for the image (checkMemory():
    /// the render command does, before the first frame).
    /// @throws GlError as render().
    image::Image draw(const Frame& frame, sg::RenderStatistics& statistics,
                      bool withDepth = false);

    /// @brief Makes draw() split frames into tiles of at most `pixels` a side; 0 (the default):
    /// the device's largest framebuffer. Smaller tiles cost a pass over the frame's splats each.
    /// @throws DataError when `pixels` is negative.
    void setMaxTileSize(int pixels);

    /// @brief The largest tile side draw() uses (asks the device the first time when
    /// setMaxTileSize() was not given one).
    int maxTileSize();

    /// @brief The render target of the last frame or tile (the viewer shows it); it holds the
    /// light scaled by gl::kLightScale.
    /// @throws GlError when no frame was drawn yet.
    const gl::Framebuffer& framebuffer() const;

private:
    struct Prepared;
    struct Tile;

    void useFramebuffer(int width, int height);
    Prepared prepare(const Frame& frame, sg::RenderStatistics& statistics);
    void drawPasses(const Frame& frame, Prepared& prepared, const Tile* tile,
                    sg::RenderStatistics& statistics);
    void readTile(const Tile& tile, image::Image& image, sg::RenderStatistics& statistics) const;

    std::optional<gl::Framebuffer> mFramebuffer;
    std::unique_ptr<detail::SplatBatchCache> mBatches;
    int mMaxTileSize = 0;
};

} // namespace texsplat::render
