#include "octree/SliceOrder.h"

#include "OctreeTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <vector>

using texsplat::octree::ClassifiedGrid;
using texsplat::octree::SliceOrder;
using texsplat::octree::View;
using texsplat::octree::test::Cell;
using texsplat::octree::test::checkVisibilityOrder;

namespace {

std::vector<std::uint64_t> orderOf(const ClassifiedGrid& grid, const View& view) {
    std::vector<std::uint64_t> order;
    SliceOrder(grid, view).forEach(
        [&](std::uint64_t index, glm::u64vec3 voxel) {
            EXPECT_EQ(grid.index(voxel), index);
            order.push_back(index);
        });
    return order;
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
        const ClassifiedGrid grid(dims, glm::dvec3(1.0), glm::dvec3(0.0));
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
    const ClassifiedGrid grid({5, 7, 3}, glm::dvec3(1.0), glm::dvec3(0.0));
    EXPECT_EQ(SliceOrder(grid, View::orthographic({0.9, -0.5, 0.2})).sliceAxis(), 0);
    EXPECT_EQ(SliceOrder(grid, View::orthographic({0.1, -0.5, 0.2})).sliceAxis(), 1);
    EXPECT_EQ(SliceOrder(grid, View::perspective({9.0, 9.0, 9.0}, {0.1, 0.5, -0.7})).sliceAxis(),
              2);
}

TEST(SliceOrder, axisViewsAreSortedByCentreDepth) {
    const ClassifiedGrid grid({5, 7, 3}, {1.0, 0.5, 2.0}, {1.0, -2.0, 0.0});
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
    const ClassifiedGrid grid({9, 8, 7}, {1.0, 1.5, 0.75}, glm::dvec3(0.0));
    for (const glm::dvec3 direction :
         {glm::dvec3(1.0, 1.0, 1.0), glm::dvec3(-1.0, 0.3, 0.6), glm::dvec3(0.2, -1.0, -0.9)}) {
        checkAgainstRays(grid, View::orthographic(direction));
    }
}

TEST(SliceOrder, isBackToFrontForPerspectiveEyesOutsideAndInside) {
    const ClassifiedGrid grid({9, 8, 7}, {1.0, 1.5, 0.75}, glm::dvec3(0.0));
    for (const View& view : {View::perspective({30.0, -10.0, 12.0}, {-1.0, 0.5, -0.3}),
                             View::perspective({4.0, 5.0, -20.0}, {0.0, 0.0, 1.0}),
                             View::perspective({4.2, 5.1, 2.4}, {0.2, 1.0, 0.1}),
                             View::perspective({0.1, 9.9, 4.6}, {1.0, -0.2, 0.0})}) {
        checkAgainstRays(grid, view);
    }
}

TEST(SliceOrder, walksFromBothEndsTowardAnEyeInside) {
    const ClassifiedGrid grid({6, 1, 1}, {2.0, 1.0, 1.0}, glm::dvec3(0.0));
    const SliceOrder order(grid, View::perspective({4.4, 0.0, 0.0}, {1.0, 0.0, 0.0}));
    EXPECT_EQ(order.axisOrder(0), (std::vector<std::uint64_t>{0, 1, 5, 4, 3, 2}));
    const SliceOrder outside(grid, View::perspective({-3.0, 0.0, 0.0}, {1.0, 0.0, 0.0}));
    EXPECT_EQ(outside.axisOrder(0), (std::vector<std::uint64_t>{5, 4, 3, 2, 1, 0}));
    const SliceOrder beyond(grid, View::perspective({30.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}));
    EXPECT_EQ(beyond.axisOrder(0), (std::vector<std::uint64_t>{0, 1, 2, 3, 4, 5}));
}
