#pragma once

#include "nodes/render/cpu/ColorPlanes.h"
#include "nodes/render/cpu/FootprintStamps.h"
#include "nodes/render/cpu/SplatRaster.h"

#include <cstddef>

namespace texsplat::microbench {

/// @brief The floor under the CPU backend's stamped loop (issue 11): every 8-lane row vector,
/// on the cache-line boundaries render::cpu::compositeSplats() uses, of the pixel boxes of
/// `splats` (stamped, set up, in order), composited into `planes` with the least a back-to-front
/// "over" does per vector: the footprint from one stamp (the splat's phase, not the blend of
/// four), x = τ·f, 1 − e^(−x) by four multiply-adds of its series, and the over of the four
/// colour planes (four loads, four multiply-adds, four stores). What the real loop spends beyond
/// it (three more stamp loads and the blend, the colour weight, the clamps and depth test, the
/// choices per splat) a faster loop could still save; the vectors themselves are what the layout
/// costs. Not an image anyone should look at (the colour weight is left out).
void compositeFloor(const render::cpu::SplatRaster* splats, std::size_t count,
                    const render::cpu::FootprintStamps& stamps,
                    render::cpu::ColorPlanes& planes);

} // namespace texsplat::microbench
