#include "nodes/volume/ValueHistogram.h"

#include "scenegraph/Assert.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace texsplat::volume {
namespace {

double scalarOf(float value) { return value; }
// In double: a huge vector's squared length overflows float.
double scalarOf(const glm::vec3& value) { return glm::length(glm::dvec3(value)); }

} // namespace

template <class T>
std::vector<std::uint64_t> valueHistogram(const Grid<T>& grid, double low, double high,
                                          std::size_t bins) {
    TEXSPLAT_ASSERT(bins >= 1 && low < high, "valueHistogram: no bins or an empty range");
    std::vector<std::uint64_t> counts(bins, 0);
    const double span = high - low;
    grid.forEachActive([&](const glm::i64vec3& /*index*/, const T& value) {
        const double bin = (scalarOf(value) - low) / span * double(bins);
        counts[std::min(bins - 1, static_cast<std::size_t>(std::max(0.0, bin)))] += 1;
    });
    return counts;
}

template std::vector<std::uint64_t> valueHistogram(const Grid<float>&, double, double, std::size_t);
template std::vector<std::uint64_t> valueHistogram(const Grid<glm::vec3>&, double, double,
                                                   std::size_t);

} // namespace texsplat::volume
