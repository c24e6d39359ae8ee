#pragma once

#include <cstddef>
#include <vector>

namespace texsplat::sg {
struct RenderStatistics;
} // namespace texsplat::sg

namespace texsplat::render {
struct Frame;
} // namespace texsplat::render

namespace texsplat::render::detail {

/// A run of consecutive splats of one batch: splats [begin, end) of batch `batch`.
struct SplatRun {
    std::size_t batch = 0;
    std::size_t begin = 0;
    std::size_t end = 0;

    bool operator==(const SplatRun& other) const {
        return batch == other.batch && begin == other.begin && end == other.end;
    }
};

/// Interleaves several back-to-front splat batches into one back-to-front sequence of runs, for
/// the backends' splat passes (GlRenderer, cpu::CpuRenderer): `depths[b][i]` is the distance
/// from the eye of splat i of batch b (larger: farther). Each batch keeps its own order (its
/// splats are already ordered for the view, which is what makes "over" right inside one
/// volume); among the batches, the next splat drawn is always the farthest of their next splats
/// (a k-way merge), ties going to the batch that came first in the graph. Consecutive picks from
/// one batch form one run, so volumes that do not overlap in depth cost one run each, and volumes
/// that share space (the paper's figure 8: clouds and winds) interleave splat by splat.
/// O(splats × batches).
std::vector<SplatRun> depthOrderedRuns(const std::vector<std::vector<float>>& depths);

/// The runs both backends draw `frame`'s splat batches in: its only batch whole, or its batches
/// merged by depthOrderedRuns() over their camera depths (the time counting as
/// RenderPhase::Order in `statistics`); none without splat batches.
std::vector<SplatRun> frameRuns(const Frame& frame, sg::RenderStatistics& statistics);

} // namespace texsplat::render::detail
