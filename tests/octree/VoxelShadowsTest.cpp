#include "octree/VoxelShadows.h"

#include "octree/ClassifiedGrid.h"

#include <gtest/gtest.h>

#include <cmath>

namespace texsplat::octree {
namespace {

// A grid of `dims` with spacing `spacing` whose voxels `isFilled(i, j, k)` are not empty.
template <class IsFilled>
ClassifiedGrid filledGrid(glm::u64vec3 dims, IsFilled isFilled,
                          glm::dvec3 spacing = glm::dvec3(1.0)) {
    ClassifiedGrid grid(dims, spacing, glm::dvec3(0.0));
    for (std::uint64_t k = 0; k < dims.z; ++k) {
        for (std::uint64_t j = 0; j < dims.y; ++j) {
            for (std::uint64_t i = 0; i < dims.x; ++i) {
                if (isFilled(i, j, k)) {
                    grid.setVoxel({i, j, k}, glm::vec3(0.1f), 1.0f);
                }
            }
        }
    }
    return grid;
}

TEST(VoxelShadows, aFullBoxIsAsDeepAsItsEdgeAlongEachAxis) {
    const VoxelShadows shadows(filledGrid({12, 20, 30}, [](auto, auto, auto) { return true; }));
    EXPECT_EQ(shadows.voxels(), 12u * 20u * 30u);
    EXPECT_EQ(shadows.columns(0), 20u * 30u);
    EXPECT_EQ(shadows.columns(1), 12u * 30u);
    EXPECT_EQ(shadows.columns(2), 12u * 20u);
    EXPECT_DOUBLE_EQ(shadows.meanDepth({1.0, 0.0, 0.0}), 12.0);
    EXPECT_DOUBLE_EQ(shadows.meanDepth({0.0, -3.0, 0.0}), 20.0);
    EXPECT_DOUBLE_EQ(shadows.meanDepth({0.0, 0.0, 2.0}), 30.0);
    // Along a diagonal the shadow is the sum of the faces' projections: V / A.
    const double n = 1.0 / std::sqrt(3.0);
    EXPECT_NEAR(shadows.meanDepth({1.0, 1.0, -1.0}), 7200.0 / (n * 600.0 + n * 360.0 + n * 240.0),
                1e-9);
    EXPECT_EQ(shadows.meanDepth({0.0, 0.0, 0.0}), 0.0);
}

TEST(VoxelShadows, sparseDataIsAsDeepAsItsOwnVoxelsNotTheBox) {
    // A column of 8 voxels along z in a 32³ box, and blocks of the box with nothing in them.
    const VoxelShadows column(
        filledGrid({32, 32, 32}, [](std::uint64_t i, std::uint64_t j, std::uint64_t k) {
            return i == 17 && j == 9 && k >= 10 && k < 18;
        }));
    EXPECT_DOUBLE_EQ(column.meanDepth({0.0, 0.0, 1.0}), 8.0);
    EXPECT_DOUBLE_EQ(column.meanDepth({1.0, 0.0, 0.0}), 1.0);
    const VoxelShadows empty(filledGrid({9, 9, 9}, [](auto, auto, auto) { return false; }));
    EXPECT_EQ(empty.meanDepth({0.0, 0.0, 1.0}), 0.0);
}

TEST(VoxelShadows, anisotropicVoxelsCountInVoxelsOfTheirMeanSize) {
    // Voxels 2 x 1 x 4 long: h = 2, a voxel's area h² = 4. Seen along z, a 10³ box's shadow is
    // 100 faces of 2 x 1: 10³ · 4 / 200 = 20 of the mean voxels deep (40 world units, 2 per h).
    const VoxelShadows shadows(
        filledGrid({10, 10, 10}, [](auto, auto, auto) { return true; }, {2.0, 1.0, 4.0}));
    EXPECT_NEAR(shadows.meanDepth({0.0, 0.0, 1.0}), 20.0, 1e-12);
    EXPECT_NEAR(shadows.meanDepth({1.0, 0.0, 0.0}), 1000.0 * 4.0 / (100.0 * 4.0), 1e-12);
}

TEST(VoxelShadows, voxelsOfBlocksClippedByTheGridsFacesAreNotCounted) {
    // 10 is not a multiple of the blocks' 8: the second blocks are clipped.
    const VoxelShadows shadows(filledGrid({10, 3, 9}, [](auto, auto, auto) { return true; }));
    EXPECT_EQ(shadows.voxels(), 270u);
    EXPECT_EQ(shadows.columns(2), 30u);
}

} // namespace
} // namespace texsplat::octree
