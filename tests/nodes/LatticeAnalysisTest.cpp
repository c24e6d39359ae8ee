#include "nodes/kernel/LatticeAnalysis.h"

#include "SceneNodesTestSupport.h"
#include "nodes/kernel/CubicKernel.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>

using texsplat::kernel::CubicCoefficients;
using texsplat::kernel::CubicKernel;
using texsplat::kernel::LatticeAnalysis;
using texsplat::nodes::test::errorOf;

namespace {

// Half a unit in the last digit the paper prints.
constexpr double kHalfUnit5 = 0.5e-5;

// The mean of c and the relative r.m.s. sampled on a midpoint grid of the cell, independent of
// the autocorrelation sum LatticeAnalysis uses.
std::pair<double, double> sampledMeanAndRms(const LatticeAnalysis& analysis,
                                            const std::array<double, 3>& spacing, int count) {
    double sum = 0.0;
    double squares = 0.0;
    for (int i = 0; i < count; ++i)
        for (int j = 0; j < count; ++j)
            for (int k = 0; k < count; ++k) {
                const double c = analysis.reconstruction({(i + 0.5) / count * spacing[0],
                                                          (j + 0.5) / count * spacing[1],
                                                          (k + 0.5) / count * spacing[2]});
                sum += c;
                squares += c * c;
            }
    const double samples = static_cast<double>(count) * count * count;
    const double mean = sum / samples;
    return {mean, std::sqrt(squares / samples - mean * mean) / mean};
}

} // namespace

TEST(LatticeAnalysis, printedKernelReproducesThePapersLatticeNumbers) {
    const CubicKernel kernel = CubicKernel::paper();
    const LatticeAnalysis analysis(kernel);
    const auto statistics = analysis.lattice3d();
    EXPECT_NEAR(statistics.relativeRms, 0.00119, kHalfUnit5);
    EXPECT_NEAR(statistics.minDeviation, -0.00233, kHalfUnit5);
    EXPECT_NEAR(statistics.maxDeviation, 0.00534, kHalfUnit5);
    for (double coordinate : statistics.minAt)
        EXPECT_NEAR(coordinate, 0.26, 0.005);
    EXPECT_NEAR(statistics.maxAt[0], 0.5, 1e-6);
    EXPECT_NEAR(statistics.maxAt[1], 0.5, 1e-6);
    EXPECT_NEAR(statistics.maxAt[2], 0.0, 1e-6);
    // The printed coefficients are normalized by the mean of c, to their six digits.
    EXPECT_NEAR(statistics.mean, 1.0, 1e-6);
}

TEST(LatticeAnalysis, printedKernelReproducesThePapersLayerSum) {
    const CubicKernel kernel = CubicKernel::paper();
    const auto layer = LatticeAnalysis(kernel).layer2d();
    EXPECT_NEAR(layer.max, 1.00249, kHalfUnit5);
    EXPECT_NEAR(layer.min, 0.99845, kHalfUnit5);
    EXPECT_NEAR(layer.maxAt[0], 0.5, 1e-6);
    EXPECT_NEAR(layer.maxAt[1], 0.5, 1e-6);
    EXPECT_NEAR(layer.minAt[0], 0.25, 0.005);
    EXPECT_NEAR(layer.minAt[1], 0.25, 0.005);
    EXPECT_NEAR(layer.mean, 1.0, 1e-6);
}

TEST(LatticeAnalysis, exactRmsAgreesWithSampledCell) {
    const CubicKernel kernel = CubicKernel::paper();
    const LatticeAnalysis analysis(kernel);
    const auto [mean, rms] = sampledMeanAndRms(analysis, {1, 1, 1}, 24);
    EXPECT_NEAR(mean, analysis.volumeIntegral(), 1e-7);
    EXPECT_NEAR(rms / analysis.relativeRms(), 1.0, 1e-4);
}

