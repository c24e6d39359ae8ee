#include "nodes/kernel/CubicKernel.h"

#include "KernelQuadrature.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using texsplat::kernel::CubicKernel;

namespace {

// A kernel from the paper's parametrization (a = 1, c and e from C¹ at s), near its minimum.
CubicKernel shapeNearPaper() { return CubicKernel::fromShape(0.89, 1.556, -2.0766, 0.1212); }

void expectFootprintMatchesQuadrature(const CubicKernel& kernel, double r) {
    const long double reference = texsplat::test::referenceFootprint(kernel, r);
    EXPECT_LE(std::fabs(static_cast<long double>(kernel.footprint(r)) - reference), 1e-12L)
        << "r = " << r;
}

} // namespace

TEST(CubicKernel, paperKernelHasPrintedCoefficients) {
    const CubicKernel kernel = CubicKernel::paper();
    EXPECT_EQ(kernel.support(), 1.556228);
    EXPECT_EQ(kernel.knot(), 0.889392);
    EXPECT_EQ(kernel.coefficients().a, 0.557526);
    EXPECT_EQ(kernel.coefficients().b, -1.157743);
    EXPECT_EQ(kernel.coefficients().c, 0.671033);
    EXPECT_EQ(kernel.coefficients().d, 0.067599);
    EXPECT_EQ(kernel.coefficients().e, 0.282474);
}

TEST(CubicKernel, fromShapeIsC1AtZeroKnotAndSupport) {
    const CubicKernel kernel = shapeNearPaper();
    const double s = kernel.knot();
    const double t = kernel.support();
    const auto& k = kernel.coefficients();
    EXPECT_EQ(k.a, 1.0);
    EXPECT_EQ(kernel.derivative(0.0), 0.0);
    // p and q and their slopes agree at s (evaluated from both polynomials at exactly s).
    const double pAtKnot = k.a + k.b * s * s + k.c * s * s * s;
    const double qAtKnot = k.d * (t - s) * (t - s) + k.e * (t - s) * (t - s) * (t - s);
    const double pSlope = 2.0 * k.b * s + 3.0 * k.c * s * s;
    const double qSlope = -2.0 * k.d * (t - s) - 3.0 * k.e * (t - s) * (t - s);
    EXPECT_NEAR(pAtKnot, qAtKnot, 1e-14);
    EXPECT_NEAR(pSlope, qSlope, 1e-14);
    EXPECT_NEAR(kernel.value(s - 1e-9), kernel.value(s + 1e-9), 1e-8);
    EXPECT_NEAR(kernel.derivative(s - 1e-9), kernel.derivative(s + 1e-9), 1e-7);
    EXPECT_EQ(kernel.value(t), 0.0);
    EXPECT_EQ(kernel.derivative(t), 0.0);
    EXPECT_NEAR(kernel.derivative(t - 1e-9), 0.0, 1e-8);
}

TEST(CubicKernel, paperKernelIsC1ToItsPrintedDigits) {
    const CubicKernel kernel = CubicKernel::paper();
    const double s = kernel.knot();
    EXPECT_NEAR(kernel.value(s - 1e-12), kernel.value(s + 1e-12), 2e-6);
    EXPECT_NEAR(kernel.derivative(s - 1e-12), kernel.derivative(s + 1e-12), 2e-5);
    EXPECT_EQ(kernel.derivative(0.0), 0.0);
}

TEST(CubicKernel, footprintMatchesLongDoubleQuadratureOnDenseSamples) {
    for (const CubicKernel& kernel : {CubicKernel::paper(), shapeNearPaper()}) {
        const int count = 1500;
        for (int i = 0; i <= count; ++i)
            expectFootprintMatchesQuadrature(kernel, kernel.support() * i / count);
    }
}

