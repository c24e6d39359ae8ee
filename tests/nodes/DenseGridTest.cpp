#include "nodes/volume/DenseGrid.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace texsplat::volume {
namespace {

TEST(DenseGrid, storesValuesAndVisitsTheNonEmptyOnes) {
    DenseScalarGrid grid(GridGeometry({3, 2, 2}), 1.0f);
    grid.setValue({2, 1, 1}, 7.0f);
    grid.setValue({0, 1, 0}, std::numeric_limits<float>::quiet_NaN());
    grid.setValue({1, 0, 1}, -std::numeric_limits<float>::infinity());
    EXPECT_EQ(grid.value({2, 1, 1}), 7.0f);
    EXPECT_EQ(grid.value({0, 1, 0}), 0.0f) << "an empty voxel reads as the background";
    EXPECT_FALSE(grid.isActive({0, 1, 0}));
    EXPECT_TRUE(grid.isActive({0, 0, 0}));

    std::vector<glm::i64vec3> visited;
    grid.forEachActive([&](const glm::i64vec3& index, const float& value) {
        visited.push_back(index);
        EXPECT_EQ(value, grid.value(index));
    });
    EXPECT_EQ(visited.size(), 10u);
    EXPECT_EQ(visited.front(), glm::i64vec3(0, 0, 0));
    EXPECT_EQ(visited.back(), glm::i64vec3(2, 1, 1));
    EXPECT_EQ(grid.memoryBytes(), 12 * sizeof(float));
}

TEST(DenseGrid, statisticsCountNonFiniteVoxels) {
    DenseScalarGrid grid(GridGeometry({4, 1, 1}));
    grid.values() = {-2.0f, std::numeric_limits<float>::quiet_NaN(), 5.0f,
                     std::numeric_limits<float>::infinity()};
    const GridStatistics statistics = grid.statistics();
    EXPECT_EQ(statistics.minimum, -2.0);
    EXPECT_EQ(statistics.maximum, 5.0);
    EXPECT_EQ(statistics.finiteCount, 2);
    EXPECT_EQ(statistics.nonFiniteCount, 2);
}

TEST(DenseGrid, vectorStatisticsMeasureMagnitudes) {
    DenseVectorGrid grid(GridGeometry({3, 1, 1}));
    grid.setValue({0, 0, 0}, {3.0f, 4.0f, 0.0f});
    grid.setValue({1, 0, 0}, {0.0f, 0.0f, 1.0f});
    grid.setValue({2, 0, 0}, {0.0f, std::numeric_limits<float>::quiet_NaN(), 0.0f});
    const GridStatistics statistics = grid.statistics();
    EXPECT_EQ(statistics.minimum, 1.0);
    EXPECT_EQ(statistics.maximum, 5.0);
    EXPECT_EQ(statistics.finiteCount, 2);
    EXPECT_EQ(statistics.nonFiniteCount, 1);
    EXPECT_EQ(grid.value({2, 0, 0}), glm::vec3(0.0f));
}

TEST(DenseGrid, emptyStatisticsAreZero) {
    DenseScalarGrid grid(GridGeometry({2, 1, 1}), std::numeric_limits<float>::quiet_NaN());
    const GridStatistics statistics = grid.statistics();
    EXPECT_EQ(statistics.minimum, 0.0);
    EXPECT_EQ(statistics.maximum, 0.0);
    EXPECT_EQ(statistics.finiteCount, 0);
    EXPECT_EQ(statistics.nonFiniteCount, 2);
}

} // namespace
} // namespace texsplat::volume
