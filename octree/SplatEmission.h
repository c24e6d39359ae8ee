#pragma once

#include "octree/Fwd.h"

namespace texsplat::octree {

/// @brief Replaces the contents of @p splats by the splats of @p cut for @p view, back to front
/// (`traverseBackToFront()`): one splat per node, at the centre of the node's voxels, with the
/// node's mean colour and extinction, sized by the node's largest block edge in voxels (2^level
/// inside the grid; less where the block is clipped by the grid's far faces).
void emitSplats(const Cut& cut, const View& view, SplatList& splats);

/// @brief Replaces the contents of @p splats by one size-1 splat per non-empty voxel of
/// @p grid, back to front in `SliceOrder`; for a perspective view, voxels not in front of the
/// eye plane are culled.
void emitVoxelSplats(const ClassifiedGrid& grid, const View& view, SplatList& splats);

} // namespace texsplat::octree
