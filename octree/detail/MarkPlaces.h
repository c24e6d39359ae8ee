#pragma once

#include "octree/Splat.h"

#include <cstddef>
#include <limits>
#include <vector>

namespace texsplat::octree::detail {

/// Where a mark goes in a splat list: after splat `after` (kNowhere: left out), and its depth
/// (larger: farther), which orders the marks that follow one splat.
struct MarkPlace {
    static constexpr std::size_t kNowhere = std::numeric_limits<std::size_t>::max();
    std::size_t after = kNowhere;
    double depth = 0.0;
};

/// Gives the splats of `splats` (which holds no marks) the marks of `marks`, each after the
/// splat its place names, the farther first among one splat's.
void placeMarks(const std::vector<SplatMark>& marks, const std::vector<MarkPlace>& places,
                SplatList& splats);

} // namespace texsplat::octree::detail
