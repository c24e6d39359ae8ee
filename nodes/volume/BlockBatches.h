#pragma once

#include "nodes/volume/Grid.h"
#include "octree/ClassifiedGrid.h"
#include "scenegraph/WorkProgress.h"

#include <glm/vec2.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <string_view>
#include <vector>

namespace texsplat::volume {

// The blocks a grid reads are the classified grid's, the octree's and the value summaries'.
static_assert(Grid<float>::kBlockEdge ==
                  static_cast<std::int64_t>(octree::ClassifiedGrid::kBlockSize),
              "the grid's read blocks are the classified grid's blocks");

/// @brief Blocks worked on in parallel between two progress reports: 2^19 voxels, and what the
/// callers keep per block of a batch (8 MiB of classified blocks) until they take it.
inline constexpr std::size_t kBlocksPerBatch = 1024;

/// @brief Works through `blocks` (a grid's occupied blocks) a batch of kBlocksPerBatch at a time:
/// `work(slot, block)` for the batch's blocks in parallel (oneTBB; `slot` < kBlocksPerBatch is
/// the block's place in the batch, where `work` leaves its result), then `take(slot, block)` for
/// them in order, then tells `progress` (when set) `step` and the fraction done, which may cancel.
/// What is taken is the same for any number of threads.
/// @throws sg::Cancelled when `progress` cancels.
template <class Work, class Take>
void inBlockBatches(const std::vector<glm::i64vec3>& blocks, const sg::WorkProgress& progress,
                    std::string_view step, Work&& work, Take&& take) {
    sg::reportWork(progress, step, 0.0);
    for (std::size_t begin = 0; begin < blocks.size(); begin += kBlocksPerBatch) {
        const std::size_t count = std::min(kBlocksPerBatch, blocks.size() - begin);
        tbb::parallel_for(std::size_t{0}, count,
                          [&](std::size_t slot) { work(slot, blocks[begin + slot]); });
        for (std::size_t slot = 0; slot < count; ++slot) {
            take(slot, blocks[begin + slot]);
        }
        sg::reportWork(progress, step,
                       static_cast<double>(begin + count) / static_cast<double>(blocks.size()));
    }
    sg::reportWork(progress, step, 1.0);
}

/// @brief The smallest and largest of `voxels`' non-empty values (an empty range, min > max,
/// when there is none).
glm::vec2 valueRangeOf(const Grid<float>::VoxelBlock& voxels);

} // namespace texsplat::volume
