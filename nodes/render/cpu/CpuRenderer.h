#pragma once

#include "nodes/image/Image.h"
#include "nodes/render/Frame.h"
#include "scenegraph/actions/RenderStatistics.h"

#include <string>

namespace texsplat::render::cpu {

/// @brief The CPU backend (DESIGN.md, "Backends"): draws a Frame without GL, as the GL backend
/// does — opaque meshes with a depth buffer, then every splat depth-tested against them,
/// composited back to front with premultiplied "over" — into a float image.
///
/// The image is split into bands of rows that threads (oneTBB) draw independently; each band
/// draws every splat in the frame's order, so each pixel is composited in list order whatever
/// the number of threads: the image is identical, byte for byte, for any thread count. Splats
/// are set up in chunks (the map from pixels to the splat's square, its depth plane and its
/// pixel box; SplatRaster) in parallel, then composited by SIMD rows (compositeSplats()).
///
/// Draws TexturedSquare and GouraudPolygon splats (the fan through its tabulated footprint);
/// vector and combined splats are left to the GL backend for now (DataError).
class CpuRenderer {
public:
    /// @brief A renderer using `threads` threads (0: one per hardware thread).
    explicit CpuRenderer(int threads = 0);

    /// @brief Draws `frame`; the time counts as RenderPhase::Draw in `statistics`, turning the
    /// planes into the image as ReadBack. With `withDepth`, the image carries the window-space
    /// depth of the meshes (1 where there is none), as the GL backend reads it back.
    /// @throws DataError for splats this backend does not draw (vector, combined).
    image::Image draw(const Frame& frame, sg::RenderStatistics& statistics,
                      bool withDepth = false) const;

    /// @brief Threads used.
    int threads() const { return mThreads; }

    /// @brief What the report names the backend: "CPU (AVX2, 2 threads)".
    std::string description() const;

    /// @brief Whether this backend draws splats of `shape`.
    static bool draws(SplatShape shape);

    /// @brief Whether this backend draws every splat batch of `frame`.
    static bool draws(const Frame& frame);

private:
    int mThreads;
};

} // namespace texsplat::render::cpu
