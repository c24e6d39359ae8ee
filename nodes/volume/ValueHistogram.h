#pragma once

#include "nodes/volume/Grid.h"
#include "octree/ValueHistograms.h"
#include "scenegraph/WorkProgress.h"

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

/// @brief The value histogram of every 8³ block of `grid` that holds a value
/// (octree::ValueHistograms): one walk over the grid's occupied blocks, in parallel batches
/// (inBlockBatches()), in their order for any number of threads. `progress` (when set) hears "summarizing
/// the data's blocks" and the fraction done, and may cancel.
/// @throws sg::Cancelled when `progress` cancels.
octree::ValueHistograms blockValueHistograms(const Grid<float>& grid,
                                             const sg::WorkProgress& progress = {});

} // namespace texsplat::volume
