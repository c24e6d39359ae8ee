#pragma once

#include "octree/Fwd.h"
#include "octree/Splat.h"

#include <vector>

namespace texsplat::octree {

/// @brief Replaces the contents of @p splats by the splats of @p cut for @p view, back to front
/// (`traverseBackToFront()`): one splat per node, at the centre of the node's voxels, with the
/// node's mean colour and extinction, sized by the node's largest block edge in voxels (2^level
/// inside the grid; less where the block is clipped by the grid's far faces). For a view with
/// sides (View::seeingOnly()) the nodes out of sight are left out.
void emitSplats(const Cut& cut, const View& view, SplatList& splats);

/// @brief Replaces the contents of @p splats by one size-1 splat per non-empty voxel of
/// @p grid, back to front in `SliceOrder`; for a perspective view, voxels not in front of the
/// eye plane are culled, and for a view with sides (View::seeingOnly()) the blocks whose voxels'
/// splats are all out of sight (SliceOrder skips them).
///
/// With @p marks (combined splats: MarkSource), the list also carries them, each after the last
/// splat of its voxel's slice, farther first: drawn over its slice and the slices behind, under
/// the slices in front. A mark behind the eye, or with no splat in its slice or behind, is left
/// out.
void emitVoxelSplats(const ClassifiedGrid& grid, const View& view, SplatList& splats,
                     const std::vector<SplatMark>* marks = nullptr);

} // namespace texsplat::octree
