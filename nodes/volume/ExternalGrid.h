#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/detail/ContiguousVoxels.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace texsplat::volume {

/// @brief A grid that reads an application's voxel values where they are, without a copy: the
/// way a C++ code renders its own array (VolumeData::setGrid(), docs/embedding.md).
///
/// The values lie one after the other, x fastest, then y, then z, as DenseGrid stores its own:
/// a C-order array indexed [z][y][x] (NumPy's default for a (z, y, x) array), or a Fortran-order
/// one indexed (x, y, z). A NaN or infinite value is an empty voxel. For vectors, T is glm::vec3:
/// three floats x y z per voxel.
///
/// **Lifetime.** The grid does not own the values. Either pass an `owner` — any shared pointer
/// that keeps them alive (the `std::shared_ptr<std::vector<float>>` holding them, say) — and the
/// grid holds it; or pass none and keep the values alive yourself as long as the grid lives,
/// and so as long as any node that holds it (VolumeData keeps its grid until setGrid() replaces
/// it or the node is destroyed) and any render that uses it. **Changes.** Nodes cache what they
/// derive from a grid (the classified voxels, the octree) by the grid's identity: after changing
/// the values, give the node a new grid over them (`setGrid(std::make_shared<ExternalScalarGrid>
/// (…))`, again without a copy) and the next render derives everything anew. Changing the values
/// while a render runs is a data race.
template <typename T>
class ExternalGrid final : public Grid<T> {
public:
    /// @brief The grid of `geometry` over `values`, which must hold geometry.voxelCount() values.
    /// @throws DataError when `values` is null or `count` is not the voxel count.
    ExternalGrid(const GridGeometry& geometry, const T* values, std::size_t count,
                 std::shared_ptr<const void> owner = nullptr);

    /// @brief A grid owning `values` (moved in, not copied), held by a shared pointer.
    /// @throws DataError when values.size() is not the voxel count.
    static std::shared_ptr<const ExternalGrid> owning(const GridGeometry& geometry,
                                                      std::vector<T> values);

    /// @brief The values read, in linearIndex() order.
    const T* data() const { return mValues; }

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
    /// @brief The bytes of the values it reads (the application's memory, or its owner's).
    std::size_t memoryBytes() const override;

private:
    detail::ContiguousVoxels<T> voxels() const { return {this->geometry(), mValues}; }

    const T* mValues;
    std::shared_ptr<const void> mOwner;
};

extern template class ExternalGrid<float>;
extern template class ExternalGrid<glm::vec3>;

/// @brief A grid of the application's float values.
using ExternalScalarGrid = ExternalGrid<float>;
/// @brief A grid of the application's vectors.
using ExternalVectorGrid = ExternalGrid<glm::vec3>;

} // namespace texsplat::volume
