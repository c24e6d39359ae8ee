#include "nodes/kernel/KernelTable.h"

#include "nodes/kernel/CubicKernel.h"
#include "nodes/kernel/GaussianKernel.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace texsplat::kernel {
namespace {

// Largest |table(r²) − g(r)| over a fine grid of radii, relative to g(0).
double maxRelativeError(const RadialKernel& kernel, const KernelTable& table) {
    const double support = kernel.support();
    double worst = 0.0;
    for (int i = 0; i <= 200000; ++i) {
        const double r = support * 1.05 * i / 200000.0;
        const double error = std::abs(table(static_cast<float>(r * r)) - kernel.value(r));
        worst = std::max(worst, error);
    }
    return worst / kernel.value(0.0);
}

TEST(KernelTable, paperKernelIsWithinTwoEMinusFiveOfTheClosedForm) {
    const CubicKernel paper = CubicKernel::paper();
    const double error = maxRelativeError(paper, KernelTable::paper());
    RecordProperty("max_relative_error", std::to_string(error));
    EXPECT_LT(error, 2e-5);
    // Fewer entries are measurably worse: the bound is the table's, not the test's.
    EXPECT_GT(maxRelativeError(paper, KernelTable(paper, 64)), 2e-5);
}

TEST(KernelTable, isZeroFromTheSupportOnAndForNaN) {
    const KernelTable& table = KernelTable::paper();
    const float t2 = table.supportSquared();
    EXPECT_EQ(table(t2), 0.0f);
    EXPECT_EQ(table(std::nextafter(t2, 0.0f)) < 1e-6f, true);
    EXPECT_EQ(table(1e30f), 0.0f);
    EXPECT_EQ(table(std::numeric_limits<float>::infinity()), 0.0f);
    EXPECT_EQ(table(std::numeric_limits<float>::quiet_NaN()), 0.0f);
    EXPECT_NEAR(table(0.0f), 0.557526f, 1e-6f);
}

TEST(KernelTable, tabulatesOtherKernelsToo) {
    const GaussianKernel gaussian(0.3, 1.5); // g(t) / g(0) = 4e-6: no jump at the support
    EXPECT_LT(maxRelativeError(gaussian, KernelTable(gaussian)), 2e-5);
}

TEST(KernelTable, rejectsTooFewEntries) {
    try {
        KernelTable(CubicKernel::paper(), 1);
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "KernelTable: needs at least 2 entries, got 1");
    }
}

} // namespace
} // namespace texsplat::kernel
