#pragma once

#include "nodes/volume/GridStatistics.h"

#include <glm/gtc/type_precision.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace texsplat::volume {

/// @brief What a brick of a grid split over processes knows of the whole grid (distributed
/// rendering, docs/distributed.md): where it lies in it, and the figures a transfer function's
/// data range is taken from (TransferFunction `rangeMode` DATA and PERCENTILE), so that every
/// brick classifies its voxels as the whole grid's would be, whatever the others hold.
struct WholeGrid {
    /// @brief Bins of `histogram`: those of the percentiles of a PERCENTILE range.
    static constexpr std::size_t kHistogramBins = 65536;

    /// @brief Value range and counts of the whole grid (for vectors: of the lengths).
    GridStatistics statistics;
    /// @brief How many finite values of the whole grid (for vectors: lengths) fall in each of
    /// kHistogramBins equal bins over [statistics.minimum, statistics.maximum], as
    /// valueHistogram() counts them; empty when no PERCENTILE range needs it.
    std::vector<std::uint64_t> histogram;
};

} // namespace texsplat::volume
