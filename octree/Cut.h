#pragma once

#include "octree/Fwd.h"
#include "octree/NodeRef.h"

#include <cstdint>
#include <vector>

namespace texsplat::octree {

/// @brief A cut through an `Octree`: the set of nodes that are splatted for a frame, each
/// standing for all the voxels below it (Laur & Hanrahan 1991). Stored as one "split" bit per
/// node record, so a cut costs N/7 bits and refining it never moves data.
///
/// A node is in the cut when its parent is split and it is not; the root is in the cut unless
/// it is split. The cut refers to the octree, which must outlive it.
class Cut {
public:
    /// @brief The coarsest cut: the root alone (no node for an empty octree).
    explicit Cut(const Octree& octree);

    /// @brief The cut that splats a node when its error is <= @p threshold and descends
    /// otherwise; voxels are always splatted. Threshold 0 splats every non-empty voxel except
    /// where a whole block is uniform (its mean is then exact).
    /// @throws DataError when @p threshold is negative or not finite.
    [[nodiscard]] static Cut byError(const Octree& octree, double threshold);

    /// @brief The cut of byError() at @p fraction of the octree's `valueScale()`, the largest
    /// colour or extinction of any voxel: at fraction f every voxel a splat stands for is within
    /// f times the grid's largest value of what the splat carries, whatever the transfer
    /// function's scale. 0 gives byError(octree, 0); 1 or more the root alone.
    /// @throws DataError when @p fraction is negative or not finite.
    [[nodiscard]] static Cut byRelativeError(const Octree& octree, double fraction);

    /// @brief The octree this cut goes through.
    [[nodiscard]] const Octree& octree() const { return *mOctree; }

    /// @brief Number of nodes in the cut, i.e. splats per frame before culling.
    [[nodiscard]] std::uint64_t splatCount() const { return mSplatCount; }

    /// @brief Whether @p node is split (its children replace it); voxels never are.
    [[nodiscard]] bool isSplit(const NodeRef& node) const {
        return node.level > 0 && mSplit[static_cast<std::size_t>(node.index)];
    }

    /// @brief Replaces @p node, a node of level >= 1 in the cut, by its non-empty children.
    void split(const NodeRef& node);

    /// @brief Whether both cuts select the same nodes of the same octree.
    [[nodiscard]] bool operator==(const Cut& other) const {
        return mOctree == other.mOctree && mSplit == other.mSplit;
    }

    /// @brief Whether the cuts differ.
    [[nodiscard]] bool operator!=(const Cut& other) const { return !(*this == other); }

    /// @brief split() for the node whose record is @p record (in `Octree::nodes()`): for a
    /// caller that knows nodes by their records alone, e.g. Refiner::refineAtOnce().
    void splitRecord(std::uint64_t record);

private:
    const Octree* mOctree;
    std::vector<bool> mSplit;
    std::uint64_t mSplatCount = 0;
};

} // namespace texsplat::octree
