#include "nodes/render/ShadedGrid.h"

#include <tbb/parallel_for.h>

#include <array>
#include <utility>
#include <vector>

namespace texsplat::render {

std::shared_ptr<octree::ClassifiedGrid> shadedGrid(const VoxelGradients& gradients,
                                                   const VolumeLighting& lighting) {
    using octree::ClassifiedGrid;
    const ClassifiedGrid& grid = gradients.grid();
    auto shaded = std::make_shared<ClassifiedGrid>(grid.dims(), grid.spacing(), grid.origin());
    std::vector<std::pair<glm::u64vec3, ClassifiedGrid::StorageIndex>> blocks;
    blocks.reserve(grid.blockCount());
    grid.forEachBlock([&](glm::u64vec3 block, ClassifiedGrid::StorageIndex first) {
        blocks.emplace_back(block, first);
    });
    using Voxels = std::array<glm::vec4, ClassifiedGrid::kBlockVoxels>;
    std::vector<Voxels> lit(blocks.size());
    tbb::parallel_for(std::size_t{0}, blocks.size(), [&](std::size_t b) {
        const ClassifiedGrid::StorageIndex first = blocks[b].second;
        Voxels voxels;
        grid.readBlock(first, voxels);
        for (std::size_t i = 0; i < voxels.size(); ++i) {
            const glm::vec4& voxel = voxels[i];
            lit[b][i] = voxel == glm::vec4(0.0f)
                            ? voxel
                            : glm::vec4(lighting.shade(glm::vec3(voxel), voxel.w,
                                                       gradients.stored(first + i)),
                                        voxel.w);
        }
    });
    if (grid.hasVectors()) {
        shaded->enableVectors();
    }
    constexpr std::uint64_t kSize = ClassifiedGrid::kBlockSize;
    const glm::u64vec3 dims = grid.dims();
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        const auto [block, first] = blocks[b];
        shaded->setBlock(block, lit[b]);
        if (!grid.hasVectors()) {
            continue;
        }
        for (std::uint64_t z = 0; z < kSize; ++z)
            for (std::uint64_t y = 0; y < kSize; ++y)
                for (std::uint64_t x = 0; x < kSize; ++x) {
                    const glm::u64vec3 ijk = block * kSize + glm::u64vec3(x, y, z);
                    if (ijk.x < dims.x && ijk.y < dims.y && ijk.z < dims.z &&
                        lit[b][ClassifiedGrid::offsetInBlock(ijk)] != glm::vec4(0.0f)) {
                        shaded->setVector(ijk, grid.storedVector(
                                                   first + ClassifiedGrid::offsetInBlock(ijk)));
                    }
                }
    }
    return shaded;
}

} // namespace texsplat::render
