#include "octree/SplatEmission.h"

#include "octree/ClassifiedGrid.h"
#include "octree/Cut.h"
#include "octree/Octree.h"
#include "octree/SliceOrder.h"
#include "octree/Splat.h"
#include "octree/View.h"
#include "octree/detail/BackToFront.h"

#include <algorithm>

namespace texsplat::octree {

void emitSplats(const Cut& cut, const View& view, SplatList& splats) {
    const Octree& octree = cut.octree();
    splats.clear();
    splats.reserve(static_cast<std::size_t>(cut.splatCount()), false);
    const ClassifiedGrid& grid = octree.grid();
    detail::forEachBackToFront(cut, view, [&](const NodeRef& node) {
        Splat splat;
        if (node.level == 0) {
            // Voxels are most of a fine cut: read them straight from the grid.
            const glm::vec4 value = grid.voxel(node.index);
            splat.position = glm::vec3(grid.toWorld(glm::dvec3(node.coord)));
            splat.color = glm::vec3(value);
            splat.extinction = value.w;
        } else {
            const OctreeNode& summary = octree.nodes()[static_cast<std::size_t>(node.index)];
            const glm::u64vec3 extent = octree.voxelEnd(node) - octree.voxelBegin(node);
            splat.position = glm::vec3(octree.center(node));
            splat.size = static_cast<float>(std::max({extent.x, extent.y, extent.z}));
            splat.color = summary.meanColor;
            splat.extinction = summary.meanExtinction;
        }
        splats.add(splat);
    });
}

void emitVoxelSplats(const ClassifiedGrid& grid, const View& view, SplatList& splats) {
    splats.clear();
    SliceOrder(grid, view).forEach([&](std::uint64_t index, glm::u64vec3 voxel) {
        if (grid.isEmptyVoxel(index)) {
            return;
        }
        const glm::dvec3 position = grid.toWorld(glm::dvec3(voxel));
        if (view.isPerspective() && view.depth(position) <= 0.0) {
            return;
        }
        const glm::vec4 value = grid.voxel(index);
        Splat splat;
        splat.position = glm::vec3(position);
        splat.color = glm::vec3(value);
        splat.extinction = value.w;
        splats.add(splat);
    });
}

} // namespace texsplat::octree
