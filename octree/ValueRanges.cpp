#include "octree/ValueRanges.h"

#include "octree/ClassifiedGrid.h"
#include "scenegraph/Error.h"
#include "scenegraph/MemoryLimit.h"

#include <algorithm>
#include <limits>
#include <string>

namespace texsplat::octree {

ValueRanges::ValueRanges(glm::u64vec3 dims)
    : mDims(dims),
      mBlockDims(ClassifiedGrid::boxBlockDims(dims)) {
    const std::uint64_t blocks = ClassifiedGrid::boxBlockCount(dims);
    if (blocks > std::numeric_limits<std::size_t>::max() / sizeof(std::uint32_t)) {
        throw DataError("ValueRanges: " + std::to_string(blocks) +
                        " blocks exceed the addressable memory");
    }
    mSlots.assign(static_cast<std::size_t>(blocks), kNoBlock);
}

std::uint64_t ValueRanges::memoryBytesFor(glm::u64vec3 dims, std::uint64_t blocks) {
    return byteSum(byteProduct(ClassifiedGrid::boxBlockCount(dims), sizeof(std::uint32_t)),
                   byteProduct(blocks, sizeof(glm::vec2)));
}

glm::vec2 ValueRanges::valueRange() const {
    if (mRanges.empty()) {
        return glm::vec2(0.0f);
    }
    glm::vec2 range = mRanges.front();
    for (const glm::vec2& block : mRanges) {
        range = glm::vec2(std::min(range.x, block.x), std::max(range.y, block.y));
    }
    return range;
}

} // namespace texsplat::octree
