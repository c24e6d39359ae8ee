#pragma once

#include "scenegraph/Assert.h"

#include <glm/ext/vector_double3.hpp>
#include <glm/ext/vector_uint3_sized.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace texsplat::octree {

/// @brief A voxel grid after classification by a transfer function: per voxel a colour (RGB,
/// per unit length, ready to be premultiplied) and an extinction coefficient tau (opacity per
/// unit length). This is the input of the octree and of full-resolution splatting.
///
/// Voxel (i, j, k) is a sample at `origin + spacing * (i, j, k)`; its cell, the box a splat of
/// it stands for, is that point +- spacing / 2. Dimensions and indices are 64-bit; the linear
/// index is `i + nx * (j + ny * k)`. A voxel whose colour and extinction are all zero is empty
/// and produces no splat (docs/design.md: "no splats for transparent voxels").
class ClassifiedGrid {
public:
    /// @brief A grid of @p dims voxels, all empty.
    /// @throws DataError when a dimension is zero, the voxel count does not fit in memory
    /// addressing, a spacing is not finite and positive, or the origin is not finite.
    ClassifiedGrid(glm::u64vec3 dims, glm::dvec3 spacing, glm::dvec3 origin);

    /// @brief Sets voxel @p ijk (which must lie inside the grid).
    /// @throws DataError when a colour channel or the extinction is negative or not finite.
    void setVoxel(glm::u64vec3 ijk, glm::vec3 color, float extinction);

    /// @brief Gives every voxel a vector, all zero until setVector(): the flow that vector splats
    /// draw as marks (Crawfis & Max 1993, "Combined Vector and Scalar Textures"). Scalar grids have
    /// none and pay nothing for it (12 more bytes per voxel when enabled).
    void enableVectors();

    /// @brief Whether enableVectors() was called.
    [[nodiscard]] bool hasVectors() const { return !mVectors.empty(); }

    /// @brief Sets the vector of voxel @p ijk, in the grid's (local) space; needs hasVectors().
    /// @throws DataError when a component is not finite.
    void setVector(glm::u64vec3 ijk, glm::vec3 vector);

    /// @brief The vector of the voxel with linear index @p index (hasVectors() must hold).
    [[nodiscard]] glm::vec3 vector(std::uint64_t index) const {
        TEXSPLAT_ASSERT(index < mVectors.size(), "ClassifiedGrid::vector(): no vector there");
        return mVectors[static_cast<std::size_t>(index)];
    }

    /// @brief Colour (xyz) and extinction (w) of the voxel with linear index @p index.
    [[nodiscard]] glm::vec4 voxel(std::uint64_t index) const {
        TEXSPLAT_ASSERT(index < mVoxels.size(), "ClassifiedGrid::voxel(): index outside the grid");
        return mVoxels[static_cast<std::size_t>(index)];
    }

    /// @brief Whether the voxel with linear index @p index is empty (all four values zero).
    [[nodiscard]] bool isEmptyVoxel(std::uint64_t index) const {
        return voxel(index) == glm::vec4(0.0f);
    }

    /// @brief Linear index of voxel @p ijk.
    [[nodiscard]] std::uint64_t index(glm::u64vec3 ijk) const {
        return ijk.x + mDims.x * (ijk.y + mDims.y * ijk.z);
    }

    /// @brief World position of a point given in voxel index coordinates (voxel centres are
    /// at integer coordinates).
    [[nodiscard]] glm::dvec3 toWorld(glm::dvec3 indexPosition) const {
        return mOrigin + mSpacing * indexPosition;
    }

    /// @brief Number of voxels along x, y, z.
    [[nodiscard]] glm::u64vec3 dims() const { return mDims; }

    /// @brief Distance between neighbouring voxel centres along x, y, z.
    [[nodiscard]] glm::dvec3 spacing() const { return mSpacing; }

    /// @brief World position of voxel (0, 0, 0).
    [[nodiscard]] glm::dvec3 origin() const { return mOrigin; }

    /// @brief Total number of voxels.
    [[nodiscard]] std::uint64_t voxelCount() const { return mDims.x * mDims.y * mDims.z; }

private:
    glm::u64vec3 mDims;
    glm::dvec3 mSpacing;
    glm::dvec3 mOrigin;
    std::vector<glm::vec4> mVoxels;
    std::vector<glm::vec3> mVectors;
};

} // namespace texsplat::octree
