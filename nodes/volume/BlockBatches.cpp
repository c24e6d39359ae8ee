#include "nodes/volume/BlockBatches.h"

#include <algorithm>
#include <limits>

namespace texsplat::volume {

glm::vec2 valueRangeOf(const Grid<float>::VoxelBlock& voxels) {
    float lowest = std::numeric_limits<float>::infinity();
    float highest = -std::numeric_limits<float>::infinity();
    if (voxels.nonEmpty.all()) { // a dense grid's inner block: a loop the compiler vectorizes
        for (const float value : voxels.values) {
            lowest = std::min(lowest, value);
            highest = std::max(highest, value);
        }
        return {lowest, highest};
    }
    for (std::size_t v = 0; v < voxels.values.size(); ++v) {
        if (voxels.nonEmpty[v]) {
            lowest = std::min(lowest, voxels.values[v]);
            highest = std::max(highest, voxels.values[v]);
        }
    }
    return {lowest, highest};
}

} // namespace texsplat::volume
