#pragma once

#include "nodes/image/Image.h"
#include "nodes/render/Frame.h"
#include "scenegraph/actions/RenderStatistics.h"

#include <memory>
#include <string>

namespace texsplat::render::cpu {
class ColorPlanes;
namespace detail {
class SamplerCache;
} // namespace detail

/// @brief The CPU backend (docs/design.md, "Backends"): draws a Frame without GL, as the GL backend
/// does — opaque meshes with a depth buffer, then every splat depth-tested against them,
/// composited back to front with premultiplied "over" — into a float image.
///
/// The image is split into bands of rows that threads (oneTBB) draw independently; each band
/// draws every splat in the frame's order, so each pixel is composited in list order whatever
/// the number of threads: the image is identical, byte for byte, for any thread count. Splats
/// are set up in chunks (the map from pixels to the splat's square, its depth plane and its
/// pixel box; SplatRaster) in parallel, then composited by SIMD rows (compositeSplats()).
///
/// Draws every kind of splat: TexturedSquare, GouraudPolygon (the fan through its tabulated
/// footprint), and the vector and combined splats' squares turned to their vectors with the
/// mark table.
class CpuRenderer {
public:
    /// @brief A renderer using `threads` threads (0: one per hardware thread).
    explicit CpuRenderer(int threads = 0);
    ~CpuRenderer();
    CpuRenderer(CpuRenderer&&) noexcept;
    CpuRenderer& operator=(CpuRenderer&&) noexcept;

    /// @brief Draws `frame`; the time counts as RenderPhase::Draw in `statistics`, turning the
    /// planes into the image as ReadBack (a grid's voxels drawn without a list: in Draw, each
    /// band's threads copying it once drawn). With `withDepth`, the image carries the window-space
    /// depth of the meshes (1 where there is none), as the GL backend reads it back.
    image::Image draw(const Frame& frame, sg::RenderStatistics& statistics,
                      bool withDepth = false) const;

    /// @brief Threads used.
    int threads() const { return mThreads; }

    /// @brief What the report names the backend: "CPU (AVX2, 2 threads)".
    std::string description() const;

    /// @brief Frees the colour planes kept for the next frame (one image's worth), for a caller
    /// that draws no other frame soon and needs the memory (a rank before compositing).
    void releasePlanes();

private:
    int mThreads;
    // The footprints and mark tables laid out for the rasterizer, kept while their nodes' are
    // (a frame after frame of the same scene lays them out once). Not thread-safe: one draw()
    // at a time.
    std::unique_ptr<detail::SamplerCache> mSamplers;
    // The last frame's colour planes, cleared for the next frame of the same size instead of
    // allocated again (a new allocation faults in every page of it, on one thread, each
    // frame). Not thread-safe either.
    mutable std::unique_ptr<ColorPlanes> mPlanes;
};

} // namespace texsplat::render::cpu
