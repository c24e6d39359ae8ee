#include "octree/ValueRanges.h"

#include "octree/ClassifiedGrid.h"
#include "scenegraph/Error.h"

#include <limits>
#include <string>

namespace texsplat::octree {

ValueRanges::ValueRanges(glm::u64vec3 dims)
    : mDims(dims),
      mBlockDims((dims + (ClassifiedGrid::kBlockSize - 1)) / ClassifiedGrid::kBlockSize) {
    const std::uint64_t blocks = ClassifiedGrid::boxBlockCount(dims);
    if (blocks > std::numeric_limits<std::size_t>::max() / sizeof(std::uint32_t)) {
        throw DataError("ValueRanges: " + std::to_string(blocks) +
                        " blocks exceed the addressable memory");
    }
    mSlots.assign(static_cast<std::size_t>(blocks), kNoBlock);
}

} // namespace texsplat::octree
