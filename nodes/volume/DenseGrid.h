#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/detail/ContiguousVoxels.h"
#include "scenegraph/Assert.h"

#include <vector>

namespace texsplat::volume {

/// @brief A grid that stores every voxel, x fastest (the layout of raw files and generators).
///
/// Memory is dims.x * dims.y * dims.z * sizeof(T); a voxel is empty only when its value is not
/// finite. The background of a dense grid is zero.
template <typename T>
class DenseGrid final : public Grid<T> {
public:
    /// @brief A grid of `geometry` with every voxel set to `fill`.
    /// @throws DataError if the voxel count cannot be held in memory on this platform.
    explicit DenseGrid(const GridGeometry& geometry, const T& fill = T(0.0f));

    /// @brief A grid of `geometry` holding `values`, one per voxel in linearIndex() order, taken
    /// without a copy (a reader's buffer becomes the grid: no second grid's worth at its peak).
    DenseGrid(const GridGeometry& geometry, std::vector<T> values);

    /// @brief Sets voxel `index` (inside the grid); a non-finite value makes the voxel empty.
    void setValue(const glm::i64vec3& index, const T& value) {
        TEXSPLAT_ASSERT(this->geometry().contains(index), "DenseGrid::setValue(): index outside");
        mValues[static_cast<std::size_t>(this->geometry().linearIndex(index))] = value;
    }
    /// @brief All voxels in linearIndex() order, for bulk reading.
    const std::vector<T>& values() const { return mValues; }
    /// @brief All voxels in linearIndex() order, for bulk filling by sources.
    std::vector<T>& values() { return mValues; }

    /// @copydoc Grid::value
    T value(const glm::i64vec3& index) const override;
    /// @copydoc Grid::isActive
    bool isActive(const glm::i64vec3& index) const override;
    /// @copydoc Grid::forEachStored
    void forEachStored(const typename Grid<T>::VoxelVisitor& visit) const override;
    /// @copydoc Grid::statistics
    GridStatistics statistics() const override { return voxels().statistics(); }
    /// @copydoc Grid::readBlock
    void readBlock(const glm::i64vec3& block,
                   typename Grid<T>::VoxelBlock& out) const override {
        voxels().readBlock(block, out);
    }
    /// @copydoc Grid::memoryBytes
    std::size_t memoryBytes() const override { return mValues.capacity() * sizeof(T); }

private:
    detail::ContiguousVoxels<T> voxels() const { return {this->geometry(), mValues.data()}; }

    std::vector<T> mValues;
};

extern template class DenseGrid<float>;
extern template class DenseGrid<glm::vec3>;

/// @brief A dense grid of float values.
using DenseScalarGrid = DenseGrid<float>;
/// @brief A dense grid of 3D vectors.
using DenseVectorGrid = DenseGrid<glm::vec3>;

} // namespace texsplat::volume
