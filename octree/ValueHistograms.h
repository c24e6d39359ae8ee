#pragma once

#include "octree/ClassifiedGrid.h"

#include <glm/ext/vector_uint3_sized.hpp>
#include <glm/vec2.hpp>

#include <array>
#include <bitset>
#include <cstdint>
#include <vector>

namespace texsplat::octree {

/// @brief How a grid's *data* is distributed within each 8³ block (the blocks of
/// `ClassifiedGrid`), before any transfer function: the block's non-empty values sorted into
/// kBins equal bins over the block's own range, and per bin how many values fell in and their
/// mean. Like ValueRanges it depends on the data alone: made once per grid (when the first
/// transfer-function edit is previewed, volume::blockValueHistograms()), it serves every
/// function after.
///
/// What it is for: a transfer function gives a block's mean classification from it without
/// reading a voxel (TransferFunction::classifyBlockMeans(), the interactive preview of an edit;
/// docs/octree.md, "Transfer-function edits"): the sum over the bins of count × the function at
/// the bin's mean. That is exact where the function is linear over each bin's values (so where
/// each bin holds one distinct value, and for a function linear over the block's range)
/// and otherwise off by the function's bend within a bin, at most its variation over a
/// sixteenth of the block's range. 128 bytes per block holding a value.
class ValueHistograms {
public:
    /// @brief Bins per block.
    static constexpr int kBins = 16;

    /// @brief A block's values and which of them are non-empty, as the grids read them.
    using BlockValues = std::array<float, ClassifiedGrid::kBlockVoxels>;
    using BlockMask = std::bitset<ClassifiedGrid::kBlockVoxels>;

    /// @brief One block's summary.
    struct Block {
        glm::u64vec3 coordinates{0};              ///< block coordinates (voxel / 8)
        glm::vec2 range{0.0f};                    ///< smallest and largest non-empty value
        std::array<float, kBins> means{};         ///< mean value of each bin (0 when empty)
        std::array<std::uint16_t, kBins> counts{}; ///< values in each bin (at most 512)
    };

    /// @brief The summary of block @p coordinates from its voxels (x fastest, as the grids read
    /// blocks): the finite values where @p nonEmpty is set (at least one), whose smallest and
    /// largest are @p range (found by the caller in the same read).
    [[nodiscard]] static Block summarize(glm::u64vec3 coordinates, const BlockValues& values,
                                         const BlockMask& nonEmpty, glm::vec2 range);

    /// @brief Keeps @p block (any order; one block once).
    void add(const Block& block) { mBlocks.push_back(block); }

    /// @brief The blocks holding a value, in the order added.
    [[nodiscard]] const std::vector<Block>& blocks() const { return mBlocks; }

    /// @brief Bytes held.
    [[nodiscard]] std::uint64_t memoryBytes() const { return mBlocks.capacity() * sizeof(Block); }

private:
    std::vector<Block> mBlocks;
};

} // namespace texsplat::octree
