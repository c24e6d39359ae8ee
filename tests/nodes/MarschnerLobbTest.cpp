#include "nodes/volume/MarschnerLobb.h"

#include "nodes/volume/DenseGrid.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace texsplat::volume {
namespace {

TEST(MarschnerLobb, hasTheClosedFormValues) {
    // rho_r(0) = cos(2 pi f_M) = 1: rho(0,0,z) = (1 - sin(pi z / 2) + 2 alpha) / (2 (1 + alpha)).
    EXPECT_DOUBLE_EQ(marschnerLobb({0.0, 0.0, 0.0}, 6.0, 0.25), 0.6);
    EXPECT_DOUBLE_EQ(marschnerLobb({0.0, 0.0, 1.0}, 6.0, 0.25), 0.2);
    EXPECT_DOUBLE_EQ(marschnerLobb({0.0, 0.0, -1.0}, 6.0, 0.25), 1.0);
    // At r = 1, cos(pi r / 2) = 0, so rho_r = 1 again.
    EXPECT_NEAR(marschnerLobb({0.6, 0.8, 0.0}, 6.0, 0.25), 0.6, 1e-12);
    // At r = 2/3, cos(pi/3) = 1/2, rho_r = cos(6 pi) = 1; at f_M = 5.5 it is cos(5.5 pi) = 0.
    EXPECT_NEAR(marschnerLobb({2.0 / 3.0, 0.0, 0.0}, 5.5, 0.25), (1.0 + 0.25) / 2.5, 1e-12);
}

TEST(MarschnerLobb, standardGridIs41CubedOnMinusOneToOne) {
    const ScalarGridPtr grid = generateMarschnerLobb({});
    EXPECT_EQ(grid->geometry(), GridGeometry({41, 41, 41}, glm::dvec3(-1.0), glm::dvec3(0.05)));
    EXPECT_EQ(grid->value({20, 20, 20}), 0.6f);
    EXPECT_EQ(grid->value({20, 20, 40}), 0.2f);
    const GridStatistics statistics = grid->statistics();
    EXPECT_EQ(statistics.finiteCount, 41 * 41 * 41);
    EXPECT_GE(statistics.minimum, 0.0);
    EXPECT_LE(statistics.maximum, 1.0);
}

TEST(MarschnerLobb, isDeterministic) {
    const MarschnerLobbParameters parameters{{9, 10, 11}, 6.0, 0.25};
    EXPECT_EQ(dynamic_cast<const DenseScalarGrid&>(*generateMarschnerLobb(parameters)).values(),
              dynamic_cast<const DenseScalarGrid&>(*generateMarschnerLobb(parameters)).values());
}

TEST(MarschnerLobb, rejectsBadParameters) {
    try {
        generateMarschnerLobb({{41, 41, 41}, 6.0, -0.5});
        FAIL();
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "marschner-lobb: alpha must be finite and at least 0, got -0.5");
    }
    try {
        generateMarschnerLobb({{41, 41, 41}, INFINITY, 0.25});
        FAIL();
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "marschner-lobb: modulation frequency must be finite, got inf");
    }
}

} // namespace
} // namespace texsplat::volume
