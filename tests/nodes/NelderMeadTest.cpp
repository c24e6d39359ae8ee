#include "nodes/kernel/detail/NelderMead.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace texsplat::kernel::detail;

TEST(NelderMead, minimizesTheRosenbrockValley) {
    const auto rosenbrock = [](const std::vector<double>& x) {
        return 100.0 * std::pow(x[1] - x[0] * x[0], 2) + std::pow(1.0 - x[0], 2);
    };
    NelderMeadOptions options;
    options.initialStep = {0.1, 0.1};
    options.tolerance = 1e-10;
    const NelderMeadResult result = minimizeNelderMead(rosenbrock, {-1.2, 1.0}, options);
    EXPECT_TRUE(result.converged);
    EXPECT_NEAR(result.point[0], 1.0, 1e-6);
    EXPECT_NEAR(result.point[1], 1.0, 1e-6);
}

TEST(NelderMead, treatsInfiniteAndNanValuesAsOutsideTheDomain) {
    // Minimum of (x−2)² restricted to x < 1.5 lies at the boundary.
    const auto restricted = [](const std::vector<double>& x) {
        if (x[0] >= 1.5)
            return std::nan("");
        return (x[0] - 2.0) * (x[0] - 2.0);
    };
    NelderMeadOptions options;
    options.initialStep = {0.5};
    const NelderMeadResult result = minimizeNelderMead(restricted, {0.0}, options);
    EXPECT_LT(result.point[0], 1.5);
    EXPECT_NEAR(result.point[0], 1.5, 1e-6);
}

TEST(NelderMead, stopsAtTheEvaluationCap) {
    NelderMeadOptions options;
    options.initialStep = {1.0, 1.0};
    options.maxEvaluations = 10;
    const NelderMeadResult result = minimizeNelderMead(
        [](const std::vector<double>& x) { return x[0] * x[0] + x[1] * x[1]; }, {5.0, 5.0},
        options);
    EXPECT_FALSE(result.converged);
    EXPECT_LE(result.evaluations, 12);
}
