#include "nodes/kernel/KernelOptimizer.h"

#include "SceneNodesTestSupport.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

using namespace texsplat::kernel;
using texsplat::nodes::test::errorOf;

namespace {

void expectStartRejected(const KernelShape& start, const std::string& message,
                         const OptimizerOptions& options = {}) {
    try {
        KernelOptimizer(options).optimize(start);
        FAIL() << "expected DataError: " << message;
    } catch (const texsplat::DataError& error) {
        EXPECT_EQ(error.what(), message);
    }
}

} // namespace

TEST(KernelOptimizer, landsOnThePapersMinimumFromANearbyStart) {
    const KernelOptimizer optimizer;
    int reports = 0;
    const OptimizerResult result =
        optimizer.optimize(optimizer.defaultStart(), [&](const OptimizerStep&) { ++reports; });
    // The paper's t = 1.556228, s = 0.889392 to five digits (its optimizer stopped 2e-12 above
    // the minimum, which moves t by 3e-6; docs/kernel.md).
    EXPECT_NEAR(result.kernel.support(), 1.556228, 5e-6);
    EXPECT_NEAR(result.kernel.knot(), 0.889392, 5e-6);
    EXPECT_NEAR(result.relativeRms, 0.00119, 0.5e-5);
    const CubicCoefficients& k = result.kernel.coefficients();
    EXPECT_NEAR(k.a, 0.557526, 2e-6);
    EXPECT_NEAR(k.b, -1.157743, 2e-6);
    EXPECT_NEAR(k.c, 0.671033, 2e-6);
    EXPECT_NEAR(k.d, 0.067599, 5e-6);
    EXPECT_NEAR(k.e, 0.282474, 2e-6);
    EXPECT_GT(reports, 0);
    EXPECT_EQ(result.path.back().relativeRms, result.relativeRms);
    // Normalized as the paper does: the mean of the reconstruction is 1.
    EXPECT_NEAR(LatticeAnalysis(result.kernel).volumeIntegral(), 1.0, 1e-12);
}

TEST(KernelOptimizer, otherStartsFindOtherMinimaWithLowerVariance) {
    const KernelOptimizer optimizer;
    const OptimizerResult wider = optimizer.optimize({1.0, 2.0, -1.5, 0.1});
    EXPECT_NEAR(wider.kernel.support(), 1.894, 1e-3);
    EXPECT_LT(wider.relativeRms, 0.5e-3);
    EXPECT_TRUE(wider.kernel.isNonIncreasing());
}

TEST(KernelOptimizer, paperPointIsNoBetterThanTheFoundMinimum) {
    const KernelOptimizer optimizer;
    const double a = 0.557526;
    const double paperPoint =
        optimizer.objective({0.889392, 1.556228, -1.157743 / a, 0.067599 / a});
    const OptimizerResult result = optimizer.optimize(optimizer.defaultStart());
    EXPECT_LE(result.relativeRms, paperPoint);
    EXPECT_LT(paperPoint - result.relativeRms, 1e-11);
}

TEST(KernelOptimizer, fixedSupportKeepsTheSupport) {
    OptimizerOptions options;
    options.fixedSupport = 2.0;
    const KernelOptimizer optimizer(options);
    const OptimizerResult result = optimizer.optimize(optimizer.defaultStart());
    EXPECT_EQ(result.kernel.support(), 2.0);
    EXPECT_LT(result.relativeRms, 0.00119);
    EXPECT_GT(result.kernel.knot(), 0.0);
    EXPECT_LT(result.kernel.knot(), 2.0);
}

TEST(KernelOptimizer, anisotropicLatticeGetsARotationallySymmetricKernel) {
    OptimizerOptions options;
    options.spacing = {1.0, 1.0, 2.0};
    options.fixedSupport = 1.556228 * 2.0;
    const KernelOptimizer optimizer(options);
    const OptimizerResult result = optimizer.optimize(optimizer.defaultStart());
    EXPECT_LT(result.relativeRms, 0.001);
    const LatticeAnalysis analysis(result.kernel, options.spacing);
    EXPECT_NEAR(analysis.relativeRms(), result.relativeRms, 1e-12);
    EXPECT_NEAR(analysis.lattice3d().mean, 1.0, 1e-12);
}

TEST(KernelOptimizer, objectiveIsInfiniteOutsideItsDomain) {
    const KernelOptimizer optimizer;
    EXPECT_EQ(optimizer.objective({-0.5, 1.5, -2.0, 0.1}), HUGE_VAL);
    EXPECT_EQ(optimizer.objective({1.5, 1.5, -2.0, 0.1}), HUGE_VAL);
    EXPECT_EQ(optimizer.objective({0.9, 1.5, std::nan(""), 0.1}), HUGE_VAL);
    EXPECT_EQ(optimizer.objective({0.9, 1.5, 2.0, 0.1}), HUGE_VAL); // increasing at 0
    EXPECT_EQ(optimizer.objective({0.5, 0.86, -2.0, 0.1}), HUGE_VAL); // misses the cell corner
    EXPECT_EQ(optimizer.objective({2.5, 4.1, -0.3, 0.02}), HUGE_VAL); // beyond 4 voxels
    EXPECT_TRUE(std::isfinite(optimizer.objective(optimizer.defaultStart())));
}

