#pragma once

#include "octree/ClassifiedGrid.h"
#include "octree/NodeRef.h"
#include "octree/OctreeNode.h"
#include "octree/detail/BitCount.h"
#include "scenegraph/WorkProgress.h"

#include <glm/common.hpp>
#include <glm/ext/vector_double3.hpp>
#include <glm/ext/vector_uint3_sized.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace texsplat::octree {

/// @brief The Laur–Hanrahan hierarchy ("Hierarchical Splatting", SIGGRAPH 1991) over a
/// classified grid: every node summarizes its voxels by their mean colour and extinction and
/// bounds the error of that summary, so that a view can splat coarse nodes where the summary
/// is good enough and refine elsewhere.
///
/// Nodes are aligned power-of-two blocks clipped to the grid, so any dimensions work (one voxel
/// thick included); an axis that is exhausted simply stops splitting. Only nodes of level >= 1
/// holding at least one non-empty voxel get a record (about 1/7 of the voxel count for dense
/// data); voxels are read from the shared grid, and empty subtrees have no nodes at all. The
/// nodes of level 3 are the grid's 8³ blocks: the build skips the blocks the grid did not
/// allocate, and the nodes above them that hold none, so its time follows the allocated blocks
/// (plus an occupancy bit per 4096 voxels of the box). The blocks' subtrees are built in
/// parallel (oneTBB) and the levels above them serially: the same nodes, bit for bit, for any
/// number of threads.
class Octree {
public:
    /// @brief Builds the hierarchy over @p grid in O(voxels) time, telling @p progress (when
    /// set) how far the build got: "building the octree" and the fraction of allocated blocks
    /// done.
    /// @throws DataError when @p grid is null; sg::Cancelled when @p progress cancels.
    explicit Octree(std::shared_ptr<const ClassifiedGrid> grid,
                    const sg::WorkProgress& progress = {});

    /// @brief The grid the leaves reference.
    [[nodiscard]] const ClassifiedGrid& grid() const { return *mGrid; }

    /// @brief Whether the grid has no non-empty voxel (then there is no root and no splat).
    [[nodiscard]] bool isEmpty() const { return mIsEmpty; }

    /// @brief The root: level `rootLevel()`, coordinates 0. Only valid when `!isEmpty()`.
    [[nodiscard]] NodeRef root() const;

    /// @brief Level of the root: the smallest L with 2^L >= the largest dimension.
    [[nodiscard]] int rootLevel() const { return mRootLevel; }

    /// @brief The largest value of any channel (R, G, B, tau) over the grid's voxels: the scale of
    /// the error measure, since no node's error exceeds it (all values are >= 0). A relative error
    /// threshold (Cut::byRelativeError()) is a fraction of it, so scaling the transfer function's
    /// opacities (colour is premultiplied by them) leaves the cut of a relative threshold alone.
    [[nodiscard]] float valueScale() const { return mValueScale; }

    /// @brief The records of the nodes of level >= 1, children before their parents.
    [[nodiscard]] const std::vector<OctreeNode>& nodes() const { return mNodes; }

    /// @brief The summary of @p node; for a voxel it is synthesized from the grid (error 0).
    [[nodiscard]] OctreeNode node(const NodeRef& node) const;

    /// @brief The child of @p node in @p octant (bit 0: upper x, bit 1: upper y, bit 2: upper z),
    /// which must be set in the node's `childMask`.
    [[nodiscard]] NodeRef child(const NodeRef& node, int octant) const {
        const OctreeNode& record = mNodes[static_cast<std::size_t>(node.index)];
        const auto bit = static_cast<unsigned>(octant);
        NodeRef result;
        result.coord = childCoord(node.coord, octant);
        result.level = node.level - 1;
        // Children are stored in octant order, so a child's rank is the number of lower bits.
        const auto rank = static_cast<std::uint64_t>(
            detail::bitCount(static_cast<std::uint8_t>(record.childMask & ((1u << bit) - 1u))));
        result.index = result.level == 0 ? mGrid->index(result.coord) : record.firstChild + rank;
        return result;
    }

