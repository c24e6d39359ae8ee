#pragma once

#include "nodes/volume/Grid.h"

#include <array>
#include <bitset>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

namespace texsplat::volume {

/// @brief A block-sparse grid: only 8³ blocks that hold an active voxel are allocated, so memory
/// is proportional to the active voxels (as in OpenVDB's leaf nodes, which map onto the blocks
/// one to one when the OpenVDB reader passes the matching block offset).
///
/// A voxel is active once setValue() stored a value in it; inactive voxels read as the
/// background. An active voxel with a non-finite value is still empty (see Grid).
template <typename T>
class SparseGrid final : public Grid<T> {
public:
    /// @brief Edge length of a block, in voxels.
    static constexpr std::int64_t kBlockSize = 8;

    /// @brief An empty grid of `geometry`. Block boundaries lie where (index + blockOffset) is a
    /// multiple of kBlockSize; blockOffset components must be in [0, kBlockSize).
    explicit SparseGrid(const GridGeometry& geometry, const T& background = T(0.0f),
                        const glm::i64vec3& blockOffset = glm::i64vec3(0));

    /// @brief Stores `value` in voxel `index` (inside the grid) and makes it active.
    void setValue(const glm::i64vec3& index, const T& value);
    /// @brief The voxels of one block, x fastest, and which of them are active.
    struct BlockVoxels {
        std::array<T, 512> values;
        std::bitset<512> active;
    };
    /// @brief setValue() for the active voxels of a whole block at once (a reader's bulk copy):
    /// the block whose voxel (0,0,0) is `first`, a corner of the block lattice (first +
    /// blockOffset() a multiple of kBlockSize; it may lie outside the grid). Its active voxels
    /// must lie inside the grid.
    void setBlock(const glm::i64vec3& first, const BlockVoxels& voxels);
    /// @brief The offset passed to the constructor.
    const glm::i64vec3& blockOffset() const { return mBlockOffset; }
    /// @brief Number of allocated blocks.
    std::size_t blockCount() const { return mBlocks.size(); }
    /// @brief Number of active voxels (finite or not).
    std::int64_t activeVoxelCount() const;

    /// @copydoc Grid::value
    T value(const glm::i64vec3& index) const override;
    /// @copydoc Grid::isActive
    bool isActive(const glm::i64vec3& index) const override;
    /// @copydoc Grid::forEachStored
    void forEachStored(const typename Grid<T>::VoxelVisitor& visit) const override;
    /// @brief The blocks (of Grid::kBlockEdge, aligned at index 0) that an allocated block
    /// overlaps: up to 8 each when blockOffset() is not 0.
    std::vector<glm::i64vec3> occupiedBlocks() const override;
    /// @copydoc Grid::readBlock
    void readBlock(const glm::i64vec3& block, typename Grid<T>::VoxelBlock& out) const override;
    /// @copydoc Grid::statistics
    GridStatistics statistics() const override;
    /// @copydoc Grid::memoryBytes
    std::size_t memoryBytes() const override;
    /// @brief The active voxels (activeVoxelCount()).
    std::uint64_t storedVoxelCount() const override {
        return static_cast<std::uint64_t>(activeVoxelCount());
    }

    /// @brief What a grid of `blocks` allocated blocks costs (its memoryBytes()), saturating at
    /// the largest uint64: a loader checks it against memory before building the grid.
    static std::uint64_t memoryBytesForBlocks(std::uint64_t blocks);

private:
    static constexpr std::size_t kBlockVoxels = 512;
    struct Block : BlockVoxels {
        glm::i64vec3 first; // grid index of the block's voxel (0,0,0); may be negative
    };

    struct Location {
        std::int64_t key;   // which block, as a linear index over the block lattice
        glm::i64vec3 first; // grid index of that block's voxel (0,0,0)
        std::size_t slot;   // which voxel inside it, x fastest
    };

    Location locate(const glm::i64vec3& index) const;
    const Block* findBlock(const Location& location) const;
    Block& blockAt(const Location& location); // allocated if it is not yet

    glm::i64vec3 mBlockOffset;
    glm::i64vec3 mBlockDims;
    std::vector<std::unique_ptr<Block>> mBlocks;
    std::unordered_map<std::int64_t, std::size_t> mBlockByKey;
};

extern template class SparseGrid<float>;
extern template class SparseGrid<glm::vec3>;

/// @brief A sparse grid of float values.
using SparseScalarGrid = SparseGrid<float>;
/// @brief A sparse grid of 3D vectors.
using SparseVectorGrid = SparseGrid<glm::vec3>;

} // namespace texsplat::volume