TEST(KernelOptimizer, badStartsThrowWithClearMessages) {
    expectStartRejected({0.9, 0.8, -2.0, 0.1},
                        "optimizer start: support t = 0.8 must be > knot s = 0.9");
    expectStartRejected({0.9, 0.9, -2.0, 0.1},
                        "optimizer start: support t = 0.9 must be > knot s = 0.9");
    expectStartRejected({-1.0, 1.5, -2.0, 0.1}, "optimizer start: knot s = -1 must be > 0");
    expectStartRejected({0.0, 1.5, -2.0, 0.1}, "optimizer start: knot s = 0 must be > 0");
    expectStartRejected({std::nan(""), 1.5, -2.0, 0.1},
                        "optimizer start: knot s = nan is not finite");
    expectStartRejected({0.9, HUGE_VAL, -2.0, 0.1},
                        "optimizer start: support t = inf is not finite");
    expectStartRejected({0.9, 1.5, -2.0, -HUGE_VAL}, "optimizer start: d = -inf is not finite");
    expectStartRejected({0.9, 1.5, 2.0, 0.1},
                        "optimizer start: outside the search domain (the profile must not "
                        "increase, and s must lie within [0.001 t, 0.999 t])");
    expectStartRejected({0.9, 100.0, -2.0, 0.1},
                        "optimizer start: support t = 100 must be in (0.866025, 4] on lattice "
                        "spacing (1, 1, 1): more than half the cell diagonal (or some points are "
                        "out of every kernel's reach) and at most 4 times the cube root of the "
                        "cell volume (the run time grows as t³ over the volume)");
    OptimizerOptions fixed;
    fixed.fixedSupport = 0.88;
    expectStartRejected({0.9, 1.5, -2.0, 0.1},
                        "optimizer start: support t = 0.88 must be > knot s = 0.9", fixed);
}

TEST(KernelOptimizer, supportRangeFollowsTheLattice) {
    const KernelOptimizer cubic;
    EXPECT_DOUBLE_EQ(cubic.minSupport(), 0.5 * std::sqrt(3.0));
    EXPECT_EQ(cubic.maxSupport(), 4.0);
    OptimizerOptions options;
    options.spacing = {1.0, 2.0, 2.0};
    const KernelOptimizer anisotropic(options);
    EXPECT_EQ(anisotropic.minSupport(), 1.5);
    EXPECT_DOUBLE_EQ(anisotropic.maxSupport(), 4.0 * std::cbrt(4.0));
}

TEST(KernelOptimizer, badOptionsThrowWithClearMessages) {
    const auto expectRejected = [](const OptimizerOptions& options, const std::string& message) {
        EXPECT_EQ(errorOf<texsplat::DataError>([&] { KernelOptimizer{options}; }), message);
    };
    const std::string reason = ": more than half the cell diagonal (or some points are out of "
                               "every kernel's reach) and at most 4 times the cube root of the "
                               "cell volume (the run time grows as t³ over the volume)";
    OptimizerOptions options;
    for (double support : {-1.0, 1e-6, 0.5 * std::sqrt(3.0), 4.001, std::nan("")}) {
        options.fixedSupport = support;
        std::ostringstream value;
        value << support;
        expectRejected(options, "kernel support " + value.str() +
                                    " must be in (0.866025, 4] on lattice spacing (1, 1, 1)" +
                                    reason);
    }
    options.spacing = {1.0, 1.0, 4.0};
    options.fixedSupport = 2.0;
    expectRejected(options, "kernel support 2 must be in (2.12132, 6.3496] on lattice spacing (1, "
                            "1, 4)" + reason);
    options.spacing = {1.0, 1.0, 5.0};
    options.fixedSupport.reset();
    expectRejected(options, "lattice spacing (1, 1, 5) must have its largest spacing at most 4 "
                            "times its smallest (the run time grows with the ratio)");
    EXPECT_EQ(errorOf<texsplat::DataError>([] { KernelOptimizer().fitGaussian(5.0); }),
              "kernel support 5 must be in (0.866025, 4] on lattice spacing (1, 1, 1)" + reason);
}

TEST(KernelOptimizer, gaussianOfTheSameExtentIsFarLessFlat) {
    const KernelOptimizer optimizer;
    const GaussianFit gaussian = optimizer.fitGaussian(1.556228);
    EXPECT_EQ(gaussian.kernel.support(), 1.556228);
    EXPECT_NEAR(gaussian.kernel.sigma(), 0.552, 1e-3);
    EXPECT_NEAR(gaussian.relativeRms, 0.01568, 1e-5);
    const CubicKernel paper = CubicKernel::paper();
    const LatticeAnalysis cubic(paper);
    EXPECT_GT(gaussian.relativeRms, 10.0 * cubic.relativeRms());
    const LatticeAnalysis analysis(gaussian.kernel);
    EXPECT_NEAR(analysis.volumeIntegral(), 1.0, 1e-12);
    const Layer2dStatistics layer = analysis.layer2d();
    EXPECT_GT(layer.max - layer.min, 10.0 * (1.00249 - 0.99845));
}
