#pragma once

#include "octree/ClassifiedGrid.h"
#include "octree/Fwd.h"
#include "octree/Splat.h"
#include "octree/View.h"

#include <glm/ext/vector_uint3_sized.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <vector>

namespace texsplat::octree {

/// @brief Replaces the contents of @p splats by the splats of @p cut for @p view, back to front
/// (`traverseBackToFront()`): one splat per node, at the centre of the node's voxels, with the
/// node's mean colour and extinction, sized by the node's largest block edge in voxels (2^level
/// inside the grid; less where the block is clipped by the grid's far faces). For a view with
/// sides (View::seeingOnly()) the nodes out of sight are left out.
void emitSplats(const Cut& cut, const View& view, SplatList& splats);

/// @brief Which voxels of a grid make splats at full resolution for a view: the non-empty ones,
/// less, for a perspective view, those not in front of the eye plane.
class DrawnVoxels {
public:
    /// @brief The drawn voxels of @p grid (which must outlive this) for @p view.
    DrawnVoxels(const ClassifiedGrid& grid, const View& view);

    /// @brief The grid.
    [[nodiscard]] const ClassifiedGrid& grid() const { return *mGrid; }

    /// @brief Whether some voxel centre may lie behind the eye plane (a perspective view with
    /// the eye near or among them): then each is tested.
    [[nodiscard]] bool cullsBehindEye() const { return mCullsBehindEye; }

    /// @brief Whether voxel @p voxel, stored at @p stored, makes a splat.
    [[nodiscard]] bool isDrawn(glm::u64vec3 voxel, ClassifiedGrid::StorageIndex stored) const {
        return mGrid->storedVoxel(stored) != glm::vec4(0.0f) &&
               !(mCullsBehindEye && isBehindEye(voxel));
    }

private:
    bool isBehindEye(glm::u64vec3 voxel) const;

    const ClassifiedGrid* mGrid;
    View mView;
    bool mCullsBehindEye;
};

/// @brief The splat of voxel @p voxel of @p grid (stored at @p stored): size 1 at the voxel's
/// centre, with its colour and extinction.
[[nodiscard]] Splat voxelSplat(const ClassifiedGrid& grid, glm::u64vec3 voxel,
                               ClassifiedGrid::StorageIndex stored);

/// @brief Replaces the contents of @p splats by one size-1 splat per non-empty voxel of
/// @p grid (voxelSplat()), back to front in `SliceOrder`; for a perspective view, voxels not in
/// front of the eye plane are culled, and for a view with sides (View::seeingOnly()) the blocks
/// whose voxels' splats are all out of sight (SliceOrder skips them): the DrawnVoxels.
///
/// With @p marks (combined splats: MarkSource), the list also carries them, each after the last
/// splat of its voxel's slice, farther first: drawn over its slice and the slices behind, under
/// the slices in front. A mark behind the eye, or with no splat in its slice or behind, is left
/// out.
void emitVoxelSplats(const ClassifiedGrid& grid, const View& view, SplatList& splats,
                     const std::vector<SplatMark>* marks = nullptr);

/// @brief emitVoxelSplats() without marks of slices [@p sliceBegin, @p sliceEnd) of @p order
/// alone, voxels as @p drawn says (of the same grid and view): a piece of the whole list, the
/// pieces of consecutive ranges end to end being the whole.
void emitVoxelSplats(const SliceOrder& order, const DrawnVoxels& drawn, std::size_t sliceBegin,
                     std::size_t sliceEnd, SplatList& splats);

} // namespace texsplat::octree