TEST(CubicKernel, footprintMatchesQuadratureNearZeroKnotAndSupport) {
    for (const CubicKernel& kernel : {CubicKernel::paper(), shapeNearPaper()}) {
        const double s = kernel.knot();
        const double t = kernel.support();
        for (double offset : {1e-9, 3e-10, 1e-12, 1e-15}) {
            expectFootprintMatchesQuadrature(kernel, offset);
            expectFootprintMatchesQuadrature(kernel, s - offset);
            expectFootprintMatchesQuadrature(kernel, s + offset);
            expectFootprintMatchesQuadrature(kernel, t - offset);
        }
        expectFootprintMatchesQuadrature(kernel, std::numeric_limits<double>::denorm_min());
        expectFootprintMatchesQuadrature(kernel, std::nextafter(t, 0.0));
    }
}

TEST(CubicKernel, footprintKeepsRelativeAccuracyNearSupport) {
    // Near t the footprint is O((t−r)^{5/2}); the series form keeps its relative digits.
    const CubicKernel kernel = CubicKernel::paper();
    for (double offset : {1e-2, 1e-4, 1e-6, 1e-8}) {
        const double r = kernel.support() - offset;
        const long double reference = texsplat::test::referenceFootprint(kernel, r);
        EXPECT_NEAR(kernel.footprint(r) / reference, 1.0, 1e-9) << "t - r = " << offset;
    }
}

TEST(CubicKernel, footprintOutsideSupportNegativeAndNanHaveDefinedValues) {
    const CubicKernel kernel = CubicKernel::paper();
    EXPECT_EQ(kernel.footprint(kernel.support()), 0.0);
    EXPECT_EQ(kernel.footprint(2.0), 0.0);
    EXPECT_EQ(kernel.footprint(std::numeric_limits<double>::infinity()), 0.0);
    EXPECT_EQ(kernel.footprint(-0.7), kernel.footprint(0.7));
    EXPECT_EQ(kernel.footprint(-0.0), kernel.footprint(0.0));
    EXPECT_TRUE(std::isnan(kernel.footprint(std::numeric_limits<double>::quiet_NaN())));
    EXPECT_EQ(kernel.value(-0.3), kernel.value(0.3));
    EXPECT_EQ(kernel.value(5.0), 0.0);
}

TEST(CubicKernel, shellIntegralMatchesQuadrature) {
    const CubicKernel kernel = CubicKernel::paper();
    const auto integrand = [&](long double r) { return kernel.profile(r) * r; };
    for (double r : {0.3, 0.889392, 1.2, 1.556228, 3.0}) {
        const long double end = std::min(r, kernel.support());
        const long double reference =
            texsplat::test::adaptiveIntegral(integrand, 0.0L, std::min(end, 0.889392L), 1e-19L) +
            (end > 0.889392L
                 ? texsplat::test::adaptiveIntegral(integrand, 0.889392L, end, 1e-19L)
                 : 0.0L);
        EXPECT_NEAR(static_cast<double>(kernel.shellIntegral(r)), static_cast<double>(reference),
                    1e-15)
            << "r = " << r;
    }
}

TEST(CubicKernel, invalidShapesThrowWithClearMessages) {
    const auto expectMessage = [](auto make, const std::string& message) {
        try {
            make();
            FAIL() << "expected DataError: " << message;
        } catch (const texsplat::DataError& error) {
            EXPECT_EQ(error.what(), message);
        }
    };
    expectMessage([] { CubicKernel::fromShape(-0.5, 1.5, -2.0, 0.1); },
                  "cubic kernel: knot s = -0.5 must be > 0");
    expectMessage([] { CubicKernel::fromShape(0.9, 0.9, -2.0, 0.1); },
                  "cubic kernel: support t = 0.9 must be > knot s = 0.9");
    expectMessage([] { CubicKernel::fromShape(0.9, 1.5, std::nan(""), 0.1); },
                  "cubic kernel: b = nan is not finite");
    expectMessage([] { CubicKernel::paper().scaled(HUGE_VAL); },
                  "cubic kernel: scale factor = inf is not finite");
}
