#include "nodes/render/detail/DepthOrderedRuns.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace texsplat::render::detail {
namespace {

using Runs = std::vector<SplatRun>;

TEST(DepthOrderedRuns, oneBatchIsOneRun) {
    EXPECT_EQ(depthOrderedRuns({{3.0f, 2.0f, 1.0f}}), (Runs{{0, 0, 3}}));
    EXPECT_EQ(depthOrderedRuns({}), Runs{});
    EXPECT_EQ(depthOrderedRuns({{}, {}}), Runs{});
}

TEST(DepthOrderedRuns, batchesApartInDepthAreDrawnFarthestFirstWhateverTheirOrder) {
    // The near volume comes first in the graph; the far one is still drawn first.
    EXPECT_EQ(depthOrderedRuns({{2.0f, 1.0f}, {9.0f, 8.0f, 7.0f}}),
              (Runs{{1, 0, 3}, {0, 0, 2}}));
}

TEST(DepthOrderedRuns, batchesInTheSameSpaceInterleaveSplatBySplat) {
    EXPECT_EQ(depthOrderedRuns({{6.0f, 4.0f, 2.0f}, {5.0f, 3.0f, 1.0f}}),
              (Runs{{0, 0, 1}, {1, 0, 1}, {0, 1, 2}, {1, 1, 2}, {0, 2, 3}, {1, 2, 3}}));
}

TEST(DepthOrderedRuns, tiesGoToTheEarlierBatchAndEveryBatchKeepsItsOwnOrder) {
    EXPECT_EQ(depthOrderedRuns({{5.0f, 5.0f}, {5.0f}}), (Runs{{0, 0, 2}, {1, 0, 1}}));
    // A batch whose own order is not monotone in depth (an octree cut) is never reordered.
    const Runs runs = depthOrderedRuns({{4.0f, 6.0f, 1.0f}, {5.0f, 3.0f}});
    EXPECT_EQ(runs, (Runs{{1, 0, 1}, {0, 0, 2}, {1, 1, 2}, {0, 2, 3}}));
    std::size_t drawn = 0;
    for (const SplatRun& run : runs) {
        drawn += run.end - run.begin;
    }
    EXPECT_EQ(drawn, 5u);
}

} // namespace
} // namespace texsplat::render::detail
