#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/detail/StatisticsAccumulator.h"
#include "scenegraph/Assert.h"

#include <bitset>
#include <cstddef>
#include <cstdint>

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

    /// @brief Grid::readBlock(): rows of up to 8 values copied, the finite ones non-empty. The
    /// flags of one z slice of the block (8 rows of 8) gather in a word first: setting 512 bits
    /// one by one cost more than the copy.
    void readBlock(const glm::i64vec3& block, typename Grid<T>::VoxelBlock& out) const {
        constexpr std::int64_t kEdge = Grid<T>::kBlockEdge;
        static_assert(kEdge * kEdge == 64, "one 64-bit word of flags per z slice");
        const glm::i64vec3 first = block * kEdge;
        const glm::i64vec3 last = glm::min(first + kEdge, geometry.dims());
        const auto width = static_cast<std::size_t>(last.x - first.x);
        std::bitset<512> nonEmpty;
        for (std::int64_t z = first.z; z < last.z; ++z) {
            std::uint64_t slice = 0;
            for (std::int64_t y = first.y; y < last.y; ++y) {
                const T* row = values + geometry.linearIndex({first.x, y, z});
                const auto rowInSlice = static_cast<std::size_t>(kEdge * (y - first.y));
                const auto slot = rowInSlice + static_cast<std::size_t>(kEdge * kEdge * (z - first.z));
                slice |= (width == kEdge ? copyRow<kEdge>(row, &out.values[slot])
                                         : copyRow(row, &out.values[slot], width))
                         << rowInSlice;
            }
            nonEmpty |= std::bitset<512>(slice) << static_cast<std::size_t>(64 * (z - first.z));
        }
        out.nonEmpty = nonEmpty;
    }

    /// @brief Copies `width` values of `row` to `out`; returns a bit per value, set if finite.
    /// With the width a constant (a whole row of a block) the loop is unrolled, not a memmove.
    template <std::size_t kWidth = 0>
    static std::uint64_t copyRow(const T* row, T* out, std::size_t width = kWidth) {
        std::uint64_t finite = 0;
        for (std::size_t x = 0; x < (kWidth > 0 ? kWidth : width); ++x) {
            out[x] = row[x];
            finite |= std::uint64_t{isFiniteValue(row[x])} << x;
        }
        return finite;
    }

    /// @brief Grid::statistics(): the values walked directly (a raw file's load checks them).
    GridStatistics statistics() const {
        StatisticsAccumulator<T> statistics;
        const auto count = static_cast<std::size_t>(geometry.voxelCount());
        for (std::size_t i = 0; i < count; ++i) {
            statistics.add(values[i]);
        }
        return statistics.result();
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
