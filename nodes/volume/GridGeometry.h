#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/type_precision.hpp>

#include <cstdint>

namespace texsplat::volume {

/// @brief Where a regular grid's voxels lie: dimensions, the world position of voxel (0,0,0)
/// and the (possibly anisotropic) spacing between voxel centers.
///
/// Voxel (i,j,k) has its center at `origin + (i,j,k) * spacing` and owns the cell of one spacing
/// around it, so a one-voxel-thick grid still has a non-empty box. Voxels are stored x fastest,
/// then y, then z; every index computation is done in 64 bits so grids with more than 2^31
/// voxels are addressed correctly. Validation happens once, in the constructor, so an existing
/// geometry is always usable.
class GridGeometry {
public:
    /// @brief A grid of `dims` voxels.
    /// @throws DataError if a dimension is below 1 (a zero-size grid), the voxel count does not
    /// fit in a signed 64-bit integer, the spacing is not finite and positive, or the origin is
    /// not finite.
    explicit GridGeometry(const glm::i64vec3& dims, const glm::dvec3& origin = glm::dvec3(0.0),
                          const glm::dvec3& spacing = glm::dvec3(1.0));

    /// @brief Number of voxels along x, y and z (each at least 1).
    const glm::i64vec3& dims() const { return mDims; }
    /// @brief World position of the center of voxel (0,0,0).
    const glm::dvec3& origin() const { return mOrigin; }
    /// @brief World distance between neighbouring voxel centers along x, y and z.
    const glm::dvec3& spacing() const { return mSpacing; }
    /// @brief dims.x * dims.y * dims.z.
    std::int64_t voxelCount() const { return mDims.x * mDims.y * mDims.z; }

    /// @brief Whether (i,j,k) names a voxel of this grid.
    bool contains(const glm::i64vec3& index) const {
        return glm::all(glm::greaterThanEqual(index, glm::i64vec3(0))) &&
               glm::all(glm::lessThan(index, mDims));
    }
    /// @brief Position of voxel (i,j,k) in the x-fastest storage order.
    std::int64_t linearIndex(const glm::i64vec3& index) const {
        return index.x + mDims.x * (index.y + mDims.y * index.z);
    }
    /// @brief Inverse of linearIndex().
    glm::i64vec3 indexOf(std::int64_t linear) const;

    /// @brief World position of a (possibly fractional) voxel index; integers are voxel centers.
    glm::dvec3 indexToWorld(const glm::dvec3& index) const { return mOrigin + index * mSpacing; }
    /// @brief Fractional voxel index of a world position (inverse of indexToWorld()).
    glm::dvec3 worldToIndex(const glm::dvec3& world) const {
        return (world - mOrigin) / mSpacing;
    }
    /// @brief The voxel whose cell contains a world position (it may lie outside the grid).
    glm::i64vec3 nearestIndex(const glm::dvec3& world) const;

    /// @brief Low corner of the box the voxel cells cover: origin - spacing / 2.
    glm::dvec3 boundsMin() const { return mOrigin - 0.5 * mSpacing; }
    /// @brief High corner of the box the voxel cells cover: origin + (dims - 1/2) * spacing.
    glm::dvec3 boundsMax() const {
        return mOrigin + (glm::dvec3(mDims) - 0.5) * mSpacing;
    }

    /// @brief Same dimensions, origin and spacing.
    bool operator==(const GridGeometry& other) const {
        return mDims == other.mDims && mOrigin == other.mOrigin && mSpacing == other.mSpacing;
    }
    /// @brief Not operator==.
    bool operator!=(const GridGeometry& other) const { return !(*this == other); }

private:
    glm::i64vec3 mDims;
    glm::dvec3 mOrigin;
    glm::dvec3 mSpacing;
};

} // namespace texsplat::volume
