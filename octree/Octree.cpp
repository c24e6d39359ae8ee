#include "octree/Octree.h"

#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <utility>

namespace texsplat::octree {

/// Running statistics of a block of voxels: enough to merge children exactly into a parent.
/// The per-channel minimum and maximum give the exact largest deviation from the mean, which a
/// bound built from the children's errors alone would only overestimate.
struct Octree::Statistics {
    glm::dvec4 sum{0.0};
    glm::vec4 minimum{0.0f};
    glm::vec4 maximum{0.0f};
    std::uint64_t count = 0;
    OctreeNode record;

    void merge(const Statistics& other) {
        minimum = count == 0 ? other.minimum : glm::min(minimum, other.minimum);
        maximum = count == 0 ? other.maximum : glm::max(maximum, other.maximum);
        sum += other.sum;
        count += other.count;
        record.nonEmptyCount += other.record.nonEmptyCount;
    }

    void finish() {
        const glm::dvec4 mean = sum / static_cast<double>(count);
        record.meanColor = glm::vec3(mean);
        record.meanExtinction = static_cast<float>(mean.w);
        double error = 0.0;
        for (int channel = 0; channel < 4; ++channel) {
            error = std::max({error, static_cast<double>(maximum[channel]) - mean[channel],
                              mean[channel] - static_cast<double>(minimum[channel])});
        }
        record.error = static_cast<float>(error);
    }
};

/// A node's non-empty children as the build meets them, in octant order: the records the node
/// appends contiguously once the children's own subtrees are stored.
struct Octree::Children {
    std::array<OctreeNode, 8> records;
    int count = 0;

    // Merges `child`, the child in `octant`, into `parent`, and keeps its record when it holds a
    // non-empty voxel.
    void add(Statistics& parent, int octant, const Statistics& child) {
        parent.merge(child);
        if (child.record.nonEmptyCount > 0) {
            parent.record.childMask |= static_cast<std::uint8_t>(1u << octant);
            records[static_cast<std::size_t>(count++)] = child.record;
        }
    }
};

/// Where the build appends records: the octree's own, or a block's slot while blocks are built
/// in parallel (then a record's firstChild counts from the slot's start until
/// BlockBatches::place() moves the slot into the octree).
struct Octree::Records {
    std::vector<OctreeNode>& nodes;

    // Appends `children`'s records and returns the index of the first: their parent's firstChild.
    std::uint64_t append(const Children& children) {
        const std::uint64_t first = nodes.size();
        nodes.insert(nodes.end(), children.records.begin(),
                     children.records.begin() + children.count);
        return first;
    }
};

namespace {

constexpr const char* kBuildStep = "building the octree";
// Blocks built in parallel between two progress reports (2^19 voxels, as classification's
// batches): few enough that a cancel is prompt and the slots of two batches stay small (6 MiB),
// enough that the threads share the work evenly.
constexpr std::size_t kBlocksPerBatch = 1024;
// Records of a block's subtree at most: 8 of level 2 and 64 of level 1.
constexpr std::size_t kBlockRecords = 8 + 64;

// Levels above 62 would overflow the 64-bit voxel coordinates of a node's block.
[[maybe_unused]] constexpr int kMaxLevel = 62; // only asserted

// Nodes of `level` along each axis of a grid of `dims` voxels.
glm::u64vec3 nodeCounts(glm::u64vec3 dims, int level) {
    return (dims + ((std::uint64_t{1} << level) - 1)) >> glm::u64vec3(level);
}

// Linear index of `node` among the nodes of `level`.
std::size_t nodeIndex(glm::u64vec3 dims, int level, glm::u64vec3 node) {
    const glm::u64vec3 count = nodeCounts(dims, level);
    return static_cast<std::size_t>(node.x + count.x * (node.y + count.y * node.z));
}

// A subtree built into a slot numbers its records from the slot's start; to be moved to
// `offset` in the octree's records, those that point at records (of level >= 2) must point
// `offset` further. From `record` of `level`, whose descendants' records are `slot`.
void shiftChildIndices(OctreeNode& record, int level, std::uint64_t offset,
                       std::vector<OctreeNode>& slot) {
    if (level < 2) {
        return;
    }
    const std::uint64_t first = record.firstChild;
    record.firstChild += offset;
    const auto count = static_cast<std::size_t>(detail::bitCount(record.childMask));
    for (std::size_t rank = 0; rank < count; ++rank) {
        shiftChildIndices(slot[static_cast<std::size_t>(first + rank)], level - 1, offset, slot);
    }
}

} // namespace

/// The subtrees of the blocks, built in parallel (oneTBB) a batch at a time, each into a slot of
/// its own, and handed to the serial build of the levels above in build order; while the calling
/// thread places one batch, the other threads build the next. Each block's subtree is made by the
/// same code in the same order whatever thread makes it, and the levels above are built in one
/// order on one thread, so the octree is the same for any number of threads. Between two batches
/// the calling thread tells the progress callback how many blocks are built: the callback runs on
/// that thread only, and a cancel stops the build within a batch.
class Octree::BlockBatches {
public:
    // `blocks`: the nodes of `level` holding an allocated block, in build order.
    BlockBatches(const Octree& octree, int level, std::vector<glm::u64vec3> blocks,
                 const sg::WorkProgress& progress)
        : mOctree(octree), mLevel(level), mBlocks(std::move(blocks)), mProgress(progress) {
        const std::size_t count = std::min(mBlocks.size(), kBlocksPerBatch);
        for (Slots& slots : mSlots) {
            slots.statistics.resize(count);
            slots.nodes.resize(count);
            for (std::size_t slot = 0; slot < count; ++slot) {
                slots.nodes[slot].reserve(kBlockRecords);
            }
        }
    }

