#pragma once

#include "nodes/kernel/RadialKernel.h"

#include <cstddef>
#include <vector>

namespace texsplat::kernel {

/// @brief A radial kernel g tabulated in r² for fast evaluation in inner loops (the ray
/// caster's reconstruction sums): `operator()(r²)` interpolates linearly between `entries`
/// equally spaced samples of g(√u) on [0, t²], one table load and one multiply-add, no square
/// root.
///
/// In u = r² the paper's cubic is a + b·u + c·u^{3/2} near 0 and smooth elsewhere except at the
/// knot, so linear interpolation with 4096 entries is within 2e-5 of g (relative to g(0)); the
/// test measures the bound (KernelTableTest).
class KernelTable {
public:
    /// @brief Default number of intervals.
    static constexpr int kDefaultEntries = 4096;

    /// @brief Tabulates `kernel` with `entries` intervals over [0, t²].
    /// @throws DataError when `entries` < 2 or the support is not finite and positive.
    explicit KernelTable(const RadialKernel& kernel, int entries = kDefaultEntries);

    /// @brief g(√u) for u = r² ≥ 0; 0 from u ≥ t² on (and for NaN).
    float operator()(float radiusSquared) const {
        if (!(radiusSquared < mSupportSquared)) {
            return 0.0f;
        }
        const float position = radiusSquared * mScale;
        const auto index = static_cast<int>(position);
        const float fraction = position - static_cast<float>(index);
        const Entry& entry = mEntries[static_cast<std::size_t>(index)];
        return entry.value + fraction * entry.slope;
    }

    /// @brief The support radius t.
    float support() const { return mSupport; }

    /// @brief t², where the table ends.
    float supportSquared() const { return mSupportSquared; }

    /// @brief The table of the paper's kernel (CubicKernel::paper()), built once.
    static const KernelTable& paper();

private:
    struct Entry {
        float value; // g at the interval's start
        float slope; // difference to the next sample
    };

    std::vector<Entry> mEntries;
    float mSupport;
    float mSupportSquared;
    float mScale;
};

} // namespace texsplat::kernel
