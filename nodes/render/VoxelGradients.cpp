#include "nodes/render/VoxelGradients.h"

#include "scenegraph/Assert.h"

#include <glm/matrix.hpp>
#include <tbb/parallel_for.h>

#include <array>

namespace texsplat::render {

VoxelGradients::VoxelGradients(std::shared_ptr<const octree::ClassifiedGrid> grid,
                               const glm::mat4& model)
    : mGrid(std::move(grid)) {
    TEXSPLAT_ASSERT(mGrid, "VoxelGradients: no grid");
    const octree::ClassifiedGrid& voxels = *mGrid;
    mGradients.assign(voxels.blockCount() * octree::ClassifiedGrid::kBlockVoxels, glm::vec3(0.0f));
    // Index differences to root space: (M⁻¹)ᵀ · S⁻¹, S the spacing, M the model's linear part.
    const glm::dvec3 spacing = voxels.spacing();
    const glm::dmat3 perLength(1.0 / (2.0 * spacing.x), 0.0, 0.0, 0.0, 1.0 / (2.0 * spacing.y),
                               0.0, 0.0, 0.0, 1.0 / (2.0 * spacing.z));
    const glm::mat3 toRoot(glm::transpose(glm::inverse(glm::dmat3(model))) * perLength);
    const glm::u64vec3 dims = voxels.dims();
    std::vector<std::pair<glm::u64vec3, octree::ClassifiedGrid::StorageIndex>> blocks;
    blocks.reserve(voxels.blockCount());
    voxels.forEachBlock([&](glm::u64vec3 block, octree::ClassifiedGrid::StorageIndex first) {
        blocks.emplace_back(block, first);
    });
    // τ at `ijk` moved by `step` along `axis`, 0 outside the grid.
    const auto extinction = [&](glm::u64vec3 ijk, int axis, int step) {
        if ((step < 0 && ijk[axis] == 0) || (step > 0 && ijk[axis] + 1 >= dims[axis])) {
            return 0.0f;
        }
        ijk[axis] = step < 0 ? ijk[axis] - 1 : ijk[axis] + 1;
        return voxels.voxel(ijk).w;
    };
    constexpr std::uint64_t kSize = octree::ClassifiedGrid::kBlockSize;
    tbb::parallel_for(std::size_t{0}, blocks.size(), [&](std::size_t b) {
        const auto [block, first] = blocks[b];
        const glm::u64vec3 origin = block * kSize;
        for (std::uint64_t z = 0; z < kSize; ++z)
            for (std::uint64_t y = 0; y < kSize; ++y)
                for (std::uint64_t x = 0; x < kSize; ++x) {
                    const glm::u64vec3 ijk = origin + glm::u64vec3(x, y, z);
                    if (ijk.x >= dims.x || ijk.y >= dims.y || ijk.z >= dims.z) {
                        continue; // a block clipped by the grid's upper faces
                    }
                    glm::vec3 difference;
                    for (int axis = 0; axis < 3; ++axis) {
                        difference[axis] = extinction(ijk, axis, 1) - extinction(ijk, axis, -1);
                    }
                    mGradients[static_cast<std::size_t>(
                        first + octree::ClassifiedGrid::offsetInBlock(ijk))] = toRoot * difference;
                }
    });
}

glm::vec3 VoxelGradients::at(glm::u64vec3 ijk) const {
    const octree::ClassifiedGrid::StorageIndex first =
        mGrid->blockStorage(ijk / octree::ClassifiedGrid::kBlockSize);
    return first == octree::ClassifiedGrid::kNoStorage
               ? glm::vec3(0.0f)
               : stored(first + octree::ClassifiedGrid::offsetInBlock(ijk));
}

} // namespace texsplat::render
