#include "octree/ValueHistograms.h"

#include "scenegraph/Assert.h"

#include <algorithm>
#include <cmath>

namespace texsplat::octree {

ValueHistograms::Block ValueHistograms::summarize(glm::u64vec3 coordinates,
                                                  const BlockValues& values,
                                                  const BlockMask& nonEmpty, glm::vec2 range) {
    // A NaN or infinity would make no bin (and an index out of the bins).
    TEXSPLAT_ASSERT(std::isfinite(range.x) && std::isfinite(range.y) && range.x <= range.y,
                    "ValueHistograms::summarize: no finite range");
    const float lowest = range.x;
    const float highest = range.y;
    Block block;
    block.coordinates = coordinates;
    block.range = range;
    // In double: the width of a range from -3e38 to 3e38 overflows float.
    const double width = static_cast<double>(highest) - lowest;
    const double binsPerValue = width > 0.0 ? kBins / width : 0.0;
    std::array<double, kBins> sums{};
    for (std::size_t v = 0; v < values.size(); ++v) {
        if (!nonEmpty[v]) {
            continue;
        }
        const double value = values[v];
        const int bin = std::min(kBins - 1, static_cast<int>((value - lowest) * binsPerValue));
        sums[static_cast<std::size_t>(bin)] += value;
        ++block.counts[static_cast<std::size_t>(bin)];
    }
    for (std::size_t bin = 0; bin < sums.size(); ++bin) {
        if (block.counts[bin] > 0) {
            // Rounding may leave the mean of equal values a hair off them: keep it in the range.
            block.means[bin] =
                std::clamp(static_cast<float>(sums[bin] / block.counts[bin]), lowest, highest);
        }
    }
    return block;
}

} // namespace texsplat::octree
