#include "nodes/kernel/GaussianKernel.h"

#include "KernelQuadrature.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <cmath>

using texsplat::kernel::GaussianKernel;

TEST(GaussianKernel, profileIsTruncatedGaussian) {
    const GaussianKernel kernel(0.5, 1.5, 2.0);
    EXPECT_DOUBLE_EQ(kernel.value(0.0), 2.0);
    EXPECT_DOUBLE_EQ(kernel.value(0.5), 2.0 * std::exp(-0.5));
    EXPECT_DOUBLE_EQ(kernel.value(-0.5), kernel.value(0.5));
    EXPECT_EQ(kernel.value(1.5), 0.0);
    EXPECT_GT(kernel.value(std::nextafter(1.5, 0.0)), 0.0); // the jump truncation causes
}

TEST(GaussianKernel, footprintMatchesLongDoubleQuadrature) {
    const GaussianKernel kernel(0.55, 1.556228, 0.4);
    for (int i = 0; i <= 400; ++i) {
        const double r = kernel.support() * i / 400;
        EXPECT_NEAR(kernel.footprint(r),
                    static_cast<double>(texsplat::test::referenceFootprint(kernel, r)), 1e-12)
            << "r = " << r;
    }
    EXPECT_EQ(kernel.footprint(2.0), 0.0);
    EXPECT_EQ(kernel.footprint(-0.3), kernel.footprint(0.3));
    EXPECT_TRUE(std::isnan(kernel.footprint(std::nan(""))));
}

TEST(GaussianKernel, shellIntegralMatchesQuadrature) {
    const GaussianKernel kernel(0.55, 1.556228);
    const auto integrand = [&](long double r) { return kernel.profile(r) * r; };
    for (double r : {1e-6, 0.4, 1.556228}) {
        const long double reference = texsplat::test::adaptiveIntegral(integrand, 0.0L, r, 1e-20L);
        EXPECT_NEAR(static_cast<double>(kernel.shellIntegral(r) / reference), 1.0, 1e-14);
    }
    EXPECT_EQ(kernel.shellIntegral(5.0), kernel.shellIntegral(1.556228));
}

TEST(GaussianKernel, badParametersThrowWithClearMessages) {
    const auto expectMessage = [](auto make, const char* message) {
        try {
            make();
            FAIL() << message;
        } catch (const texsplat::DataError& error) {
            EXPECT_STREQ(error.what(), message);
        }
    };
    expectMessage([] { GaussianKernel(0.0, 1.5); },
                  "gaussian kernel: sigma = 0 must be a finite number > 0");
    expectMessage([] { GaussianKernel(0.5, -1.0); },
                  "gaussian kernel: support t = -1 must be a finite number > 0");
    expectMessage([] { GaussianKernel(0.5, 1.5, HUGE_VAL); },
                  "gaussian kernel: amplitude = inf must be finite");
}