    // The statistics of the next block in build order, whose subtree's records are appended to
    // `records` (the next batch is waited for when this one is used up).
    Statistics place(Records& records) {
        if (mNext == mBatchEnd) {
            nextBatch();
        }
        Slots& slots = mSlots[mPlacing];
        const std::size_t slot = mNext++ - mBatchBegin;
        Statistics statistics = slots.statistics[slot];
        std::vector<OctreeNode>& nodes = slots.nodes[slot];
        shiftChildIndices(statistics.record, mLevel, records.nodes.size(), nodes);
        records.nodes.insert(records.nodes.end(), nodes.begin(), nodes.end());
        return statistics;
    }

private:
    // Per block of a batch: its statistics and its subtree's records, with firstChild indices
    // into the slot.
    struct Slots {
        std::vector<Statistics> statistics;
        std::vector<std::vector<OctreeNode>> nodes;
    };

    // Makes the batch after the one placed so far the one to place, and starts building the one
    // after it. When the progress callback cancels, no batch is being built.
    void nextBatch() {
        if (mBatchEnd == 0) {
            build(mSlots[mPlacing], 0);
        } else {
            mBuilding.wait();
            mPlacing = 1 - mPlacing;
        }
        mBatchBegin = mBatchEnd;
        mBatchEnd = std::min(mBatchBegin + kBlocksPerBatch, mBlocks.size());
        sg::reportWork(mProgress, kBuildStep,
                       static_cast<double>(mBatchEnd) / static_cast<double>(mBlocks.size()));
        if (mBatchEnd < mBlocks.size()) {
            mBuilding.run([this, &slots = mSlots[1 - mPlacing], begin = mBatchEnd] {
                build(slots, begin);
            });
        }
    }

    // Builds the batch that starts at block `begin` into `slots`, in parallel.
    void build(Slots& slots, std::size_t begin) const {
        const std::size_t count = std::min(kBlocksPerBatch, mBlocks.size() - begin);
        tbb::parallel_for(std::size_t{0}, count, [&](std::size_t slot) {
            slots.nodes[slot].clear();
            Records records{slots.nodes[slot]};
            slots.statistics[slot] = mOctree.buildSubtree(mLevel, mBlocks[begin + slot], records);
        });
    }

