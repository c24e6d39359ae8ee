#include "nodes/kernel/KernelTable.h"

#include "nodes/kernel/CubicKernel.h"
#include "scenegraph/Error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace texsplat::kernel {

KernelTable::KernelTable(const RadialKernel& kernel, int entries) {
    const double support = kernel.support();
    if (entries < 2) {
        throw DataError("KernelTable: needs at least 2 entries, got " + std::to_string(entries));
    }
    if (!std::isfinite(support) || !(support > 0.0)) {
        throw DataError("KernelTable: the kernel's support must be finite and positive");
    }
    mSupport = static_cast<float>(support);
    mSupportSquared = static_cast<float>(support * support);
    mScale = static_cast<float>(entries) / mSupportSquared;
    // One spare entry: a radius just below t² in float may round to index `entries`.
    mEntries.resize(static_cast<std::size_t>(entries) + 1);
    const double step = support * support / entries;
    auto sample = [&](int i) {
        const double u = std::min(step * i, support * support);
        return kernel.value(std::sqrt(u));
    };
    double next = sample(0);
    for (int i = 0; i <= entries; ++i) {
        const double value = next;
        next = i < entries ? sample(i + 1) : 0.0;
        mEntries[static_cast<std::size_t>(i)] = {static_cast<float>(value),
                                                 static_cast<float>(next - value)};
    }
}

const KernelTable& KernelTable::paper() {
    static const KernelTable table(CubicKernel::paper());
    return table;
}

} // namespace texsplat::kernel
