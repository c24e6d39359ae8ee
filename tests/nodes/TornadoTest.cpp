#include "nodes/volume/Tornado.h"

#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/Magnitude.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace texsplat::volume {
namespace {

const DenseVectorGrid& dense(const VectorGridPtr& grid) {
    return dynamic_cast<const DenseVectorGrid&>(*grid);
}

// Values printed by Crawfis's original C gen_tornado (float arithmetic) for xs = ys = zs = 11.
struct Reference {
    int time;
    glm::i64vec3 index;
    glm::vec3 value;
};
constexpr Reference kReferences[] = {
    {0, {2, 7, 4}, {0.0297625288f, 0.0878710076f, 0.0f}},
    {0, {5, 5, 0}, {-0.198511153f, -0.0100000026f, 0.019851109f}},
    {0, {9, 1, 10}, {-0.0522741415f, -0.177613378f, 0.0f}},
    {25, {2, 7, 4}, {0.0276932679f, 0.0651264787f, 0.0f}},
    {25, {5, 5, 0}, {-0.131308794f, 0.134016156f, 0.01679595f}},
    {25, {9, 1, 10}, {-0.0322083123f, -0.1610751f, 0.0f}},
};

TEST(Tornado, matchesTheOriginalCodeAtKnownPoints) {
    for (const Reference& reference : kReferences) {
        const VectorGridPtr grid = generateTornado({{11, 11, 11}, double(reference.time)});
        const glm::vec3 value = grid->value(reference.index);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(value[c], reference.value[c], 1e-6)
                << "time " << reference.time << " component " << c;
        const glm::dvec3 position = glm::dvec3(reference.index) / 10.0;
        EXPECT_EQ(value, glm::vec3(tornadoVelocity(position, reference.time)));
    }
}

TEST(Tornado, samplesTheUnitCubeWithFiniteValues) {
    const VectorGridPtr grid = generateTornado({{64, 32, 16}, 3.0});
    EXPECT_EQ(grid->geometry(),
              GridGeometry({64, 32, 16}, glm::dvec3(0.0), {1.0 / 63, 1.0 / 31, 1.0 / 15}));
    const GridStatistics statistics = grid->statistics();
    EXPECT_EQ(statistics.finiteCount, 64 * 32 * 16);
    EXPECT_EQ(statistics.nonFiniteCount, 0);
    // The original's comment: "values range from 0.0 to around 0.4 (I think)".
    EXPECT_GT(statistics.maximum, 0.25);
    EXPECT_LT(statistics.maximum, 0.4);
}

TEST(Tornado, maximumMagnitudeMatchesTheOriginalAt64Cubed) {
    const VectorGridPtr grid = generateTornado({{64, 64, 64}, 0.0});
    EXPECT_NEAR(magnitudeGrid(*grid)->statistics().maximum, 0.313282, 2e-6);
}

TEST(Tornado, isDeterministicAndMovesWithTime) {
    const TornadoParameters parameters{{16, 16, 16}, 7.0};
    EXPECT_EQ(dense(generateTornado(parameters)).values(),
              dense(generateTornado(parameters)).values());
    EXPECT_NE(dense(generateTornado({{16, 16, 16}, 8.0})).values(),
              dense(generateTornado(parameters)).values());
}

TEST(Tornado, oneVoxelThickGridSamplesTheLowEnd) {
    const VectorGridPtr grid = generateTornado({{1, 5, 5}, 0.0});
    EXPECT_EQ(grid->geometry().spacing().x, 1.0);
    EXPECT_EQ(grid->value({0, 2, 3}), glm::vec3(tornadoVelocity({0.0, 0.5, 0.75}, 0.0)));
}

TEST(Tornado, rejectsBadParameters) {
    try {
        generateTornado({{0, 4, 4}, 0.0});
        FAIL();
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(),
                     "tornado: grid dimensions must be at least 1 voxel each, got 0 x 4 x 4");
    }
    try {
        generateTornado({{4, 4, 4}, std::numeric_limits<double>::quiet_NaN()});
        FAIL();
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "tornado: time must be finite, got nan");
    }
}

} // namespace
} // namespace texsplat::volume
