#pragma once

#include "octree/Fwd.h"

#include <glm/ext/vector_double3.hpp>

#include <array>
#include <cstdint>

namespace texsplat::octree {

/// @brief How deep a classified grid's non-empty voxels lie along a line of sight: their count
/// over the area of the shadow they cast, in voxels. What vector splats spread their marks by, so
/// that the marks cover the image as densely whatever the depth of the data behind a pixel
/// (docs/vector-splats.md, "How many marks").
///
/// The shadow along a direction d is estimated from the three axis-aligned shadows (the columns
/// along x, y and z that hold a non-empty voxel): A(d) = Σ_a |d_a| · columns_a · the area of a
/// voxel's face across axis a, exact for a box and for any union of columns along the axes.
class VoxelShadows {
public:
    /// @brief The shadows of `grid`'s non-empty voxels, in one parallel pass over its blocks.
    explicit VoxelShadows(const ClassifiedGrid& grid);

    /// @brief Shadows counted elsewhere: `columns` along x, y, z holding a non-empty voxel and
    /// `voxels` non-empty voxels of a grid of `spacing` (a grid split over processes, whose
    /// bricks' columns are merged: nodes/distributed).
    VoxelShadows(const std::array<std::uint64_t, 3>& columns, std::uint64_t voxels,
                 const glm::dvec3& spacing)
        : mColumns(columns), mVoxels(voxels), mSpacing(spacing) {}

    /// @brief Columns along axis `axis` (0: x, 1: y, 2: z) holding a non-empty voxel.
    [[nodiscard]] std::uint64_t columns(int axis) const {
        return mColumns[static_cast<std::size_t>(axis)];
    }

    /// @brief Non-empty voxels.
    [[nodiscard]] std::uint64_t voxels() const { return mVoxels; }

    /// @brief The mean number of non-empty voxels behind a point of their shadow seen along
    /// `direction` (the grid's index space scaled by its spacing, i.e. world directions of the
    /// grid; any length): voxels · h² / A(direction), h the spacing's geometric mean (a lone
    /// voxel seen along a diagonal: 1/√3, its shadow being a hexagon of area √3); 0 for an
    /// empty grid or a zero direction.
    [[nodiscard]] double meanDepth(const glm::dvec3& direction) const;

private:
    std::array<std::uint64_t, 3> mColumns{};
    std::uint64_t mVoxels = 0;
    glm::dvec3 mSpacing{1.0};
};

} // namespace texsplat::octree
