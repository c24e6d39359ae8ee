#include "nodes/distributed/RankGrid.h"

#include "nodes/volume/detail/ShiftedBlocks.h"

#include <utility>

namespace texsplat::distributed {

template <typename T>
RankGrid<T>::RankGrid(const volume::GridGeometry& whole,
                      std::shared_ptr<const volume::Grid<T>> block, const glm::i64vec3& blockOffset,
                      const volume::IndexBox& owned)
    : volume::Grid<T>(whole, block ? block->background() : T(0.0f)), mBlock(std::move(block)),
      mOffset(blockOffset), mOwned(owned) {}

template <typename T>
void RankGrid<T>::forEachStored(const typename volume::Grid<T>::VoxelVisitor& visit) const {
    if (!mBlock) {
        return;
    }
    mBlock->forEachStored([&](const glm::i64vec3& index, const T& value) {
        const glm::i64vec3 inWhole = index + mOffset;
        if (mOwned.contains(inWhole)) {
            visit(inWhole, value);
        }
    });
}

template <typename T> std::vector<glm::i64vec3> RankGrid<T>::occupiedBlocks() const {
    std::vector<glm::i64vec3> blocks;
    if (mOwned.isEmpty()) {
        return blocks;
    }
    constexpr std::int64_t kEdge = volume::Grid<T>::kBlockEdge;
    const glm::i64vec3 first = mOwned.lo / kEdge;
    const glm::i64vec3 last = (mOwned.hi - std::int64_t{1}) / kEdge;
    glm::i64vec3 block;
    for (block.z = first.z; block.z <= last.z; ++block.z) {
        for (block.y = first.y; block.y <= last.y; ++block.y) {
            for (block.x = first.x; block.x <= last.x; ++block.x) {
                blocks.push_back(block);
            }
        }
    }
    return blocks;
}

template <typename T>
void RankGrid<T>::readBlock(const glm::i64vec3& block,
                            typename volume::Grid<T>::VoxelBlock& out) const {
    if (!mBlock) {
        out.nonEmpty.reset();
        return;
    }
    volume::detail::readShiftedBlock(*mBlock, -mOffset, mOwned, block, out);
}

template class RankGrid<float>;
template class RankGrid<glm::vec3>;

} // namespace texsplat::distributed
