#pragma once

#include "nodes/render/cpu/ColorPlanes.h"
#include "nodes/render/cpu/SplatRaster.h"

#include <cstddef>
#include <cstdint>

namespace texsplat::render::cpu {

struct FollowingMarks;

/// @brief The rows [begin, end) of the image a set-up splat may cover (empty when it covers no
/// pixel), kept apart from its SplatRaster: a band of rows scans these, 8 bytes a splat, to
/// find the splats that reach it, instead of the rasters, about 110.
struct RowSpan {
    std::int32_t begin = 0;
    std::int32_t end = 0;
};

/// @brief The rows `splat` may cover.
inline RowSpan rowSpanOf(const SplatRaster& splat) {
    return splat.isEmpty() ? RowSpan{} : RowSpan{splat.rowBegin, splat.rowEnd};
}

/// @brief Composites `count` set-up splats (`rows[i]` the rows of `splats[i]`), in their order (back to front), with premultiplied
/// "over" into rows [rowBegin, rowEnd) of `planes`; the rest of each splat is left to the call
/// that owns those rows. Per pixel, as the GL backend's splat pass: a pixel whose centre lies on
/// the splat's square (and in front of the depth plane's opaque surface, between the near and
/// far planes) gets footprint f = sampler(a, b)·lengthScale, α = 1 − e^(−τf) and colour
/// C·f·φ(τf) = C·α/τ, φ(x) = (1 − e^(−x))/x (C·f for τ below 1e-30), then
/// dst = src + (1 − α)·dst, clamped to FLT_MAX.
///
/// SIMD over adjacent pixels of a row through Highway, dispatched at run time to the best
/// instruction set of the CPU (AVX-512, AVX2, SSE4 …); 1 − e^(−x) is Highway's Expm1 (a few
/// ulp). A pixel's arithmetic does not depend on the row range or on which lane holds it, so
/// the image is the same for any split of the rows among threads.
///
/// Splats set up as stamped (SplatRaster::kStamped, orthographic views) take their footprint
/// from `stamps`, the SplatSetup's FootprintStamps, instead of the sampler.
///
/// With `marks` (combined splats), each splat is followed by its marks, composited as
/// compositeMarks() does, before the next splat.
void compositeSplats(const SplatRaster* splats, const RowSpan* rows, std::size_t count,
                     const FootprintSampler* sampler, const FootprintStamps* stamps,
                     const FollowingMarks* marks, ColorPlanes& planes, int rowBegin, int rowEnd);

/// @brief The instruction set compositeSplats() runs with on this CPU ("AVX2", "AVX3" …).
const char* compositeTarget();

} // namespace texsplat::render::cpu
