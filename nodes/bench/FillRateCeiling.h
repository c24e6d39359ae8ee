#pragma once

#include "nodes/render/SplatView.h"
#include "octree/Fwd.h"
#include "scenegraph/gl/Buffer.h"
#include "scenegraph/gl/Framebuffer.h"
#include "scenegraph/gl/Program.h"
#include "scenegraph/gl/VertexArray.h"

#include <cstddef>
#include <cstdint>

namespace texsplat::bench {

/// @brief The fill-rate ceiling of the current GL device for a splat list: the same number of
/// instanced quads, of the same size on screen, drawn with a trivial shader and the same
/// blending into the same kind of framebuffer as GlRenderer's splat pass.
///
/// Each quad reads the splat's centre and size from the octree's 32-byte `Splat` (the same
/// instance data a render::SplatBatch reads) and spans `extent · size` voxels in the plane
/// perpendicular to the central viewing direction; the fragment shader writes a constant
/// colour. So the ceiling pays for what no splat renderer can avoid — one instance per splat,
/// rasterization, premultiplied "over" blending into RGBA32F with the depth test on — and for
/// nothing else (no per-splat basis, no footprint lookup, no emission–absorption). A method's
/// frame time divided by the ceiling's time is the framework's overhead: 1 is the best a
/// method can do on this device. The quads face the central direction, not each its own eye
/// ray, so under perspective their area differs from the splats' by the cosine of the angle
/// off the axis (a few percent at the edge of the view); fragments() measures it.
///
/// Move-only (it holds GL objects); create and use it with the same context current.
class FillRateCeiling {
public:
    /// @brief A ceiling drawing into its own `width` x `height` RGBA32F framebuffer with a
    /// 32-bit float depth buffer (what GlRenderer renders into).
    /// @throws GlError when no context is current or the shaders do not build.
    FillRateCeiling(int width, int height);

    /// @brief Replaces the quads by one per splat of `splats`, in its order.
    void upload(const octree::SplatList& splats);

    /// @brief Clears the framebuffer, draws every quad for `view` with quads `extent` voxels
    /// from the centre at size 1, and waits for the GL (glFinish). Returns the wall seconds,
    /// clear and finish included, as GlRenderer's Draw phase counts them.
    /// @throws GlError on a GL error.
    double draw(const render::SplatView& view, float extent);

    /// @brief The fragments one draw() rasterizes, counted with a GL_SAMPLES_PASSED query.
    /// @throws GlError on a GL error.
    std::uint64_t fragments(const render::SplatView& view, float extent);

    /// @brief Number of uploaded quads.
    std::size_t size() const { return mCount; }

private:
    void drawQuads(const render::SplatView& view, float extent);

    gl::Framebuffer mFramebuffer;
    gl::Program mProgram;
    gl::Buffer mCorners;
    gl::Buffer mInstances;
    gl::VertexArray mVertexArray;
    std::size_t mCount = 0;
};

} // namespace texsplat::bench
