#include "octree/SliceOrder.h"

#include "OctreeTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <limits>
#include <vector>

using texsplat::octree::ClassifiedGrid;
using texsplat::octree::SliceOrder;
using texsplat::octree::View;
using texsplat::octree::test::Cell;
using texsplat::octree::test::checkVisibilityOrder;

namespace {

// The linear indices of the voxels SliceOrder visits, in its order.
std::vector<std::uint64_t> orderOf(const ClassifiedGrid& grid, const View& view) {
    std::vector<std::uint64_t> order;
    SliceOrder(grid, view).forEach([&](glm::u64vec3 voxel, ClassifiedGrid::StorageIndex stored) {
        EXPECT_EQ(grid.storedVoxel(stored), grid.voxel(voxel));
        order.push_back(grid.index(voxel));
    });
    return order;
}

// A grid whose every voxel is non-empty (so that every block is allocated).
ClassifiedGrid filledGrid(glm::u64vec3 dims, glm::dvec3 spacing, glm::dvec3 origin) {
    ClassifiedGrid grid(dims, spacing, origin);
    for (std::uint64_t k = 0; k < dims.z; ++k) {
        for (std::uint64_t j = 0; j < dims.y; ++j) {
            for (std::uint64_t i = 0; i < dims.x; ++i) {
                grid.setVoxel({i, j, k}, glm::vec3(1.0f), 1.0f);
            }
        }
    }
    return grid;
}

glm::dvec3 voxelPosition(const ClassifiedGrid& grid, std::uint64_t index) {
    const glm::u64vec3 dims = grid.dims();
    return grid.toWorld(glm::dvec3(index % dims.x, (index / dims.x) % dims.y,
                                   index / (dims.x * dims.y)));
}

void checkAgainstRays(const ClassifiedGrid& grid, const View& view) {
    std::vector<Cell> cells;
    const glm::dvec3 half = 0.5 * grid.spacing();
    for (const std::uint64_t index : orderOf(grid, view)) {
        const glm::dvec3 center = voxelPosition(grid, index);
        cells.push_back({center - half, center + half});
    }
    const glm::dvec3 low = grid.toWorld(glm::dvec3(-0.5));
    const glm::dvec3 high = grid.toWorld(glm::dvec3(grid.dims()) - 0.5);
    const auto check = checkVisibilityOrder(cells, view, low, high, 300, 23);
    EXPECT_EQ(check.violations, 0u);
    EXPECT_GT(check.orderedPairs, 300u);
}

} // namespace

TEST(SliceOrder, visitsEveryVoxelOnce) {
    for (const glm::u64vec3 dims :
         {glm::u64vec3(1), glm::u64vec3(1, 9, 9), glm::u64vec3(5, 7, 3)}) {
        const ClassifiedGrid grid = filledGrid(dims, glm::dvec3(1.0), glm::dvec3(0.0));
        for (const View& view : {View::orthographic({0.3, -1.0, 0.2}),
                                 View::perspective({2.2, 3.1, 1.4}, {0.0, 0.0, 1.0})}) {
            std::vector<std::uint64_t> order = orderOf(grid, view);
            std::sort(order.begin(), order.end());
            ASSERT_EQ(order.size(), grid.voxelCount());
            for (std::uint64_t index = 0; index < order.size(); ++index) {
                EXPECT_EQ(order[index], index);
            }
        }
    }
}

TEST(SliceOrder, slicesAlongTheAxisMostParallelToTheView) {
    const ClassifiedGrid grid = filledGrid({5, 7, 3}, glm::dvec3(1.0), glm::dvec3(0.0));
    EXPECT_EQ(SliceOrder(grid, View::orthographic({0.9, -0.5, 0.2})).sliceAxis(), 0);
    EXPECT_EQ(SliceOrder(grid, View::orthographic({0.1, -0.5, 0.2})).sliceAxis(), 1);
    EXPECT_EQ(SliceOrder(grid, View::perspective({9.0, 9.0, 9.0}, {0.1, 0.5, -0.7})).sliceAxis(),
              2);
}

TEST(SliceOrder, axisViewsAreSortedByCentreDepth) {
    const ClassifiedGrid grid = filledGrid({5, 7, 3}, {1.0, 0.5, 2.0}, {1.0, -2.0, 0.0});
    for (int axis = 0; axis < 3; ++axis) {
        for (const double sign : {1.0, -1.0}) {
            glm::dvec3 direction(0.0);
            direction[axis] = sign;
            const View view = View::orthographic(direction);
            double previous = std::numeric_limits<double>::infinity();
            for (const std::uint64_t index : orderOf(grid, view)) {
                const double depth = view.depth(voxelPosition(grid, index));
                EXPECT_LE(depth, previous);
                previous = depth;
            }
        }
    }
}

TEST(SliceOrder, isBackToFrontForObliqueOrthographicViews) {
    const ClassifiedGrid grid = filledGrid({9, 8, 7}, {1.0, 1.5, 0.75}, glm::dvec3(0.0));
    for (const glm::dvec3 direction :
         {glm::dvec3(1.0, 1.0, 1.0), glm::dvec3(-1.0, 0.3, 0.6), glm::dvec3(0.2, -1.0, -0.9)}) {
        checkAgainstRays(grid, View::orthographic(direction));
    }
}