TEST(LatticeAnalysis, anisotropicRmsAgreesWithSampledCell) {
    const CubicKernel kernel = CubicKernel::fromShape(1.8, 3.1, -0.5, 0.03);
    const std::array<double, 3> spacing{1.0, 1.0, 2.0};
    const LatticeAnalysis analysis(kernel, spacing);
    const auto [mean, rms] = sampledMeanAndRms(analysis, spacing, 24);
    EXPECT_NEAR(mean / (analysis.volumeIntegral() / 2.0), 1.0, 1e-8);
    EXPECT_NEAR(rms / analysis.relativeRms(), 1.0, 1e-3);
}

TEST(LatticeAnalysis, relativeMeasuresDoNotDependOnTheLengthUnit) {
    // The paper's kernel on a lattice of spacing L, scaled by L: g_L(r) = g(r/L). At L = 1000
    // the quadrature once took 4000 times as many pieces as at L = 1; now they scale with L.
    const CubicKernel kernel = CubicKernel::paper();
    const CubicCoefficients& k = kernel.coefficients();
    const LatticeAnalysis unit(kernel);
    for (double length : {2.0, 1000.0, 0.001}) {
        const CubicKernel scaledKernel(length * kernel.knot(), length * kernel.support(),
                                       {k.a, k.b / (length * length),
                                        k.c / (length * length * length), k.d / (length * length),
                                        k.e / (length * length * length)});
        const LatticeAnalysis scaled(scaledKernel, {length, length, length});
        EXPECT_NEAR(scaled.relativeRms(), unit.relativeRms(), 1e-12) << length;
        EXPECT_NEAR(scaled.volumeIntegral() / (length * length * length), unit.volumeIntegral(),
                    1e-12)
            << length;
    }
}

TEST(LatticeAnalysis, nonIntegrableKernelHasInfiniteRms) {
    const CubicKernel negative = CubicKernel::paper().scaled(-1.0);
    EXPECT_EQ(LatticeAnalysis(negative).relativeRms(), HUGE_VAL);
}

TEST(LatticeAnalysis, badSpacingThrowsWithClearMessage) {
    const CubicKernel kernel = CubicKernel::paper();
    for (double bad : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
        std::ostringstream expected;
        expected << "lattice spacing (1, " << bad << ", 1) must be finite and > 0";
        EXPECT_EQ(errorOf<texsplat::DataError>([&] { LatticeAnalysis(kernel, {1.0, bad, 1.0}); }),
                  expected.str());
    }
}

TEST(LatticeAnalysis, spacingRatioAboveFourIsRejected) {
    const CubicKernel kernel = CubicKernel::paper();
    EXPECT_NO_THROW(LatticeAnalysis(kernel, {1.0, 1.0, 4.0}));
    for (const auto& [spacing, text] :
         {std::pair{std::array<double, 3>{1.0, 1.0, 4.001}, "(1, 1, 4.001)"},
          std::pair{std::array<double, 3>{1e-10, 1.0, 1.0}, "(1e-10, 1, 1)"}}) {
        EXPECT_EQ(errorOf<texsplat::DataError>([&] { LatticeAnalysis(kernel, spacing); }),
                  std::string("lattice spacing ") + text +
                      " must have its largest spacing at most 4 times its smallest (the run time "
                      "grows with the ratio)");
    }
}

TEST(LatticeAnalysis, supportAboveFourCubeRootsOfTheCellVolumeIsRejected) {
    const CubicKernel kernel = CubicKernel::paper();
    EXPECT_EQ(LatticeAnalysis::maxSupport({1.0, 0.5, 2.0}), 4.0);
    EXPECT_NO_THROW(LatticeAnalysis(kernel, {0.39, 0.39, 0.39}));
    EXPECT_EQ(errorOf<texsplat::DataError>([&] { LatticeAnalysis(kernel, {0.2, 0.25, 0.3}); }),
              "kernel support 1.55623 must be at most 0.986485 on lattice spacing (0.2, 0.25, "
              "0.3) (4 times the cube root of the cell volume; the run time grows as t³ over the "
              "volume)");
}
