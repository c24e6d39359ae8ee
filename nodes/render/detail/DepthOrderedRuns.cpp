#include "nodes/render/detail/DepthOrderedRuns.h"

#include "nodes/render/Frame.h"
#include "octree/Splat.h"
#include "scenegraph/actions/RenderStatistics.h"
#include "scenegraph/actions/Seconds.h"

namespace texsplat::render::detail {

std::vector<SplatRun> frameRuns(const Frame& frame, sg::RenderStatistics& statistics) {
    if (frame.splats.size() == 1) {
        return {{0, 0, frame.splats.front().splatCount()}};
    }
    const sg::TimingClock::time_point start = sg::TimingClock::now();
    std::vector<std::vector<float>> depths;
    depths.reserve(frame.splats.size());
    for (const FrameSplats& splats : frame.splats) {
        depths.push_back(splats.cameraDepths());
    }
    std::vector<SplatRun> runs = depthOrderedRuns(depths);
    statistics.addTime(sg::RenderPhase::Order, sg::secondsSince(start));
    return runs;
}

std::vector<SplatRun> depthOrderedRuns(const std::vector<std::vector<float>>& depths) {
    const std::size_t batches = depths.size();
    std::vector<std::size_t> next(batches, 0);
    std::vector<SplatRun> runs;
    // Whether splat `i` of batch `b` goes before the next splat of batch `other`.
    const auto isBefore = [&](std::size_t b, std::size_t i, std::size_t other) {
        const float here = depths[b][i];
        const float there = depths[other][next[other]];
        return here > there || (here == there && b < other);
    };
    for (;;) {
        std::size_t best = batches;
        for (std::size_t b = 0; b < batches; ++b) {
            if (next[b] < depths[b].size() && (best == batches || isBefore(b, next[b], best))) {
                best = b;
            }
        }
        if (best == batches) {
            return runs;
        }
        SplatRun run{best, next[best], next[best] + 1};
        const auto continues = [&](std::size_t i) {
            for (std::size_t other = 0; other < batches; ++other) {
                if (other != best && next[other] < depths[other].size() &&
                    !isBefore(best, i, other)) {
                    return false;
                }
            }
            return true;
        };
        while (run.end < depths[best].size() && continues(run.end)) {
            ++run.end;
        }
        next[best] = run.end;
        runs.push_back(run);
    }
}

} // namespace texsplat::render::detail
