#include "nodes/volume/SparseGrid.h"

#include "scenegraph/Assert.h"

#include <limits>

namespace texsplat::volume {

template <typename T>
SparseGrid<T>::SparseGrid(const GridGeometry& geometry, const T& background,
                          const glm::i64vec3& blockOffset)
    : Grid<T>(geometry, background), mBlockOffset(blockOffset),
      mBlockDims((geometry.dims() + blockOffset + (kBlockSize - 1)) / kBlockSize) {
    TEXSPLAT_ASSERT(glm::all(glm::greaterThanEqual(blockOffset, glm::i64vec3(0))) &&
                        glm::all(glm::lessThan(blockOffset, glm::i64vec3(kBlockSize))),
                    "SparseGrid::SparseGrid(): block offset outside [0, 8)");
}

template <typename T>
typename SparseGrid<T>::Location SparseGrid<T>::locate(const glm::i64vec3& index) const {
    const glm::i64vec3 shifted = index + mBlockOffset; // never negative inside the grid
    const glm::i64vec3 block = shifted / kBlockSize;
    const glm::i64vec3 local = shifted - block * kBlockSize;
    return {block.x + mBlockDims.x * (block.y + mBlockDims.y * block.z),
            block * kBlockSize - mBlockOffset,
            static_cast<std::size_t>(local.x + kBlockSize * (local.y + kBlockSize * local.z))};
}

template <typename T>
const typename SparseGrid<T>::Block* SparseGrid<T>::findBlock(const Location& location) const {
    const auto found = mBlockByKey.find(location.key);
    return found == mBlockByKey.end() ? nullptr : mBlocks[found->second].get();
}

template <typename T>
void SparseGrid<T>::setValue(const glm::i64vec3& index, const T& value) {
    TEXSPLAT_ASSERT(this->geometry().contains(index), "SparseGrid::setValue(): index outside grid");
    const Location location = locate(index);
    auto [found, inserted] = mBlockByKey.try_emplace(location.key, mBlocks.size());
    if (inserted) {
        auto fresh = std::make_unique<Block>();
        fresh->first = location.first;
        fresh->values.fill(this->background());
        mBlocks.push_back(std::move(fresh));
    }
    Block& target = *mBlocks[found->second];
    target.values[location.slot] = value;
    target.active.set(location.slot);
}

template <typename T>
std::int64_t SparseGrid<T>::activeVoxelCount() const {
    std::int64_t count = 0;
    for (const auto& block : mBlocks)
        count += static_cast<std::int64_t>(block->active.count());
    return count;
}

template <typename T>
T SparseGrid<T>::value(const glm::i64vec3& index) const {
    TEXSPLAT_ASSERT(this->geometry().contains(index), "SparseGrid::value(): index outside grid");
    const Location location = locate(index);
    const Block* block = findBlock(location);
    if (block == nullptr || !block->active.test(location.slot) ||
        !isFiniteValue(block->values[location.slot]))
        return this->background();
    return block->values[location.slot];
}

template <typename T>
bool SparseGrid<T>::isActive(const glm::i64vec3& index) const {
    TEXSPLAT_ASSERT(this->geometry().contains(index), "SparseGrid::isActive(): index outside grid");
    const Location location = locate(index);
    const Block* block = findBlock(location);
    return block != nullptr && block->active.test(location.slot) &&
           isFiniteValue(block->values[location.slot]);
}

template <typename T>
void SparseGrid<T>::forEachStored(const typename Grid<T>::VoxelVisitor& visit) const {
    for (const auto& block : mBlocks) {
        if (block->active.none())
            continue;
        for (std::size_t slot = 0; slot < kBlockVoxels; ++slot) {
            if (!block->active.test(slot))
                continue;
            const auto local = static_cast<std::int64_t>(slot);
            const glm::i64vec3 offset(local % kBlockSize, (local / kBlockSize) % kBlockSize,
                                      local / (kBlockSize * kBlockSize));
            visit(block->first + offset, block->values[slot]);
        }
    }
}

namespace {
// Each hash entry costs about a node (key, value, next pointer, cached hash) plus a bucket.
constexpr std::size_t kEntryBytes = 4 * sizeof(void*) + sizeof(std::int64_t);
} // namespace

template <typename T>
std::size_t SparseGrid<T>::memoryBytes() const {
    return mBlocks.size() * (sizeof(Block) + sizeof(std::unique_ptr<Block>) + kEntryBytes) +
           mBlockByKey.bucket_count() * sizeof(void*);
}

template <typename T>
std::uint64_t SparseGrid<T>::memoryBytesForBlocks(std::uint64_t blocks) {
    // As memoryBytes(), with about one bucket per block.
    constexpr std::uint64_t kPerBlock =
        sizeof(Block) + sizeof(std::unique_ptr<Block>) + kEntryBytes + sizeof(void*);
    return blocks > std::numeric_limits<std::uint64_t>::max() / kPerBlock
               ? std::numeric_limits<std::uint64_t>::max()
               : blocks * kPerBlock;
}

template class SparseGrid<float>;
template class SparseGrid<glm::vec3>;

} // namespace texsplat::volume
