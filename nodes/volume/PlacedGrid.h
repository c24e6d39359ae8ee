#pragma once

#include "nodes/volume/Grid.h"

#include <memory>

namespace texsplat::volume {

/// @brief Another grid's voxels, placed elsewhere: the same dimensions and values, another origin
/// and spacing. What VolumeData's `origin` and `spacing` make of any source, without a copy, so
/// that data that comes without geometry (a NumPy array, headerless raw) lines up with data that
/// has it (a NetCDF file's coordinates): winds over clouds.
///
/// Every voxel, block and statistic is the placed grid's (`placed()`), read through; the grid
/// holds it.
template <typename T>
class PlacedGrid final : public Grid<T> {
public:
    /// @brief `placed`'s voxels at `geometry`, which must have the same dimensions.
    /// @throws DataError when the dimensions differ.
    PlacedGrid(std::shared_ptr<const Grid<T>> placed, const GridGeometry& geometry);

    /// @brief The grid whose voxels these are.
    const std::shared_ptr<const Grid<T>>& placed() const { return mPlaced; }

    /// @copydoc Grid::value
    T value(const glm::i64vec3& index) const override { return mPlaced->value(index); }
    /// @copydoc Grid::isActive
    bool isActive(const glm::i64vec3& index) const override { return mPlaced->isActive(index); }
    /// @copydoc Grid::forEachStored
    void forEachStored(const typename Grid<T>::VoxelVisitor& visit) const override {
        mPlaced->forEachStored(visit);
    }
    /// @brief The placed grid's bytes (a placed grid holds no voxels of its own).
    std::size_t memoryBytes() const override { return mPlaced->memoryBytes(); }
    /// @copydoc Grid::storedVoxelCount
    std::uint64_t storedVoxelCount() const override { return mPlaced->storedVoxelCount(); }
    /// @copydoc Grid::occupiedBlocks
    std::vector<glm::i64vec3> occupiedBlocks() const override {
        return mPlaced->occupiedBlocks();
    }
    /// @copydoc Grid::readBlock
    void readBlock(const glm::i64vec3& block,
                   typename Grid<T>::VoxelBlock& out) const override {
        mPlaced->readBlock(block, out);
    }
    /// @copydoc Grid::statistics
    GridStatistics statistics() const override { return mPlaced->statistics(); }
    /// @copydoc Grid::whole
    const WholeGrid* whole() const override { return mPlaced->whole(); }

private:
    std::shared_ptr<const Grid<T>> mPlaced;
};

extern template class PlacedGrid<float>;
extern template class PlacedGrid<glm::vec3>;

} // namespace texsplat::volume