TEST(SliceOrder, isBackToFrontForPerspectiveEyesOutsideAndInside) {
    const ClassifiedGrid grid = filledGrid({9, 8, 7}, {1.0, 1.5, 0.75}, glm::dvec3(0.0));
    for (const View& view : {View::perspective({30.0, -10.0, 12.0}, {-1.0, 0.5, -0.3}),
                             View::perspective({4.0, 5.0, -20.0}, {0.0, 0.0, 1.0}),
                             View::perspective({4.2, 5.1, 2.4}, {0.2, 1.0, 0.1}),
                             View::perspective({0.1, 9.9, 4.6}, {1.0, -0.2, 0.0})}) {
        checkAgainstRays(grid, view);
    }
}

TEST(SliceOrder, walksFromBothEndsTowardAnEyeInside) {
    const ClassifiedGrid grid = filledGrid({6, 1, 1}, {2.0, 1.0, 1.0}, glm::dvec3(0.0));
    const SliceOrder order(grid, View::perspective({4.4, 0.0, 0.0}, {1.0, 0.0, 0.0}));
    EXPECT_EQ(order.axisOrder(0), (std::vector<std::uint64_t>{0, 1, 5, 4, 3, 2}));
    const SliceOrder outside(grid, View::perspective({-3.0, 0.0, 0.0}, {1.0, 0.0, 0.0}));
    EXPECT_EQ(outside.axisOrder(0), (std::vector<std::uint64_t>{5, 4, 3, 2, 1, 0}));
    const SliceOrder beyond(grid, View::perspective({30.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}));
    EXPECT_EQ(beyond.axisOrder(0), (std::vector<std::uint64_t>{0, 1, 2, 3, 4, 5}));
}

TEST(SliceOrder, walksOnlyAllocatedBlocksInTheOrderOfTheWholeBox) {
    const glm::u64vec3 dims(20, 17, 19);
    ClassifiedGrid sparse(dims, {1.0, 1.5, 0.75}, glm::dvec3(0.0));
    // Every other block, plus single voxels, so that rows mix allocated and missing blocks.
    for (std::uint64_t k = 0; k < dims.z; ++k) {
        for (std::uint64_t j = 0; j < dims.y; ++j) {
            for (std::uint64_t i = 0; i < dims.x; ++i) {
                if ((i / 8 + j / 8 + k / 8) % 2 == 0 || (i * 7 + j * 3 + k) % 29 == 0) {
                    sparse.setVoxel({i, j, k}, glm::vec3(0.5f), 1.0f);
                }
            }
        }
    }
    ASSERT_LT(sparse.blockCount(), ClassifiedGrid::boxBlockCount(dims));
    const ClassifiedGrid dense = filledGrid(dims, sparse.spacing(), sparse.origin());
    for (const View& view : {View::orthographic({0.3, -1.0, 0.2}),
                             View::orthographic({-0.9, 0.1, 0.4}),
                             View::perspective({9.5, 3.1, 40.0}, {0.0, 0.0, -1.0}),
                             View::perspective({9.5, 30.0, 7.0}, {0.1, -1.0, 0.0})}) {
        const auto nonEmpty = [&](const std::vector<std::uint64_t>& order) {
            std::vector<std::uint64_t> kept;
            std::copy_if(order.begin(), order.end(), std::back_inserter(kept),
                         [&](std::uint64_t index) { return !sparse.isEmptyVoxel(sparse.coordinates(index)); });
            return kept;
        };
        const std::vector<std::uint64_t> walked = orderOf(sparse, view);
        EXPECT_LE(walked.size(), sparse.blockCount() * ClassifiedGrid::kBlockVoxels);
        EXPECT_EQ(nonEmpty(walked), nonEmpty(orderOf(dense, view)));
    }
}

TEST(SliceOrder, leavesOutTheBlocksOutOfTheViewsSightAndKeepsTheOrderOfTheRest) {
    const glm::u64vec3 dims(40, 24, 20);
    const ClassifiedGrid grid = filledGrid(dims, glm::dvec3(1.0), glm::dvec3(0.0));
    const View plain = View::perspective({19.5, 11.5, 60.0}, {0.0, 0.0, -1.0});
    // Sight: x <= 12 (cells from -0.5), splats reaching one voxel beyond their cells.
    const View::Sides sides{glm::dvec4(1.0, 0.0, 0.0, 1000.0), glm::dvec4(-1.0, 0.0, 0.0, 12.0),
                            glm::dvec4(0.0, 1.0, 0.0, 1000.0), glm::dvec4(0.0, -1.0, 0.0, 1000.0)};
    const View sighted = plain.seeingOnly(sides, 1.0);
    const std::vector<std::uint64_t> all = orderOf(grid, plain);
    std::vector<std::uint64_t> inSight;
    std::copy_if(all.begin(), all.end(), std::back_inserter(inSight), [&](std::uint64_t index) {
        // The blocks of x < 16 hold a voxel whose splat reaches x = 12: those of x < 8 and 8..15.
        return grid.coordinates(index).x < 16;
    });
    EXPECT_EQ(orderOf(grid, sighted), inSight);
}
