#include "nodes/volume/SparseGrid.h"

#include "nodes/volume/detail/StatisticsAccumulator.h"
#include "scenegraph/Assert.h"

#include <algorithm>
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
typename SparseGrid<T>::Block& SparseGrid<T>::blockAt(const Location& location) {
    auto [found, inserted] = mBlockByKey.try_emplace(location.key, mBlocks.size());
    if (inserted) {
        auto fresh = std::make_unique<Block>();
        fresh->first = location.first;
        fresh->values.fill(this->background());
        mBlocks.push_back(std::move(fresh));
    }
    return *mBlocks[found->second];
}

template <typename T>
void SparseGrid<T>::setValue(const glm::i64vec3& index, const T& value) {
    TEXSPLAT_ASSERT(this->geometry().contains(index), "SparseGrid::setValue(): index outside grid");
    const Location location = locate(index);
    Block& target = blockAt(location);
    target.values[location.slot] = value;
    target.active.set(location.slot);
}

template <typename T>
void SparseGrid<T>::setBlock(const glm::i64vec3& first, const BlockVoxels& voxels) {
    if (voxels.active.none()) {
        return;
    }
    const glm::i64vec3 shifted = first + mBlockOffset;
    TEXSPLAT_ASSERT(glm::all(glm::equal(shifted % kBlockSize, glm::i64vec3(0))) &&
                        glm::all(glm::greaterThanEqual(shifted, glm::i64vec3(0))) &&
                        glm::all(glm::lessThan(shifted, mBlockDims * kBlockSize)),
                    "SparseGrid::setBlock(): not a block of the grid's lattice");
    const glm::i64vec3 block = shifted / kBlockSize;
    Block& target = blockAt({block.x + mBlockDims.x * (block.y + mBlockDims.y * block.z), first, 0});
    if (target.active.none()) {
        static_cast<BlockVoxels&>(target) = voxels;
        return;
    }
    for (std::size_t slot = 0; slot < kBlockVoxels; ++slot) { // merging with setValue()'s
        if (voxels.active.test(slot)) {
            target.values[slot] = voxels.values[slot];
        }
    }
    target.active |= voxels.active;
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

template <typename T>
GridStatistics SparseGrid<T>::statistics() const {
    detail::StatisticsAccumulator<T> statistics;
    for (const auto& block : mBlocks) {
        for (std::size_t slot = 0; slot < kBlockVoxels; ++slot) {
            if (block->active[slot]) {
                statistics.add(block->values[slot]);
            }
        }
    }
    return statistics.result();
}

template <typename T>
std::vector<glm::i64vec3> SparseGrid<T>::occupiedBlocks() const {
    constexpr std::int64_t kEdge = Grid<T>::kBlockEdge;
    const glm::i64vec3 dims = this->geometry().dims();
    const glm::i64vec3 blockDims = (dims + (kEdge - 1)) / kEdge;
    std::vector<std::int64_t> keys;
    keys.reserve(mBlocks.size());
    for (const auto& stored : mBlocks) {
        if (stored->active.none())
            continue;
        // The stored block's voxels inside the box, and the read blocks they fall in.
        const glm::i64vec3 low = glm::max(stored->first, glm::i64vec3(0)) / kEdge;
        const glm::i64vec3 high =
            (glm::min(stored->first + kBlockSize, dims) - std::int64_t{1}) / kEdge;
        for (std::int64_t z = low.z; z <= high.z; ++z)
            for (std::int64_t y = low.y; y <= high.y; ++y)
                for (std::int64_t x = low.x; x <= high.x; ++x)
                    keys.push_back(x + blockDims.x * (y + blockDims.y * z));
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    std::vector<glm::i64vec3> blocks;
    blocks.reserve(keys.size());
    for (const std::int64_t key : keys) {
        blocks.emplace_back(key % blockDims.x, (key / blockDims.x) % blockDims.y,
                            key / (blockDims.x * blockDims.y));
    }
    return blocks;
}

template <typename T>
void SparseGrid<T>::readBlock(const glm::i64vec3& block,
                              typename Grid<T>::VoxelBlock& out) const {
    constexpr std::int64_t kEdge = Grid<T>::kBlockEdge;
    static_assert(kEdge == kBlockSize, "a read block overlaps at most 2 stored blocks per axis");
    const glm::i64vec3 first = block * kEdge;
    const glm::i64vec3 last = glm::min(first + kEdge, this->geometry().dims());
    // The stored blocks the read block overlaps, looked up once: (first + offset) / 8 and the
    // next along each axis.
    const glm::i64vec3 base = (first + mBlockOffset) / kBlockSize;
    const Block* overlapped[2][2][2];
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x) {
                const glm::i64vec3 stored = base + glm::i64vec3(x, y, z);
                overlapped[z][y][x] =
                    glm::all(glm::lessThan(stored, mBlockDims))
                        ? findBlock({stored.x + mBlockDims.x * (stored.y + mBlockDims.y * stored.z),
                                     stored * kBlockSize - mBlockOffset, 0})
                        : nullptr;
            }
    // Read-block coordinate i lies in stored block (i + offset) / 8 (0 or 1 of `overlapped`), at
    // (i + offset) % 8 there. The flags of a z slice gather in a word, as for dense grids.
    const glm::i64vec3 extent = last - first;
    std::bitset<512> nonEmpty;
    for (std::int64_t z = 0; z < extent.z; ++z) {
        const std::int64_t sz = z + mBlockOffset.z;
        const std::int64_t wz = sz / kBlockSize;
        std::uint64_t slice = 0;
        for (std::int64_t y = 0; y < extent.y; ++y) {
            const std::int64_t sy = y + mBlockOffset.y;
            const std::int64_t wy = sy / kBlockSize;
            const std::int64_t storedRow =
                kBlockSize * ((sy - wy * kBlockSize) + kBlockSize * (sz - wz * kBlockSize));
            for (std::int64_t x = 0; x < extent.x; ++x) {
                const std::int64_t sx = x + mBlockOffset.x;
                const std::int64_t wx = sx / kBlockSize;
                const Block* stored = overlapped[wz][wy][wx];
                const auto slot = static_cast<std::size_t>(storedRow + sx - wx * kBlockSize);
                if (stored == nullptr || !stored->active[slot] ||
                    !isFiniteValue(stored->values[slot]))
                    continue;
                const auto inSlice = static_cast<std::size_t>(x + kEdge * y);
                out.values[inSlice + static_cast<std::size_t>(kEdge * kEdge * z)] =
                    stored->values[slot];
                slice |= std::uint64_t{1} << inSlice;
            }
        }
        nonEmpty |= std::bitset<512>(slice) << static_cast<std::size_t>(kEdge * kEdge * z);
    }
    out.nonEmpty = nonEmpty;
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