    /// @brief Writes the non-empty children of @p node, in octant order, to @p children and
    /// returns how many there are (0 for a voxel).
    int children(const NodeRef& node, std::array<NodeRef, 8>& children) const;

    /// @brief First voxel (index coordinates) of @p node's block.
    [[nodiscard]] glm::u64vec3 voxelBegin(const NodeRef& node) const {
        return node.coord << glm::u64vec3(node.level);
    }

    /// @brief One past the last voxel of @p node's block, clipped to the grid.
    [[nodiscard]] glm::u64vec3 voxelEnd(const NodeRef& node) const {
        return glm::min((node.coord + std::uint64_t{1}) << glm::u64vec3(node.level),
                        mGrid->dims());
    }

    /// @brief Number of voxels (empty or not) in @p node's block.
    [[nodiscard]] std::uint64_t voxelCount(const NodeRef& node) const;

    /// @brief World-space centre of @p node's voxels: where its splat goes.
    [[nodiscard]] glm::dvec3 center(const NodeRef& node) const {
        return mGrid->toWorld(
            (glm::dvec3(voxelBegin(node)) + glm::dvec3(voxelEnd(node)) - 1.0) * 0.5);
    }

    /// @brief Lower world-space corner of the cells of @p node's voxels.
    [[nodiscard]] glm::dvec3 cellMin(const NodeRef& node) const {
        return mGrid->toWorld(glm::dvec3(voxelBegin(node)) - 0.5);
    }

    /// @brief Upper world-space corner of the cells of @p node's voxels.
    [[nodiscard]] glm::dvec3 cellMax(const NodeRef& node) const {
        return mGrid->toWorld(glm::dvec3(voxelEnd(node)) - 0.5);
    }

    /// @brief World-space positions of the three planes that separate @p node's child octants
    /// (level >= 1); an axis the node does not split has its plane at the block's upper face.
    [[nodiscard]] glm::dvec3 splitPlanes(const NodeRef& node) const;

    /// @brief Bytes used by the node records (the grid is not counted: it is shared).
    [[nodiscard]] std::uint64_t memoryBytes() const {
        return mNodes.capacity() * sizeof(OctreeNode);
    }

private:
    struct Statistics;
    struct Children;
    struct Records;
    class BlockBatches;
    static glm::u64vec3 childCoord(glm::u64vec3 coord, int octant) {
        const auto bit = static_cast<unsigned>(octant);
        return coord * std::uint64_t{2} +
               glm::u64vec3(bit & 1u, (bit >> 1) & 1u, (bit >> 2) & 1u);
    }

    // Per level above the blocks (index: level), whether each node holds an allocated block.
    using Occupancy = std::vector<std::vector<bool>>;
    Occupancy occupancy() const;
    // Whether the node of `level` at `coord` holds an allocated block (at or above the blocks).
    bool holdsBlock(int level, glm::u64vec3 coord, const Occupancy& occupied) const;
    // Calls visit(octant, childCoord) for the children of the node that lie inside the grid.
    template <typename Visit> void forEachChild(int level, glm::u64vec3 coord, Visit&& visit) const;
    // The block nodes (level min(rootLevel, 3)) holding an allocated block, in build order.
    void collectBlocks(int level, glm::u64vec3 coord, const Occupancy& occupied,
                       std::vector<glm::u64vec3>& blocks) const;
    Statistics build(int level, glm::u64vec3 coord, const Occupancy& occupied,
                     BlockBatches& blocks);
    Statistics buildSubtree(int level, glm::u64vec3 coord, Records& records) const;
    Statistics buildBlock(glm::u64vec3 block, Records& records) const;
    Statistics voxelStatistics(glm::u64vec3 voxel) const;

    std::shared_ptr<const ClassifiedGrid> mGrid;
    std::vector<OctreeNode> mNodes;
    int mRootLevel = 0;
    float mValueScale = 0.0f;
    bool mIsEmpty = true;
};

} // namespace texsplat::octree
