#include "octree/ValueHistograms.h"

#include <algorithm>
#include <limits>

namespace texsplat::octree {

std::optional<ValueHistograms::Block>
ValueHistograms::summarize(glm::u64vec3 coordinates, const BlockValues& values,
                           const BlockMask& nonEmpty) {
    float lowest = std::numeric_limits<float>::infinity();
    float highest = -std::numeric_limits<float>::infinity();
    for (std::size_t v = 0; v < values.size(); ++v) {
        if (nonEmpty[v]) {
            lowest = std::min(lowest, values[v]);
            highest = std::max(highest, values[v]);
        }
    }
    if (!(lowest <= highest)) {
        return std::nullopt;
    }
    Block block;
    block.coordinates = coordinates;
    block.range = glm::vec2(lowest, highest);
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
