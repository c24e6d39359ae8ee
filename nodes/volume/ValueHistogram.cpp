#include "nodes/volume/ValueHistogram.h"

#include "scenegraph/Assert.h"

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <optional>

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

octree::ValueHistograms blockValueHistograms(const Grid<float>& grid,
                                             const sg::WorkProgress& progress) {
    static_assert(Grid<float>::kBlockEdge ==
                      static_cast<std::int64_t>(octree::ClassifiedGrid::kBlockSize),
                  "the grid's read blocks are the histograms' blocks");
    constexpr const char* kStep = "summarizing the data's blocks";
    // Blocks read in parallel between two progress reports (2^19 voxels).
    constexpr std::size_t kBlocksPerBatch = 1024;
    const std::vector<glm::i64vec3> blocks = grid.occupiedBlocks();
    std::vector<std::optional<octree::ValueHistograms::Block>> batch(
        std::min(blocks.size(), kBlocksPerBatch));
    octree::ValueHistograms histograms;
    sg::reportWork(progress, kStep, 0.0);
    for (std::size_t begin = 0; begin < blocks.size(); begin += kBlocksPerBatch) {
        const std::size_t count = std::min(kBlocksPerBatch, blocks.size() - begin);
        tbb::parallel_for(std::size_t{0}, count, [&](std::size_t i) {
            typename Grid<float>::VoxelBlock voxels;
            grid.readBlock(blocks[begin + i], voxels);
            batch[i] = octree::ValueHistograms::summarize(glm::u64vec3(blocks[begin + i]),
                                                          voxels.values, voxels.nonEmpty);
        });
        for (std::size_t i = 0; i < count; ++i) {
            if (batch[i]) {
                histograms.add(*batch[i]);
            }
        }
        sg::reportWork(progress, kStep,
                       static_cast<double>(begin + count) / static_cast<double>(blocks.size()));
    }
    sg::reportWork(progress, kStep, 1.0);
    return histograms;
}

} // namespace texsplat::volume
