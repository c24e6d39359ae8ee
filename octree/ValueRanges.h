#pragma once

#include "octree/ClassifiedGrid.h"
#include "scenegraph/Assert.h"

#include <glm/ext/vector_uint3_sized.hpp>
#include <glm/vec2.hpp>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace texsplat::octree {

/// @brief What a grid's *data* holds per 8³ block (the octree's nodes of level 3, the blocks of
/// `ClassifiedGrid`), before any transfer function: the smallest and largest value of the block's
/// non-empty voxels. It depends on the data alone, so it is made once per grid and serves every
/// transfer function: a block whose whole value range a transfer function maps to nothing holds
/// no visible voxel, and classification skips it without reading its voxels' classification
/// (docs/octree.md, "Transfer-function edits").
///
/// Made by add() for every non-empty voxel; 4 bytes per block of the box (the block table) and
/// 8 bytes per block that holds a value.
class ValueRanges {
public:
    /// @brief No value yet, for a grid of @p dims voxels.
    /// @throws DataError when the block table does not fit in memory addressing.
    explicit ValueRanges(glm::u64vec3 dims);

    /// @brief Widens the range of the block of voxel @p ijk (inside the grid) by @p value, a
    /// finite value of a non-empty voxel.
    void add(glm::u64vec3 ijk, float value) {
        const std::size_t block = blockIndex(ijk);
        // Grids are walked block by block: the previous voxel's block is the likely one.
        if (block != mLastBlock) {
            std::uint32_t& slot = mSlots[block];
            if (slot == kNoBlock) {
                slot = static_cast<std::uint32_t>(mRanges.size());
                mRanges.emplace_back(value, value);
            }
            mLastBlock = block;
            mLastSlot = slot;
        }
        glm::vec2& range = mRanges[mLastSlot];
        range.x = value < range.x ? value : range.x;
        range.y = value > range.y ? value : range.y;
    }

    /// @brief Widens the range of block @p block (block coordinates) by @p range, the smallest
    /// and largest of some of its non-empty voxels' values: add() for a whole block at once.
    void addBlock(glm::u64vec3 block, glm::vec2 range) {
        std::uint32_t& slot = mSlots[blockIndex(block * ClassifiedGrid::kBlockSize)];
        if (slot == kNoBlock) {
            slot = static_cast<std::uint32_t>(mRanges.size());
            mRanges.push_back(range);
            return;
        }
        glm::vec2& stored = mRanges[slot];
        stored = glm::vec2(std::min(stored.x, range.x), std::max(stored.y, range.y));
    }

    /// @brief The smallest and largest value added (0, 0 when none was), over all blocks.
    [[nodiscard]] glm::vec2 valueRange() const;

    /// @brief Number of blocks holding a value.
    [[nodiscard]] std::size_t blockCount() const { return mRanges.size(); }

    /// @brief For every block holding a value, in the order blocks were first added: whether
    /// `isVisible(float minimum, float maximum)` holds for its value range. The answer is indexed
    /// like isVisibleBlock() reads it.
    template <typename IsVisible>
    [[nodiscard]] std::vector<bool> visibleBlocks(IsVisible&& isVisible) const {
        std::vector<bool> visible(mRanges.size());
        for (std::size_t slot = 0; slot < mRanges.size(); ++slot) {
            visible[slot] = isVisible(mRanges[slot].x, mRanges[slot].y);
        }
        return visible;
    }

    /// @brief Whether the block of voxel @p ijk is visible in @p visible (from visibleBlocks()):
    /// false for a block that holds no value.
    [[nodiscard]] bool isVisibleBlock(const std::vector<bool>& visible, glm::u64vec3 ijk) const {
        const std::uint32_t slot = mSlots[blockIndex(ijk)];
        return slot != kNoBlock && visible[slot];
    }

    /// @brief What the value ranges of a grid of @p dims with @p blocks blocks holding a value
    /// take (memoryBytes() without the growth reserve), saturating at the largest uint64: for an
    /// estimate before classifying.
    [[nodiscard]] static std::uint64_t memoryBytesFor(glm::u64vec3 dims, std::uint64_t blocks);

    /// @brief Bytes held.
    [[nodiscard]] std::uint64_t memoryBytes() const {
        return mSlots.capacity() * sizeof(std::uint32_t) + mRanges.capacity() * sizeof(glm::vec2);
    }

private:
    static constexpr std::uint32_t kNoBlock = 0xffffffffu;

    [[nodiscard]] std::size_t blockIndex(glm::u64vec3 ijk) const {
        TEXSPLAT_ASSERT(ijk.x < mDims.x && ijk.y < mDims.y && ijk.z < mDims.z,
                        "ValueRanges: voxel outside the grid");
        const glm::u64vec3 block = ijk / ClassifiedGrid::kBlockSize;
        return static_cast<std::size_t>(block.x +
                                        mBlockDims.x * (block.y + mBlockDims.y * block.z));
    }

    glm::u64vec3 mDims;
    glm::u64vec3 mBlockDims;
    std::vector<std::uint32_t> mSlots; // per block of the box: its slot in mRanges, or kNoBlock
    std::vector<glm::vec2> mRanges;    // (minimum, maximum) per block holding a value
    std::size_t mLastBlock = std::numeric_limits<std::size_t>::max(); // add()'s last block
    std::uint32_t mLastSlot = kNoBlock;
};

} // namespace texsplat::octree
