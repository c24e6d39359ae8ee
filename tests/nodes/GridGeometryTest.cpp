#include "nodes/volume/GridGeometry.h"

#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace texsplat::volume {
namespace {

template <typename Function>
std::string dataErrorOf(Function function) {
    try {
        function();
    } catch (const DataError& error) {
        return error.what();
    }
    return "no DataError";
}

TEST(GridGeometry, transformsBetweenIndexAndWorld) {
    const GridGeometry geometry({4, 5, 6}, {1.0, 2.0, 3.0}, {0.5, 1.0, 2.0});
    EXPECT_EQ(geometry.voxelCount(), 120);
    EXPECT_EQ(geometry.indexToWorld({2.0, 3.0, 1.0}), glm::dvec3(2.0, 5.0, 5.0));
    EXPECT_EQ(geometry.worldToIndex({2.0, 5.0, 5.0}), glm::dvec3(2.0, 3.0, 1.0));
    EXPECT_EQ(geometry.nearestIndex({2.2, 5.4, 5.9}), glm::i64vec3(2, 3, 1));
    EXPECT_EQ(geometry.nearestIndex({2.3, 5.6, 6.1}), glm::i64vec3(3, 4, 2));
    EXPECT_EQ(geometry.boundsMin(), glm::dvec3(0.75, 1.5, 2.0));
    EXPECT_EQ(geometry.boundsMax(), glm::dvec3(2.75, 6.5, 14.0));
}

TEST(GridGeometry, linearIndexRoundTrips) {
    const GridGeometry geometry({4, 5, 6});
    EXPECT_EQ(geometry.linearIndex({1, 2, 3}), 1 + 4 * (2 + 5 * 3));
    for (std::int64_t linear = 0; linear < geometry.voxelCount(); ++linear)
        EXPECT_EQ(geometry.linearIndex(geometry.indexOf(linear)), linear);
    EXPECT_TRUE(geometry.contains({3, 4, 5}));
    EXPECT_FALSE(geometry.contains({4, 0, 0}));
    EXPECT_FALSE(geometry.contains({0, -1, 0}));
}

TEST(GridGeometry, indexArithmeticIsSixtyFourBitBeyondTwoToTheThirtyOne) {
    // 4096 x 4096 x 512 = 2^33 voxels: only index math, nothing is allocated.
    const GridGeometry geometry({4096, 4096, 512});
    EXPECT_EQ(geometry.voxelCount(), std::int64_t{1} << 33);
    const glm::i64vec3 last(4095, 4095, 511);
    EXPECT_EQ(geometry.linearIndex(last), (std::int64_t{1} << 33) - 1);
    EXPECT_EQ(geometry.indexOf((std::int64_t{1} << 33) - 1), last);
    const glm::i64vec3 middle(17, 4000, 300);
    EXPECT_EQ(geometry.linearIndex(middle), 17 + 4096 * (4000 + std::int64_t{4096} * 300));
    EXPECT_EQ(geometry.indexOf(geometry.linearIndex(middle)), middle);
    EXPECT_EQ(geometry.nearestIndex({4095.0, 4095.0, 511.0}), last);
}

TEST(GridGeometry, oneVoxelThickGridsHaveAVolume) {
    const GridGeometry geometry({1, 7, 1}, {0.0, 0.0, 0.0}, {2.0, 1.0, 3.0});
    EXPECT_EQ(geometry.voxelCount(), 7);
    EXPECT_EQ(geometry.boundsMin(), glm::dvec3(-1.0, -0.5, -1.5));
    EXPECT_EQ(geometry.boundsMax(), glm::dvec3(1.0, 6.5, 1.5));
}

TEST(GridGeometry, nearestIndexOfFarOrNanPositionsDoesNotOverflow) {
    const GridGeometry geometry({2, 2, 2});
    const glm::i64vec3 far = geometry.nearestIndex({1e300, -1e300, std::nan("")});
    EXPECT_EQ(far, glm::i64vec3(4000000000000000000, -4000000000000000000, 0));
    EXPECT_FALSE(geometry.contains(far));
}

TEST(GridGeometry, rejectsZeroSizeAndUnusableGeometry) {
    EXPECT_EQ(dataErrorOf([] { GridGeometry({0, 64, 64}); }),
              "grid dimensions must be at least 1 voxel each, got 0 x 64 x 64");
    EXPECT_EQ(dataErrorOf([] { GridGeometry({4, -2, 4}); }),
              "grid dimensions must be at least 1 voxel each, got 4 x -2 x 4");
    EXPECT_EQ(dataErrorOf([] { GridGeometry({std::int64_t{1} << 32, std::int64_t{1} << 32, 4}); }),
              "grid of 4294967296 x 4294967296 x 4 voxels has more voxels than a 64-bit index "
              "can address");
    EXPECT_EQ(dataErrorOf([] { GridGeometry({2, 2, 2}, glm::dvec3(0.0), {1.0, 0.0, 1.0}); }),
              "grid spacing must be finite and positive, got 1 0 1");
    const double infinity = std::numeric_limits<double>::infinity();
    EXPECT_EQ(dataErrorOf([&] { GridGeometry({2, 2, 2}, {infinity, 0.0, 0.5}); }),
              "grid origin must be finite, got inf 0 0.5");
}

} // namespace
} // namespace texsplat::volume
