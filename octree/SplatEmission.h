#pragma once

#include "octree/Fwd.h"
#include "octree/Splat.h"

#include <glm/ext/vector_uint3_sized.hpp>
#include <glm/vec3.hpp>

#include <cstdint>

namespace texsplat::octree {

/// @brief What vector splats need at emission: how many marks each splat carries and the seed
/// they are drawn from (docs/vector-splats.md, "How many marks").
///
/// A splat standing for n non-empty voxels (1 for a voxel's, the node's count on coarser cuts)
/// carries on average `marksPerVoxel` · n marks, at most kMaxMarksPerSplat, each in the cell of
/// one of those voxels with its vector and medium: a coarse cut draws the marks the
/// full-resolution image draws, as many and alike, only not the same ones. The whole part of
/// the mean is always drawn, the fraction with that probability.
struct MarkEmission {
    /// @brief Expected marks of a voxel, >= 0 (the node chooses it so that the marks cover the
    /// image as densely as asked, whatever the data's depth).
    double marksPerVoxel = 0.0;
    /// @brief The marks are reproducible from it (and from each splat's voxel or node).
    std::uint32_t seed = 1;

    /// @brief The most marks one splat carries (a coarse node of thin data may stand for more).
    static constexpr int kMaxMarksPerSplat = 64;

    /// @brief The expected number of marks of a splat standing for `voxels` non-empty voxels:
    /// min(marksPerVoxel · voxels, kMaxMarksPerSplat).
    double expectedMarks(std::uint64_t voxels) const;
};

/// @brief The marks of the splat of the voxel @p voxel of @p grid: their count drawn from
/// @p emission and the voxel's index, each at a random point of the voxel's cell with the
/// voxel's vector, extinction and colour. None where the vector is zero (or not finite). Writes
/// them to @p out (room for MarkEmission::kMaxMarksPerSplat) and returns how many.
int voxelMarks(const MarkEmission& emission, const ClassifiedGrid& grid, glm::u64vec3 voxel,
               SplatMark* out);

/// @brief The marks of the splat of @p node of @p octree (a voxel at level 0, as voxelMarks()):
/// each in the cell of a non-empty voxel of the node, chosen at random among them all (the
/// children weighted by their non-empty voxels from the node down), with that voxel's own
/// vector and medium, so that no mark falls outside the data and each follows the flow where
/// it sits. A mark whose voxel has a zero vector (combined splats: voxels without a vector)
/// keeps it and draws nothing.
int nodeMarks(const MarkEmission& emission, const Octree& octree, const NodeRef& node,
              SplatMark* out);

/// @brief Replaces the contents of @p splats by the splats of @p cut for @p view, back to front
/// (`traverseBackToFront()`): one splat per node, at the centre of the node's voxels, with the
/// node's mean colour and extinction, sized by the node's largest block edge in voxels (2^level
/// inside the grid; less where the block is clipped by the grid's far faces). For a view with
/// sides (View::seeingOnly()) the nodes out of sight are left out. With @p vectors (the grid
/// must have vectors) each splat also carries its marks (nodeMarks()).
void emitSplats(const Cut& cut, const View& view, SplatList& splats,
                const MarkEmission* marks = nullptr);

/// @brief Replaces the contents of @p splats by one size-1 splat per non-empty voxel of
/// @p grid, back to front in `SliceOrder`; for a perspective view, voxels not in front of the
/// eye plane are culled, and for a view with sides (View::seeingOnly()) the blocks whose voxels'
/// splats are all out of sight (SliceOrder skips them). With @p marks, each splat also carries
/// its marks (voxelMarks()).
void emitVoxelSplats(const ClassifiedGrid& grid, const View& view, SplatList& splats,
                     const MarkEmission* marks = nullptr);

} // namespace texsplat::octree
