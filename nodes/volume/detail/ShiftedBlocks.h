#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/IndexBox.h"

namespace texsplat::volume::detail {

/// @brief Grid::readBlock() of a grid that reads another's voxels shifted: its voxel i is voxel
/// i + `shift` of `voxels`, and holds one only inside `box` (its own indices). Voxel by voxel,
/// for grids whose blocks do not fall on the other's (a brick less its ghost cells).
template <typename T>
void readShiftedBlock(const Grid<T>& voxels, const glm::i64vec3& shift, const IndexBox& box,
                      const glm::i64vec3& block, typename Grid<T>::VoxelBlock& out) {
    constexpr std::int64_t kEdge = Grid<T>::kBlockEdge;
    const glm::i64vec3 first = block * kEdge;
    const IndexBox inBlock = box.intersection({first, first + kEdge});
    out.nonEmpty.reset();
    glm::i64vec3 index;
    for (index.z = inBlock.lo.z; index.z < inBlock.hi.z; ++index.z) {
        for (index.y = inBlock.lo.y; index.y < inBlock.hi.y; ++index.y) {
            for (index.x = inBlock.lo.x; index.x < inBlock.hi.x; ++index.x) {
                if (voxels.isActive(index + shift)) {
                    const glm::i64vec3 offset = index - first;
                    const auto slot =
                        static_cast<std::size_t>(offset.x + kEdge * (offset.y + kEdge * offset.z));
                    out.values[slot] = voxels.value(index + shift);
                    out.nonEmpty.set(slot);
                }
            }
        }
    }
}

} // namespace texsplat::volume::detail
