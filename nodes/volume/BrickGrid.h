#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/IndexBox.h"

#include <memory>
#include <vector>

namespace texsplat::volume {

/// @brief One brick of a grid split over processes (distributed rendering, docs/distributed.md):
/// the voxels of a box of another grid, read through without a copy, and what the brick knows of
/// the whole grid (whole()), so that data ranges are the whole grid's.
///
/// The box may be all of the other grid (a brick read from a file) or a part of it: a simulation's
/// block without its ghost cells, which another rank owns. Voxel (0, 0, 0) of the brick is voxel
/// `box.lo` of the other grid; the geometry places it there (boxGeometry()). statistics() are the
/// brick's own. The brick holds the other grid.
template <typename T> class BrickGrid final : public Grid<T> {
public:
    /// @brief The voxels of `box` of `voxels` (a non-empty box inside it), as a brick of a whole
    /// grid described by `whole`.
    /// @throws DataError when the box is empty or not inside `voxels`.
    BrickGrid(std::shared_ptr<const Grid<T>> voxels, const IndexBox& box,
              std::shared_ptr<const WholeGrid> whole);

    /// @brief The grid whose voxels these are.
    const std::shared_ptr<const Grid<T>>& voxels() const { return mVoxels; }
    /// @brief Where the brick lies in voxels().
    const IndexBox& box() const { return mBox; }

    /// @copydoc Grid::value
    T value(const glm::i64vec3& index) const override { return mVoxels->value(index + mBox.lo); }
    /// @copydoc Grid::isActive
    bool isActive(const glm::i64vec3& index) const override {
        return mVoxels->isActive(index + mBox.lo);
    }
    /// @copydoc Grid::forEachStored
    void forEachStored(const typename Grid<T>::VoxelVisitor& visit) const override;
    /// @brief The bytes of the grid read through (a brick holds no voxels of its own).
    std::size_t memoryBytes() const override { return mVoxels->memoryBytes(); }
    /// @copydoc Grid::storedVoxelCount
    std::uint64_t storedVoxelCount() const override;
    /// @copydoc Grid::occupiedBlocks
    std::vector<glm::i64vec3> occupiedBlocks() const override;
    /// @copydoc Grid::readBlock
    void readBlock(const glm::i64vec3& block, typename Grid<T>::VoxelBlock& out) const override;
    /// @copydoc Grid::statistics
    GridStatistics statistics() const override;
    /// @brief What the brick knows of the whole grid.
    const WholeGrid* whole() const override { return mWhole.get(); }

private:
    // Whether the brick is all of the other grid: then its blocks are the other grid's.
    bool isWholeOfVoxels() const { return mBox == IndexBox::of(mVoxels->geometry()); }

    std::shared_ptr<const Grid<T>> mVoxels;
    IndexBox mBox;
    std::shared_ptr<const WholeGrid> mWhole;
};

extern template class BrickGrid<float>;
extern template class BrickGrid<glm::vec3>;

} // namespace texsplat::volume
