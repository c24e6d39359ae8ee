#pragma once

#include "octree/Fwd.h"

namespace texsplat::octree {

/// @brief Reorders @p splats (and their vectors) by decreasing centre depth for @p view: the
/// distance along the direction for an orthographic view, the distance from the eye for a
/// perspective one. Stable, so splats at equal depth keep their traversal order.
///
/// This is the order of Westover 1989 that Crawfis & Max used ("composited one by one in back to
/// front order (in regard to their center points)"). The octree and slice traversals order the
/// splats' cells, which is exact for the cells but not for kernels reaching past them under
/// oblique views (docs/octree.md); a backend that wants centre order pays for this sort: an LSD
/// radix sort of 32-bit keys, O(n).
void sortByDepth(SplatList& splats, const View& view);

} // namespace texsplat::octree
