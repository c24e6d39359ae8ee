#pragma once

#include <glm/vec3.hpp>

#include <cstdint>

namespace texsplat::octree {

/// @brief The summary an `Octree` keeps for one node (Laur & Hanrahan 1991): what a single
/// splat standing for all the node's voxels needs, and how wrong that splat may be. 40 bytes.
struct OctreeNode {
    /// @brief Mean classified colour of the node's voxels (empty voxels count as zero).
    glm::vec3 meanColor{0.0f};
    /// @brief Mean extinction of the node's voxels (empty voxels count as zero).
    float meanExtinction = 0.0f;
    /// @brief Largest absolute deviation of any voxel's colour channel or extinction from the
    /// node's mean: every voxel the splat replaces is within `error` of it (docs/octree.md).
    float error = 0.0f;
    /// @brief Bit o set when child octant o (bit 0: upper x, bit 1: upper y, bit 2: upper z)
    /// exists and holds a non-empty voxel. Empty children have no record (pruned).
    std::uint8_t childMask = 0;
    /// @brief For level >= 2: index in `Octree::nodes()` of the first child record; the
    /// non-empty children follow in octant order. Unused at level 1 (children are voxels).
    std::uint64_t firstChild = 0;
    /// @brief Number of non-empty voxels under the node.
    std::uint64_t nonEmptyCount = 0;
};

} // namespace texsplat::octree
