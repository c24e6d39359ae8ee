#pragma once

#include "nodes/volume/Grid.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace texsplat::volume {

/// @brief How many finite values of `grid` (for vectors: lengths) fall into each of `bins` (>= 1)
/// equal bins over [`low`, `high`] (low < high, both finite); values below or above the range
/// count into the first or the last bin. One walk over the grid's non-empty voxels.
template <class T>
std::vector<std::uint64_t> valueHistogram(const Grid<T>& grid, double low, double high,
                                          std::size_t bins);

extern template std::vector<std::uint64_t> valueHistogram(const Grid<float>&, double, double,
                                                          std::size_t);
extern template std::vector<std::uint64_t> valueHistogram(const Grid<glm::vec3>&, double, double,
                                                          std::size_t);

} // namespace texsplat::volume
