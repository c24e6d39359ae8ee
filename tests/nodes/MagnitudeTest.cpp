#include "nodes/volume/Magnitude.h"

#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/SparseGrid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace texsplat::volume {
namespace {

TEST(Magnitude, denseVectorsGiveDenseMagnitudes) {
    DenseVectorGrid vectors(GridGeometry({3, 1, 1}, glm::dvec3(1.0), glm::dvec3(0.5)));
    vectors.setValue({0, 0, 0}, {3.0f, 4.0f, 0.0f});
    vectors.setValue({1, 0, 0}, {0.0f, std::numeric_limits<float>::quiet_NaN(), 0.0f});
    const float huge = std::numeric_limits<float>::max();
    vectors.setValue({2, 0, 0}, {huge, huge, 0.0f});
    const ScalarGridPtr magnitude = magnitudeGrid(vectors);
    ASSERT_NE(dynamic_cast<const DenseScalarGrid*>(magnitude.get()), nullptr);
    EXPECT_EQ(magnitude->geometry(), vectors.geometry());
    EXPECT_EQ(magnitude->value({0, 0, 0}), 5.0f);
    EXPECT_FALSE(magnitude->isActive({1, 0, 0})) << "an empty vector gives an empty magnitude";
    EXPECT_EQ(magnitude->value({2, 0, 0}), huge) << "finite vectors stay finite";
    EXPECT_EQ(magnitude->statistics().nonFiniteCount, 1);
}

TEST(Magnitude, sparseVectorsStaySparse) {
    SparseVectorGrid vectors(GridGeometry({1000, 1000, 1000}), glm::vec3(0.0f, 0.0f, 2.0f),
                             {1, 2, 3});
    vectors.setValue({999, 0, 500}, {0.0f, 6.0f, 8.0f});
    const ScalarGridPtr magnitude = magnitudeGrid(vectors);
    const auto* sparse = dynamic_cast<const SparseScalarGrid*>(magnitude.get());
    ASSERT_NE(sparse, nullptr);
    EXPECT_EQ(sparse->activeVoxelCount(), 1);
    EXPECT_EQ(sparse->blockOffset(), glm::i64vec3(1, 2, 3));
    EXPECT_EQ(magnitude->value({999, 0, 500}), 10.0f);
    EXPECT_EQ(magnitude->value({0, 0, 0}), 2.0f) << "background is the background's magnitude";
}

} // namespace
} // namespace texsplat::volume
