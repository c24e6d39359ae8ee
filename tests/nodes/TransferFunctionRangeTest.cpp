// TransferFunction's range from the data (rangeMode, percentiles) and its opacity unit
// (unitDistance).

#include "nodes/TransferFunction.h"

#include "SceneNodesTestSupport.h"
#include "nodes/volume/DenseGrid.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <memory>

namespace texsplat::nodes {
namespace {

using test::errorOf;
using volume::DenseScalarGrid;
using volume::GridGeometry;

// A signed-distance-like ramp: `count` voxels along x from `low` to `high`.
std::unique_ptr<DenseScalarGrid> ramp(int count, float low, float high, double spacing = 1.0) {
    auto grid = std::make_unique<DenseScalarGrid>(
        GridGeometry({count, 1, 1}, glm::dvec3(0.0), glm::dvec3(spacing)));
    for (int i = 0; i < count; ++i) {
        grid->setValue({i, 0, 0}, low + (high - low) * float(i) / float(count - 1));
    }
    return grid;
}

int transparentVoxels(const TransferFunction& tf, const DenseScalarGrid& grid) {
    const auto classified = tf.classify(grid);
    int count = 0;
    for (std::int64_t i = 0; i < grid.geometry().dims().x; ++i) {
        count += classified->isEmptyVoxel(glm::u64vec3(std::uint64_t(i), 0, 0)) ? 1 : 0;
    }
    return count;
}

TEST(TransferFunctionRange, aNewTransferFunctionFitsTheData) {
    const auto distance = ramp(101, -0.15f, 0.15f);
    const auto tf = TransferFunction::create();
    EXPECT_EQ(tf->dataScale(*distance).range, glm::vec2(-0.15f, 0.15f));
    // Only the smallest value maps to t = 0 and zero opacity.
    EXPECT_EQ(transparentVoxels(*tf, *distance), 1);
    EXPECT_FLOAT_EQ(tf->classify(0.0f, tf->dataScale(*distance)).extinction, 0.5f);
}

TEST(TransferFunctionRange, aWrittenRangeIsKept) {
    const auto distance = ramp(101, -0.15f, 0.15f);
    const auto tf = TransferFunction::create();
    tf->range = glm::vec2(0.0f, 1.0f);
    EXPECT_EQ(tf->dataScale(*distance).range, glm::vec2(0.0f, 1.0f));
    // The old default: the negative half (and zero) clamped to t = 0.
    EXPECT_EQ(transparentVoxels(*tf, *distance), 51);
}

TEST(TransferFunctionRange, aConnectedRangeIsKept) {
    const auto distance = ramp(101, -0.15f, 0.15f);
    const auto source = TransferFunction::create();
    source->range = glm::vec2(-1.0f, 1.0f);
    const auto tf = TransferFunction::create();
    tf->range.connectFrom(source->range);
    EXPECT_EQ(tf->dataScale(*distance).range, glm::vec2(-1.0f, 1.0f));
}

TEST(TransferFunctionRange, modesOverrideWhetherRangeWasWritten) {
    const auto grid = ramp(11, 2.0f, 4.0f);
    const auto tf = TransferFunction::create();
    tf->rangeMode.setValue(RangeMode::Fixed);
    EXPECT_EQ(tf->dataScale(*grid).range, glm::vec2(0.0f, 1.0f));
    tf->range = glm::vec2(-1.0f, 1.0f);
    tf->rangeMode.setValue(RangeMode::Data);
    EXPECT_EQ(tf->dataScale(*grid).range, glm::vec2(2.0f, 4.0f));
    // The fields as written, for callers without data.
    EXPECT_FLOAT_EQ(tf->classify(0.0f).extinction, 0.5f);
}

TEST(TransferFunctionRange, percentilesIgnoreOutliers) {
    DenseScalarGrid grid(GridGeometry({1001, 1, 1}));
    for (int i = 0; i < 1000; ++i) {
        grid.setValue({i, 0, 0}, float(i) / 10.0f); // 0 .. 99.9
    }
    grid.setValue({1000, 0, 0}, 1.0e6f);
    const auto tf = TransferFunction::create();
    tf->rangeMode.setValue(RangeMode::Data);
    EXPECT_EQ(tf->dataScale(grid).range, glm::vec2(0.0f, 1.0e6f));
    tf->rangeMode.setValue(RangeMode::Percentile);
    tf->percentiles = glm::vec2(1.0f, 99.0f);
    const glm::vec2 range = tf->dataScale(grid).range;
    // One histogram bin is 1e6 / 65536 ≈ 15 wide: the outlier's span, not the data's, sets it.
    EXPECT_NEAR(range.x, 1.0f, 16.0f);
    EXPECT_NEAR(range.y, 99.0f, 16.0f);
    EXPECT_LT(range.y, 200.0f);
}

TEST(TransferFunctionRange, percentilesOfEvenlySpreadValues) {
    const auto grid = ramp(10001, 0.0f, 100.0f);
    const auto tf = TransferFunction::create();
    tf->rangeMode.setValue(RangeMode::Percentile);
    tf->percentiles = glm::vec2(5.0f, 95.0f);
    const glm::vec2 range = tf->dataScale(*grid).range;
    EXPECT_NEAR(range.x, 5.0f, 0.01f);
    EXPECT_NEAR(range.y, 95.0f, 0.01f);
}

TEST(TransferFunctionRange, oneValueGetsAUnitWideRange) {
    DenseScalarGrid grid(GridGeometry({4, 4, 4}), 3.0f);
    const auto tf = TransferFunction::create();
    EXPECT_EQ(tf->dataScale(grid).range, glm::vec2(2.5f, 3.5f));
    tf->rangeMode.setValue(RangeMode::Percentile);
    EXPECT_EQ(tf->dataScale(grid).range, glm::vec2(2.5f, 3.5f));
}

TEST(TransferFunctionRange, vectorDataUsesItsMagnitudes) {
    volume::DenseVectorGrid grid(GridGeometry({2, 1, 1}));
    grid.setValue({0, 0, 0}, glm::vec3(3.0f, 4.0f, 0.0f));
    grid.setValue({1, 0, 0}, glm::vec3(0.0f, 0.0f, -10.0f));
    EXPECT_EQ(TransferFunction::create()->dataScale(grid).range, glm::vec2(5.0f, 10.0f));
}

TEST(TransferFunctionRange, unitDistanceZeroIsOneVoxel) {
    const auto fine = ramp(3, 0.0f, 1.0f, 0.25);
    const auto tf = TransferFunction::create();
    tf->emission = 1.0f;
    EXPECT_FLOAT_EQ(tf->dataScale(*fine).unitDistance, 1.0f);
    tf->unitDistance = 0.0f;
    const DataScale scale = tf->dataScale(*fine);
    EXPECT_FLOAT_EQ(scale.unitDistance, 0.25f);
    // Extinction and emission both per voxel length: four times as much per world unit.
    const Classification top = tf->classify(1.0f, scale);
    EXPECT_FLOAT_EQ(top.extinction, 4.0f);
    EXPECT_FLOAT_EQ(top.color.r, 8.0f);
    const auto classified = tf->classify(*fine);
    EXPECT_EQ(classified->voxel(glm::u64vec3(2, 0, 0)), glm::vec4(8.0f, 8.0f, 8.0f, 4.0f));
    // Anisotropic voxels: the geometric mean of the spacing.
    DenseScalarGrid flat(GridGeometry({1, 1, 1}, glm::dvec3(0.0), glm::dvec3(0.5, 1.0, 2.0)));
    EXPECT_FLOAT_EQ(tf->dataScale(flat).unitDistance, 1.0f);
    // Without data there is no voxel: one world unit.
    EXPECT_FLOAT_EQ(tf->classify(1.0f).extinction, 1.0f);
}

TEST(TransferFunctionRange, aWorldUnitDistanceDividesTheOpacities) {
    const auto tf = TransferFunction::create();
    tf->unitDistance = 0.5f;
    EXPECT_FLOAT_EQ(tf->classify(1.0f).extinction, 2.0f);
}

TEST(TransferFunctionRange, badFieldsAreNamed) {
    const auto tf = TransferFunction::create();
    tf->percentiles = glm::vec2(50.0f, 10.0f);
    EXPECT_EQ(errorOf<DataError>([&] { tf->validate(); }),
              "TransferFunction: percentiles must satisfy 0 <= percentiles[0] < percentiles[1] "
              "<= 100, got 50 10");
    tf->percentiles = glm::vec2(0.0f, 100.0f);
    tf->unitDistance = -1.0f;
    EXPECT_EQ(errorOf<DataError>([&] { tf->validate(); }),
              "TransferFunction: unitDistance must be finite and >= 0 (0: one voxel), got -1");
}

} // namespace
} // namespace texsplat::nodes
