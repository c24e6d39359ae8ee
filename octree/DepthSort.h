#pragma once

#include "octree/Fwd.h"
#include "octree/Splat.h"

#include <cstdint>
#include <vector>

namespace texsplat::octree {

/// @brief Reorders @p splats (each with its marks) by decreasing centre depth for @p view: the
/// distance along the direction for an orthographic view, the distance from the eye for a
/// perspective one. Stable, so splats at equal depth keep their traversal order.
///
/// This is the order of Westover 1989 that Crawfis & Max used ("composited one by one in back to
/// front order (in regard to their center points)"). The octree and slice traversals order the
/// splats' cells, which is exact for the cells but not for kernels reaching past them under
/// oblique views (docs/octree.md); a backend that wants centre order pays for this sort: an LSD
/// radix sort of 32-bit keys, O(n). A caller that sorts every frame keeps a DepthSorter instead.
void sortByDepth(SplatList& splats, const View& view);

/// @brief sortByDepth() for a caller that sorts a list every frame (a splat node drawing an
/// octree cut): the keys, the radix passes' scratch and the sorted copy are kept from one call
/// to the next, so a frame allocates (and page-faults) nothing once the sizes settle, and the
/// keys, the passes and the sorted copy use all threads. The order is sortByDepth()'s: a stable
/// sort has one result, whatever the number of threads.
class DepthSorter {
public:
    /// @brief Sorts @p splats as sortByDepth() does. Afterwards @p splats holds the sorted
    /// splats in what was this sorter's copy, and the sorter keeps @p splats' old storage.
    void sort(SplatList& splats, const View& view);

    /// @brief Bytes the kept buffers hold.
    [[nodiscard]] std::uint64_t memoryBytes() const;

private:
    std::vector<std::uint64_t> mItems;      // far-first key << 32 | splat index
    std::vector<std::uint64_t> mScratch;    // the other buffer of the radix passes
    std::vector<std::uint32_t> mMarkBegins; // where each sorted splat's marks go
    SplatList mSorted;
};

} // namespace texsplat::octree
