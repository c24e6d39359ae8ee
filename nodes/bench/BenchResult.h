#pragma once

#include "scenegraph/actions/RenderStatistics.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

namespace texsplat::bench {

/// @brief What `texsplat bench` measured for one method on one dataset at one image size.
///
/// Times are medians over the repeated frames after warm-up, in wall seconds; a frame is
/// FrameAction::collect() and, on GL, GlRenderer::render() to glFinish, on the CPU
/// CpuRenderer::draw() to the finished image (classification is cached after the
/// warm-up, as in an interactive viewer). Errors are over R, G, B pooled, on the premultiplied
/// float images (image::ImageComparison, PSNR peak 1); NaN where there was nothing to compare
/// against (no reference, or no full-quality method in the run), +infinity PSNR for identical
/// images.
struct BenchResult {
    std::string dataset;     ///< BenchDataset::name()
    int width = 0;           ///< image width in pixels
    int height = 0;          ///< image height in pixels
    std::string method;      ///< BenchMethod::name()
    std::string backend;     ///< "gl" or "cpu"
    bool isFullQuality = false; ///< the texture splat with the paper's kernel at full resolution
    bool isShaded = false;      ///< the volume shaded (BenchMethod::shaded), lit every frame
    std::size_t splats = 0;  ///< splats drawn per frame
    std::uint64_t fragments = 0;        ///< fragments per frame (GL_SAMPLES_PASSED query)
    std::uint64_t ceilingFragments = 0; ///< fragments of the fill-rate ceiling's quads
    double frameSeconds = 0.0;   ///< median frame time
    std::array<double, sg::kRenderPhaseCount> phaseSeconds{}; ///< median per RenderPhase
    /// @brief Median time of the fill-rate ceiling (FillRateCeiling); GL only, NaN on the CPU.
    double ceilingSeconds = std::numeric_limits<double>::quiet_NaN();
    /// @brief Against RayCastAction (shaded per sample for a shaded method).
    double referenceRmse = std::numeric_limits<double>::quiet_NaN();
    double referencePsnr = std::numeric_limits<double>::quiet_NaN(); ///< dB
    /// @brief Against the full-quality image (NaN for a shaded method: it shows other colours).
    double fullRmse = std::numeric_limits<double>::quiet_NaN();
    double fullPsnr = std::numeric_limits<double>::quiet_NaN(); ///< dB

    /// @brief Median draw time (RenderPhase::Draw: both passes until glFinish).
    double drawSeconds() const {
        return phaseSeconds[static_cast<std::size_t>(sg::RenderPhase::Draw)];
    }

    /// Frame time over the ceiling's time, the framework's whole overhead (1 is ideal): the
    /// median over the repetitions of each frame's time over the ceiling draw timed right after
    /// it, so that load from other processes on a shared machine hits both alike.
    double frameRatio = std::numeric_limits<double>::quiet_NaN();
    /// Draw time (RenderPhase::Draw) over the ceiling's time, paired the same way: the overhead
    /// of the splat shading alone.
    double drawRatio = std::numeric_limits<double>::quiet_NaN();
    /// Frame time over the full-quality texture splats' frame time in the same run (NaN when
    /// the run has no full-quality method): what a method costs against the paper's texture
    /// splats, e.g. vector splats (the paper paid +50 %), or shading (`texture+shade`).
    double fullFrameRatio = std::numeric_limits<double>::quiet_NaN();
    /// Frame time over the same method's frame time on GL in the same run (1 for GL itself,
    /// NaN without a GL row): the CPU backend's speed-up is its inverse.
    double glFrameRatio = std::numeric_limits<double>::quiet_NaN();
};

} // namespace texsplat::bench
