#include "nodes/volume/Blob.h"

#include "nodes/volume/DenseGrid.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace texsplat::volume {
namespace {

const std::vector<float>& values(const ScalarGridPtr& grid) {
    return dynamic_cast<const DenseScalarGrid&>(*grid).values();
}

TEST(Blob, termsAreSeededAndInTheirRanges) {
    const std::vector<GaussianTerm> terms = blobTerms({{8, 8, 8}, 5, 42});
    ASSERT_EQ(terms.size(), 5u);
    for (const GaussianTerm& term : terms) {
        EXPECT_LE(glm::abs(term.center.x), 0.5);
        EXPECT_LE(glm::abs(term.center.y), 0.5);
        EXPECT_LE(glm::abs(term.center.z), 0.5);
        EXPECT_GE(term.sigma, 0.15);
        EXPECT_LT(term.sigma, 0.35);
        EXPECT_GE(term.amplitude, 0.5);
        EXPECT_LT(term.amplitude, 1.0);
    }
    EXPECT_EQ(blobTerms({{8, 8, 8}, 5, 42})[3].center, terms[3].center);
    EXPECT_NE(blobTerms({{8, 8, 8}, 5, 43})[3].center, terms[3].center);
}

TEST(Blob, valueIsTheSumOfGaussians) {
    const std::vector<GaussianTerm> terms = {{{0.0, 0.0, 0.0}, 0.5, 1.0},
                                             {{0.5, 0.0, 0.0}, 0.25, 2.0}};
    EXPECT_DOUBLE_EQ(blobValue({0.0, 0.0, 0.0}, terms), 1.0 + 2.0 * std::exp(-2.0));
    EXPECT_DOUBLE_EQ(blobValue({0.5, 0.0, 0.0}, terms), std::exp(-0.5) + 2.0);
}

TEST(Blob, gridSamplesTheFieldDeterministically) {
    const BlobParameters parameters{{17, 9, 5}, 3, 7};
    const ScalarGridPtr grid = generateBlob(parameters);
    EXPECT_EQ(grid->geometry(), GridGeometry({17, 9, 5}, glm::dvec3(-1.0), {0.125, 0.25, 0.5}));
    EXPECT_EQ(grid->value({8, 4, 2}), float(blobValue(glm::dvec3(0.0), blobTerms(parameters))));
    const GridStatistics statistics = grid->statistics();
    EXPECT_EQ(statistics.finiteCount, 17 * 9 * 5);
    EXPECT_GT(statistics.minimum, 0.0);
    EXPECT_EQ(values(generateBlob(parameters)), values(grid));
    EXPECT_NE(values(generateBlob({{17, 9, 5}, 3, 8})), values(grid));
}

TEST(Blob, rejectsBadParameters) {
    try {
        generateBlob({{8, 8, 8}, 0, 1});
        FAIL();
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "blob: term count must be at least 1, got 0");
    }
    try {
        generateBlob({{8, -8, 8}, 2, 1});
        FAIL();
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(),
                     "blob: grid dimensions must be at least 1 voxel each, got 8 x -8 x 8");
    }
}

} // namespace
} // namespace texsplat::volume
