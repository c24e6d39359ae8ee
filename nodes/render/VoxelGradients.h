#pragma once

#include "octree/ClassifiedGrid.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace texsplat::render {

/// @brief The gradient of a classified grid's extinction τ at each voxel of its allocated
/// blocks, in the traversal root's space: the normals of a shaded volume (VolumeLighting).
///
/// Central differences over the voxels' index neighbours, τ taken as 0 outside the grid and in
/// blocks that are not allocated (empty), so a volume's faces and the borders of what its
/// transfer function hides are surfaces. A difference per index step becomes one per local
/// length through the spacing, and a local gradient one in root space through the inverse
/// transpose of the model matrix (a Transform that scales or shears the volume turns its normals
/// as it turns its surfaces). Made in parallel over the blocks.
class VoxelGradients {
public:
    /// @brief The gradients of `grid` placed by `model` (local to root; invertible).
    VoxelGradients(std::shared_ptr<const octree::ClassifiedGrid> grid, const glm::mat4& model);

    /// @brief The grid whose gradients these are.
    const octree::ClassifiedGrid& grid() const { return *mGrid; }

    /// @brief The gradient of the voxel stored at `storage` (ClassifiedGrid::forEachBlock()).
    glm::vec3 stored(octree::ClassifiedGrid::StorageIndex storage) const {
        return mGradients[static_cast<std::size_t>(storage)];
    }

    /// @brief The gradient at voxel `ijk` (inside the grid); zero in blocks not allocated.
    glm::vec3 at(glm::u64vec3 ijk) const;

    /// @brief Bytes held (the gradients; the grid is shared).
    std::uint64_t memoryBytes() const { return mGradients.size() * sizeof(glm::vec3); }

private:
    std::shared_ptr<const octree::ClassifiedGrid> mGrid;
    std::vector<glm::vec3> mGradients; // per storage index of mGrid
};

} // namespace texsplat::render
