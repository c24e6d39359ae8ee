#pragma once

#include "octree/ClassifiedGrid.h"
#include "octree/SliceOrder.h"
#include "octree/Splat.h"
#include "octree/SplatEmission.h"
#include "octree/View.h"

#include <cstdint>
#include <memory>
#include <mutex>

namespace texsplat::octree {

/// @brief The splats of a grid at full resolution for a view, described rather than listed: one
/// of size 1 per drawn voxel (DrawnVoxels), back to front in SliceOrder, exactly what
/// emitVoxelSplats() lists.
///
/// A full-resolution frame of a regular grid needs no list of 32-byte splats: the classified
/// grid holds each voxel's medium and the slice order gives the back-to-front order for the
/// view, so a backend can emit the splats as it draws them, slice by slice (the CPU backend's
/// bands, docs/design.md "Splat lists and voxel batches"). Where a list earns its place (the GL
/// backend uploads one; batches of several nodes merged into one depth order), list() makes it
/// on first use.
class VoxelSplats {
public:
    /// @brief The voxel splats of @p grid for @p view; list() writes into @p list when given (a
    /// list kept from frame to frame, refilled without a new allocation), else a new one.
    VoxelSplats(std::shared_ptr<const ClassifiedGrid> grid, const View& view,
                std::shared_ptr<SplatList> list = nullptr);

    /// @brief The grid.
    [[nodiscard]] const ClassifiedGrid& grid() const { return *mGrid; }

    /// @brief The grid, shared.
    [[nodiscard]] const std::shared_ptr<const ClassifiedGrid>& sharedGrid() const { return mGrid; }

    /// @brief The view the splats are ordered and culled for.
    [[nodiscard]] const View& view() const { return mView; }

    /// @brief The order of the voxels.
    [[nodiscard]] const SliceOrder& order() const { return mOrder; }

    /// @brief Which voxels make splats.
    [[nodiscard]] const DrawnVoxels& drawn() const { return mDrawn; }

    /// @brief Number of splats (the length of list()), counted per block where the view culls
    /// no voxel of it.
    [[nodiscard]] std::uint64_t count() const { return mCount; }

    /// @brief The splats as a list, emitted on the first call (and kept).
    [[nodiscard]] const std::shared_ptr<const SplatList>& list() const;

    /// @brief Bytes of list() once it is made (its capacity), else 0.
    [[nodiscard]] std::uint64_t memoryBytes() const;

private:
    std::shared_ptr<const ClassifiedGrid> mGrid;
    View mView;
    SliceOrder mOrder;
    DrawnVoxels mDrawn;
    std::uint64_t mCount = 0;
    mutable std::once_flag mListed;
    mutable std::shared_ptr<SplatList> mStorage;    // where list() writes
    mutable std::shared_ptr<const SplatList> mList; // mStorage once written
};

} // namespace texsplat::octree
