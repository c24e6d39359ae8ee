#include "nodes/detail/DataRange.h"

#include "nodes/volume/ValueHistogram.h"
#include "scenegraph/Assert.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace texsplat::nodes::detail {
glm::dvec2 widenedRange(double low, double high) {
    return low < high ? glm::dvec2(low, high) : glm::dvec2(low - 0.5, low + 0.5);
}

namespace {

// The statistics a data range is taken from: the whole grid's for a brick of it.
template <class T> volume::GridStatistics rangeStatistics(const volume::Grid<T>& grid) {
    const volume::WholeGrid* whole = grid.whole();
    return whole ? whole->statistics : grid.statistics();
}

} // namespace

template <class T> glm::dvec2 valueRange(const volume::Grid<T>& grid) {
    const volume::GridStatistics statistics = rangeStatistics(grid);
    if (statistics.finiteCount == 0) {
        return {0.0, 1.0};
    }
    return widenedRange(statistics.minimum, statistics.maximum);
}

template <class T>
glm::dvec2 percentileRange(const volume::Grid<T>& grid, double low, double high) {
    const volume::GridStatistics statistics = rangeStatistics(grid);
    if (statistics.finiteCount == 0) {
        return {0.0, 1.0};
    }
    const double minimum = statistics.minimum;
    const double span = statistics.maximum - minimum;
    if (!(span > 0.0)) {
        return widenedRange(minimum, minimum);
    }
    constexpr std::size_t kBins = volume::WholeGrid::kHistogramBins;
    const volume::WholeGrid* whole = grid.whole();
    TEXSPLAT_ASSERT(!whole || whole->histogram.size() == kBins,
                    "percentileRange(): a brick without the whole grid's histogram");
    const std::vector<std::uint64_t> counts =
        whole ? whole->histogram : volume::valueHistogram(grid, minimum, statistics.maximum, kBins);
    // The value of rank p (0..count-1) interpolated within its bin, values spread evenly in it.
    const auto percentile = [&](double percent) {
        const double rank = percent / 100.0 * double(statistics.finiteCount - 1);
        double below = 0.0;
        for (std::size_t bin = 0; bin < kBins; ++bin) {
            const double inBin = double(counts[bin]);
            if (inBin > 0.0 && rank < below + inBin) {
                const double within = (rank - below + 0.5) / inBin;
                return minimum + span * (double(bin) + within) / double(kBins);
            }
            below += inBin;
        }
        return statistics.maximum;
    };
    return widenedRange(std::max(minimum, percentile(low)),
                   std::min(statistics.maximum, percentile(high)));
}

template glm::dvec2 valueRange(const volume::Grid<float>&);
template glm::dvec2 valueRange(const volume::Grid<glm::vec3>&);
template glm::dvec2 percentileRange(const volume::Grid<float>&, double, double);
template glm::dvec2 percentileRange(const volume::Grid<glm::vec3>&, double, double);

} // namespace texsplat::nodes::detail
