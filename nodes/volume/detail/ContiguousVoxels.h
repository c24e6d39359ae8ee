#pragma once

#include "nodes/volume/Grid.h"
#include "scenegraph/Assert.h"

#include <cstddef>

namespace texsplat::volume::detail {

/// @brief The Grid interface over voxel values laid out one after the other, x fastest, then y,
/// then z (GridGeometry::linearIndex()): shared by the grid that owns its values (DenseGrid) and
/// the one that reads an application's (ExternalGrid). A non-finite value is an empty voxel.
template <typename T> struct ContiguousVoxels {
    const GridGeometry& geometry;
    const T* values;

    /// @brief Grid::value(): the voxel's value, or `background` when it is empty.
    T value(const glm::i64vec3& index, const T& background) const {
        TEXSPLAT_ASSERT(geometry.contains(index), "Grid::value(): index outside the grid");
        const T& stored = values[static_cast<std::size_t>(geometry.linearIndex(index))];
        return isFiniteValue(stored) ? stored : background;
    }

    /// @brief Grid::isActive(): whether the voxel's value is finite.
    bool isActive(const glm::i64vec3& index) const {
        TEXSPLAT_ASSERT(geometry.contains(index), "Grid::isActive(): index outside the grid");
        return isFiniteValue(values[static_cast<std::size_t>(geometry.linearIndex(index))]);
    }

    /// @brief Grid::readBlock(): rows of up to 8 values copied, the finite ones non-empty.
    void readBlock(const glm::i64vec3& block, typename Grid<T>::VoxelBlock& out) const {
        constexpr std::int64_t kEdge = Grid<T>::kBlockEdge;
        out.nonEmpty.reset();
        const glm::i64vec3 first = block * kEdge;
        const glm::i64vec3 last = glm::min(first + kEdge, geometry.dims());
        for (std::int64_t z = first.z; z < last.z; ++z) {
            for (std::int64_t y = first.y; y < last.y; ++y) {
                const T* row = values + geometry.linearIndex({first.x, y, z});
                const auto slot =
                    static_cast<std::size_t>(kEdge * ((y - first.y) + kEdge * (z - first.z)));
                for (std::int64_t x = 0; x < last.x - first.x; ++x) {
                    const auto i = static_cast<std::size_t>(x);
                    out.values[slot + i] = row[i];
                    out.nonEmpty[slot + i] = isFiniteValue(row[i]);
                }
            }
        }
    }

    /// @brief Grid::forEachStored(): every voxel in storage order.
    void forEachStored(const typename Grid<T>::VoxelVisitor& visit) const {
        const glm::i64vec3& dims = geometry.dims();
        std::size_t linear = 0;
        glm::i64vec3 index;
        for (index.z = 0; index.z < dims.z; ++index.z)
            for (index.y = 0; index.y < dims.y; ++index.y)
                for (index.x = 0; index.x < dims.x; ++index.x)
                    visit(index, values[linear++]);
    }
};

} // namespace texsplat::volume::detail