    const Octree& mOctree;
    int mLevel;
    std::vector<glm::u64vec3> mBlocks;
    const sg::WorkProgress& mProgress;
    std::size_t mBatchBegin = 0; // the batch being placed: blocks [mBatchBegin, mBatchEnd)
    std::size_t mBatchEnd = 0;
    std::size_t mNext = 0; // the next block to place
    std::array<Slots, 2> mSlots;
    int mPlacing = 0; // the slots of the batch being placed; the other ones take the next batch
    // Builds the next batch. Were the build stopped by an exception while it runs, the group's
    // destructor cancels and waits for it.
    tbb::task_group mBuilding;
};

Octree::Octree(std::shared_ptr<const ClassifiedGrid> grid, const sg::WorkProgress& progress)
    : mGrid(std::move(grid)) {
    if (!mGrid) {
        throw DataError("Octree: no grid to build from");
    }
    const glm::u64vec3 dims = mGrid->dims();
    const std::uint64_t largest = std::max({dims.x, dims.y, dims.z});
    while ((std::uint64_t{1} << mRootLevel) < largest) {
        ++mRootLevel;
    }
    TEXSPLAT_ASSERT(mRootLevel <= kMaxLevel, "Octree::Octree(): grid too large for 64 bits");
    sg::reportWork(progress, kBuildStep, 0.0);
    const Occupancy occupied = occupancy();
    std::vector<glm::u64vec3> blocks;
    collectBlocks(mRootLevel, glm::u64vec3(0), occupied, blocks);
    // Room for the most records the blocks and the nodes above them can have: address space, not
    // memory, until the records are placed (at most 2.9 KB per block, a third of the block's
    // voxels). Growing by doubling instead copied the records over and over on the one thread
    // that places them, a third of the build's time; shrink_to_fit() below gives back the rest.
    std::size_t upperNodes = 0;
    for (const std::vector<bool>& level : occupied) {
        upperNodes += static_cast<std::size_t>(std::count(level.begin(), level.end(), true));
    }
    const std::size_t mostRecords = blocks.size() * (kBlockRecords + 1) + upperNodes;
    mNodes.reserve(mostRecords);
    // A grid of at most 4 voxels along every axis has one block, below its root's level.
    BlockBatches batches(*this, std::min(mRootLevel, ClassifiedGrid::kBlockLevel),
                         std::move(blocks), progress);
    const Statistics root = build(mRootLevel, glm::u64vec3(0), occupied, batches);
    mIsEmpty = root.record.nonEmptyCount == 0;
    mValueScale = std::max({root.maximum.r, root.maximum.g, root.maximum.b, root.maximum.a});
    if (mRootLevel > 0 && !mIsEmpty) {
        mNodes.push_back(root.record);
    }
    mNodes.shrink_to_fit();
    sg::reportWork(progress, kBuildStep, 1.0);
}

Octree::Statistics Octree::voxelStatistics(glm::u64vec3 voxel) const {
    const glm::vec4 value = mGrid->voxel(voxel);
    Statistics statistics;
    statistics.sum = glm::dvec4(value);
    statistics.minimum = value;
    statistics.maximum = value;
    statistics.count = 1;
    statistics.record.meanColor = glm::vec3(value);
    statistics.record.meanExtinction = value.w;
    statistics.record.nonEmptyCount = value == glm::vec4(0.0f) ? 0 : 1;
    return statistics;
}

Octree::Occupancy Octree::occupancy() const {
    const glm::u64vec3 dims = mGrid->dims();
    Occupancy occupied(static_cast<std::size_t>(mRootLevel + 1));
    for (int level = ClassifiedGrid::kBlockLevel + 1; level <= mRootLevel; ++level) {
        const glm::u64vec3 count = nodeCounts(dims, level);
        occupied[static_cast<std::size_t>(level)].assign(
            static_cast<std::size_t>(count.x * count.y * count.z), false);
    }
    mGrid->forEachBlock([&](glm::u64vec3 block, ClassifiedGrid::StorageIndex) {
        for (int level = ClassifiedGrid::kBlockLevel + 1; level <= mRootLevel; ++level) {
            const glm::u64vec3 node = block >> glm::u64vec3(level - ClassifiedGrid::kBlockLevel);
            occupied[static_cast<std::size_t>(level)][nodeIndex(dims, level, node)] = true;
        }
    });
    return occupied;
}

bool Octree::holdsBlock(int level, glm::u64vec3 coord, const Occupancy& occupied) const {
    if (level <= ClassifiedGrid::kBlockLevel) {
        // A block, or the root of a grid of one block.
        return mGrid->hasBlock(coord >> glm::u64vec3(ClassifiedGrid::kBlockLevel - level));
    }
    return occupied[static_cast<std::size_t>(level)][nodeIndex(mGrid->dims(), level, coord)];
}

template <typename Visit>
void Octree::forEachChild(int level, glm::u64vec3 coord, Visit&& visit) const {
    const glm::u64vec3 dims = mGrid->dims();
    for (int octant = 0; octant < 8; ++octant) {
        const glm::u64vec3 child = childCoord(coord, octant);
        const glm::u64vec3 begin = child << glm::u64vec3(level - 1);
        if (begin.x < dims.x && begin.y < dims.y && begin.z < dims.z) {
            visit(octant, child);
        }
    }
}

void Octree::collectBlocks(int level, glm::u64vec3 coord, const Occupancy& occupied,
                           std::vector<glm::u64vec3>& blocks) const {
    if (!holdsBlock(level, coord, occupied)) {
        return;
    }
    if (level <= ClassifiedGrid::kBlockLevel) {
        blocks.push_back(coord);
        return;
    }
    forEachChild(level, coord, [&](int, glm::u64vec3 child) {
        collectBlocks(level - 1, child, occupied, blocks);
    });
}

// Depth-first and post-order: a node's children are finished (and their own subtrees stored)
// before the node appends its non-empty children contiguously, so siblings stay adjacent. Above
// the blocks, on the calling thread; the blocks' subtrees come from `blocks`, in the same order.
Octree::Statistics Octree::build(int level, glm::u64vec3 coord, const Occupancy& occupied,
                                 BlockBatches& blocks) {
    if (!holdsBlock(level, coord, occupied)) {
        // No allocated block below: its voxels are empty, and only their number enters the mean
        // (what merging its empty children one by one gives: sums and bounds stay 0).
        const glm::u64vec3 begin = coord << glm::u64vec3(level);
        const glm::u64vec3 end =
            glm::min((coord + std::uint64_t{1}) << glm::u64vec3(level), mGrid->dims());
        const glm::u64vec3 extent = end - begin;
        Statistics statistics;
        statistics.count = extent.x * extent.y * extent.z;
        return statistics;
    }
    Records records{mNodes};
    if (level <= ClassifiedGrid::kBlockLevel) {
        return blocks.place(records);
    }
    Statistics statistics;
    Children children;
    forEachChild(level, coord, [&](int octant, glm::u64vec3 child) {
        children.add(statistics, octant, build(level - 1, child, occupied, blocks));
    });
    statistics.record.firstChild = records.append(children);
    statistics.finish();
    return statistics;
}

// The subtree of a block (or of the root of a grid of one block) into `records`, on any thread.
Octree::Statistics Octree::buildSubtree(int level, glm::u64vec3 coord, Records& records) const {
    if (level == 0) {
        return voxelStatistics(coord);
    }
    if (level == ClassifiedGrid::kBlockLevel) {
        return buildBlock(coord, records);
    }
    Statistics statistics;
    Children children;
    forEachChild(level, coord, [&](int octant, glm::u64vec3 child) {
        children.add(statistics, octant, buildSubtree(level - 1, child, records));
    });
    if (level >= 2) {
        statistics.record.firstChild = records.append(children);
    }
    statistics.finish();
    return statistics;
}

// The subtree of an allocated block, as buildSubtree() makes it (the same
// records in the same order, the same sums in the same order, so the same bits) but read straight
// from the block's storage, with no per-voxel Statistics: most of the build's time is spent here.
Octree::Statistics Octree::buildBlock(glm::u64vec3 block, Records& records) const {
    std::array<glm::vec4, ClassifiedGrid::kBlockVoxels> voxels;
    mGrid->readBlock(mGrid->blockStorage(block), voxels);
    // Voxels of the block inside the grid, per axis (fewer at the grid's far faces).
    const glm::u64vec3 begin = block * ClassifiedGrid::kBlockSize;
    const glm::u64vec3 extent =
        glm::min(mGrid->dims() - begin, glm::u64vec3(ClassifiedGrid::kBlockSize));
    const auto offset = [](int octant, std::uint64_t scale) {
        const auto bit = static_cast<unsigned>(octant);
        return glm::u64vec3(bit & 1u, (bit >> 1) & 1u, (bit >> 2) & 1u) * scale;
    };
    const auto isInside = [&extent](glm::u64vec3 voxel) {
        return voxel.x < extent.x && voxel.y < extent.y && voxel.z < extent.z;
    };
    Statistics statistics;
    Children quarters; // level 2
    for (int quarterOctant = 0; quarterOctant < 8; ++quarterOctant) {
        const glm::u64vec3 quarter = offset(quarterOctant, 4);
        if (!isInside(quarter)) {
            continue;
        }
        Statistics quarterStatistics;
        Children pairs; // level 1
        for (int pairOctant = 0; pairOctant < 8; ++pairOctant) {
            const glm::u64vec3 pair = quarter + offset(pairOctant, 2);
            if (!isInside(pair)) {
                continue;
            }
            Statistics pairStatistics;
            for (int voxelOctant = 0; voxelOctant < 8; ++voxelOctant) {
                const glm::u64vec3 voxel = pair + offset(voxelOctant, 1);
                if (!isInside(voxel)) {
                    continue;
                }
                const glm::vec4& value = voxels[static_cast<std::size_t>(
                    voxel.x + ClassifiedGrid::kBlockSize *
                                  (voxel.y + ClassifiedGrid::kBlockSize * voxel.z))];
                // Statistics::merge() of voxelStatistics(voxel), spelled out.
                pairStatistics.minimum =
                    pairStatistics.count == 0 ? value : glm::min(pairStatistics.minimum, value);
                pairStatistics.maximum =
                    pairStatistics.count == 0 ? value : glm::max(pairStatistics.maximum, value);
                pairStatistics.sum += glm::dvec4(value);
                ++pairStatistics.count;
                if (value != glm::vec4(0.0f)) {
                    ++pairStatistics.record.nonEmptyCount;
                    pairStatistics.record.childMask |=
                        static_cast<std::uint8_t>(1u << voxelOctant);
                }
            }
            if (pairStatistics.record.nonEmptyCount > 0) {
                // An empty pair gets no record, so its mean and error are never needed.
                pairStatistics.finish();
            }
            pairs.add(quarterStatistics, pairOctant, pairStatistics);
        }
        quarterStatistics.record.firstChild = records.append(pairs);
        if (quarterStatistics.record.nonEmptyCount > 0) {
            quarterStatistics.finish();
        }
        quarters.add(statistics, quarterOctant, quarterStatistics);
    }
    statistics.record.firstChild = records.append(quarters);
    statistics.finish();
    return statistics;
}

NodeRef Octree::root() const {
    TEXSPLAT_ASSERT(!mIsEmpty, "Octree::root(): an empty octree has no root");
    NodeRef root;
    root.level = mRootLevel;
    root.index = mRootLevel == 0 ? 0 : mNodes.size() - 1;
    return root;
}

OctreeNode Octree::node(const NodeRef& node) const {
    if (node.level > 0) {
        return mNodes[static_cast<std::size_t>(node.index)];
    }
    const glm::vec4 value = mGrid->voxel(node.coord);
    OctreeNode voxel;
    voxel.meanColor = glm::vec3(value);
    voxel.meanExtinction = value.w;
    voxel.nonEmptyCount = value == glm::vec4(0.0f) ? 0 : 1;
    return voxel;
}

int Octree::children(const NodeRef& node, std::array<NodeRef, 8>& children) const {
    if (node.level == 0) {
        return 0;
    }
    const unsigned mask = mNodes[static_cast<std::size_t>(node.index)].childMask;
    int count = 0;
    for (int octant = 0; octant < 8; ++octant) {
        if ((mask & (1u << octant)) != 0) {
            children[static_cast<std::size_t>(count++)] = child(node, octant);
        }
    }
    return count;
}

std::uint64_t Octree::voxelCount(const NodeRef& node) const {
    const glm::u64vec3 extent = voxelEnd(node) - voxelBegin(node);
    return extent.x * extent.y * extent.z;
}

glm::dvec3 Octree::splitPlanes(const NodeRef& node) const {
    TEXSPLAT_ASSERT(node.level > 0, "Octree::splitPlanes(): a voxel has no children");
    const glm::u64vec3 half = voxelBegin(node) + (std::uint64_t{1} << (node.level - 1));
    return mGrid->toWorld(glm::dvec3(glm::min(half, voxelEnd(node))) - 0.5);
}

} // namespace texsplat::octree
