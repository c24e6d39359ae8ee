#include "octree/Octree.h"

#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

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
    // Vector grids only: the sum of the non-empty voxels' vectors and of their unit directions,
    // and how many of them have a direction (a zero vector has none).
    glm::dvec3 vectorSum{0.0};
    glm::dvec3 directionSum{0.0};
    std::uint64_t directionCount = 0;
    glm::vec3 meanVector{0.0f};

    void merge(const Statistics& other) {
        minimum = count == 0 ? other.minimum : glm::min(minimum, other.minimum);
        maximum = count == 0 ? other.maximum : glm::max(maximum, other.maximum);
        sum += other.sum;
        count += other.count;
        record.nonEmptyCount += other.record.nonEmptyCount;
        vectorSum += other.vectorSum;
        directionSum += other.directionSum;
        directionCount += other.directionCount;
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
        if (directionCount > 0) {
            meanVector = glm::vec3(vectorSum / static_cast<double>(record.nonEmptyCount));
            // 1 - |mean of the unit directions| is 0 when all voxels point the same way and 1
            // when they cancel; scaled by the largest extinction it is in the units of the other
            // channels, so one threshold weighs a turning flow like a changing opacity.
            const double spread =
                1.0 - glm::length(directionSum) / static_cast<double>(directionCount);
            error = std::max(error, static_cast<double>(maximum.w) * std::max(spread, 0.0));
        }
        record.error = static_cast<float>(error);
    }
};

namespace {

constexpr const char* kBuildStep = "building the octree";
// Reports are cheap but not free: one per this many allocated blocks (2 M voxels).
constexpr std::size_t kBlocksPerReport = 4096;

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

} // namespace

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
    BuildProgress built{progress, mGrid->blockCount()};
    sg::reportWork(progress, kBuildStep, 0.0);
    const Statistics root = build(mRootLevel, glm::u64vec3(0), occupancy(), built);
    mIsEmpty = root.record.nonEmptyCount == 0;
    mValueScale = std::max({root.maximum.r, root.maximum.g, root.maximum.b, root.maximum.a});
    if (mRootLevel > 0 && !mIsEmpty) {
        mNodes.push_back(root.record);
        if (mGrid->hasVectors()) {
            mMeanVectors.push_back(root.meanVector);
        }
    }
    mNodes.shrink_to_fit();
    mMeanVectors.shrink_to_fit();
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
    if (mGrid->hasVectors() && statistics.record.nonEmptyCount > 0) {
        const glm::vec3 vector = mGrid->vector(voxel);
        statistics.meanVector = vector;
        statistics.vectorSum = glm::dvec3(vector);
        const double length = glm::length(glm::dvec3(vector));
        if (length > 0.0) {
            statistics.directionSum = glm::dvec3(vector) / length;
            statistics.directionCount = 1;
        }
    }
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

