#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/IndexBox.h"

#include <memory>
#include <vector>

namespace texsplat::distributed {

/// @brief The whole grid of a simulation as one of its ranks holds it: the voxels the rank owns,
/// where they lie in the whole grid, and none elsewhere. What an in-situ render gives the scene's
/// VolumeData on each rank (InSituRenderer): the grid is the whole one, as a scene expects, and
/// the rank's brick (VolumeData::setBrick()) is the box it owns, read through without a copy.
///
/// The block may hold more than the rank owns (ghost cells, copies of its neighbours' voxels):
/// only `owned` is the rank's, so that each voxel is drawn once.
template <typename T> class RankGrid final : public volume::Grid<T> {
public:
    /// @brief The grid of geometry `whole` whose voxels in `owned` (a box of the whole grid) are
    /// those of `block` (which holds them: its voxel 0 is whole voxel `blockOffset`); a rank
    /// that owns nothing gives an empty box and no block.
    RankGrid(const volume::GridGeometry& whole, std::shared_ptr<const volume::Grid<T>> block,
             const glm::i64vec3& blockOffset, const volume::IndexBox& owned);

    /// @brief The box of the whole grid this rank owns.
    const volume::IndexBox& owned() const { return mOwned; }

    /// @copydoc Grid::value
    T value(const glm::i64vec3& index) const override {
        return mOwned.contains(index) ? mBlock->value(index - mOffset) : this->background();
    }
    /// @copydoc Grid::isActive
    bool isActive(const glm::i64vec3& index) const override {
        return mOwned.contains(index) && mBlock->isActive(index - mOffset);
    }
    /// @copydoc Grid::forEachStored
    void forEachStored(const typename volume::Grid<T>::VoxelVisitor& visit) const override;
    /// @brief The block's bytes (the simulation's memory).
    std::size_t memoryBytes() const override { return mBlock ? mBlock->memoryBytes() : 0; }
    /// @brief The owned voxels.
    std::uint64_t storedVoxelCount() const override {
        return static_cast<std::uint64_t>(mOwned.voxelCount());
    }
    /// @brief The blocks that meet the owned box.
    std::vector<glm::i64vec3> occupiedBlocks() const override;
    /// @copydoc Grid::readBlock
    void readBlock(const glm::i64vec3& block,
                   typename volume::Grid<T>::VoxelBlock& out) const override;

private:
    std::shared_ptr<const volume::Grid<T>> mBlock;
    glm::i64vec3 mOffset;
    volume::IndexBox mOwned;
};

extern template class RankGrid<float>;
extern template class RankGrid<glm::vec3>;

} // namespace texsplat::distributed
