#pragma once

#include <glm/ext/vector_uint3_sized.hpp>

#include <cstdint>

namespace texsplat::octree {

/// @brief A node of an `Octree` as traversals see it: where it is and where its data lives.
///
/// A node at level L with coordinates c covers the voxels `[c * 2^L, min((c + 1) * 2^L, dims))`
/// (clipped at the grid's far faces, so any dimensions work). Level 0 is a single voxel.
struct NodeRef {
    /// @brief Index of the node's record in `Octree::nodes()` for level >= 1; the voxel's linear
    /// grid index for level 0 (leaves reference the grid instead of copying it).
    std::uint64_t index = 0;
    /// @brief Coordinates of the node among the nodes of its level.
    glm::u64vec3 coord{0};
    /// @brief Level above the voxels: 0 for a voxel, the node spans 2^level voxels per axis.
    int level = 0;
};

} // namespace texsplat::octree