// Depth-first and post-order: a node's children are finished (and their own subtrees stored)
// before the node appends its non-empty children contiguously, so siblings stay adjacent.
Octree::Statistics Octree::build(int level, glm::u64vec3 coord, const Occupancy& occupied,
                                 BuildProgress& progress) {
    if (level == 0) {
        return voxelStatistics(coord);
    }
    const glm::u64vec3 dims = mGrid->dims();
    Statistics statistics;
    const bool isEmpty =
        level == ClassifiedGrid::kBlockLevel
            ? !mGrid->hasBlock(coord)
            : level > ClassifiedGrid::kBlockLevel &&
                  !occupied[static_cast<std::size_t>(level)][nodeIndex(dims, level, coord)];
    if (isEmpty) {
        // No allocated block below: its voxels are empty, and only their number enters the mean
        // (what merging its empty children one by one gives: sums and bounds stay 0).
        const glm::u64vec3 begin = coord << glm::u64vec3(level);
        const glm::u64vec3 end = glm::min((coord + std::uint64_t{1}) << glm::u64vec3(level), dims);
        const glm::u64vec3 extent = end - begin;
        statistics.count = extent.x * extent.y * extent.z;
        return statistics;
    }
    if (level == ClassifiedGrid::kBlockLevel &&
        ++progress.done % kBlocksPerReport == 0) {
        sg::reportWork(progress.progress, kBuildStep,
                       static_cast<double>(progress.done) / static_cast<double>(progress.blocks));
    }
    if (level == ClassifiedGrid::kBlockLevel && !mGrid->hasVectors()) {
        return buildBlock(coord);
    }
    std::array<OctreeNode, 8> childRecords;
    std::array<glm::vec3, 8> childVectors;
    int childCount = 0;
    for (int octant = 0; octant < 8; ++octant) {
        const glm::u64vec3 child = childCoord(coord, octant);
        const glm::u64vec3 begin = child << glm::u64vec3(level - 1);
        if (begin.x >= dims.x || begin.y >= dims.y || begin.z >= dims.z) {
            continue;
        }
        const Statistics childStatistics = build(level - 1, child, occupied, progress);
        statistics.merge(childStatistics);
        if (childStatistics.record.nonEmptyCount > 0) {
            statistics.record.childMask |= static_cast<std::uint8_t>(1u << octant);
            childVectors[static_cast<std::size_t>(childCount)] = childStatistics.meanVector;
            childRecords[static_cast<std::size_t>(childCount++)] = childStatistics.record;
        }
    }
    if (level >= 2) {
        statistics.record.firstChild = mNodes.size();
        mNodes.insert(mNodes.end(), childRecords.begin(), childRecords.begin() + childCount);
        if (mGrid->hasVectors()) {
            mMeanVectors.insert(mMeanVectors.end(), childVectors.begin(),
                                childVectors.begin() + childCount);
        }
    }
    statistics.finish();
    return statistics;
}

// The subtree of an allocated block of a scalar grid, as build() makes it (the same records in
// the same order, the same sums in the same order, so the same bits) but read straight from the
// block's storage, with no per-voxel Statistics: most of the build's time is spent here.
Octree::Statistics Octree::buildBlock(glm::u64vec3 block) {
    const std::array<glm::vec4, ClassifiedGrid::kBlockVoxels>& voxels =
        mGrid->storedBlock(mGrid->blockStorage(block));
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
    std::array<OctreeNode, 8> quarterRecords; // level 2
    int quarterCount = 0;
    for (int quarterOctant = 0; quarterOctant < 8; ++quarterOctant) {
        const glm::u64vec3 quarter = offset(quarterOctant, 4);
        if (!isInside(quarter)) {
            continue;
        }
        Statistics quarterStatistics;
        std::array<OctreeNode, 8> pairRecords; // level 1
        int pairCount = 0;
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
            quarterStatistics.merge(pairStatistics);
            if (pairStatistics.record.nonEmptyCount > 0) {
                // An empty pair gets no record, so its mean and error are never needed.
                pairStatistics.finish();
                quarterStatistics.record.childMask |= static_cast<std::uint8_t>(1u << pairOctant);
                pairRecords[static_cast<std::size_t>(pairCount++)] = pairStatistics.record;
            }
        }
        quarterStatistics.record.firstChild = mNodes.size();
        mNodes.insert(mNodes.end(), pairRecords.begin(), pairRecords.begin() + pairCount);
        statistics.merge(quarterStatistics);
        if (quarterStatistics.record.nonEmptyCount > 0) {
            quarterStatistics.finish();
            statistics.record.childMask |= static_cast<std::uint8_t>(1u << quarterOctant);
            quarterRecords[static_cast<std::size_t>(quarterCount++)] = quarterStatistics.record;
        }
    }
    statistics.record.firstChild = mNodes.size();
    mNodes.insert(mNodes.end(), quarterRecords.begin(), quarterRecords.begin() + quarterCount);
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

glm::vec3 Octree::meanVector(const NodeRef& node) const {
    TEXSPLAT_ASSERT(mGrid->hasVectors(), "Octree::meanVector(): the grid has no vectors");
    return node.level == 0 ? mGrid->vector(node.coord)
                           : mMeanVectors[static_cast<std::size_t>(node.index)];
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
