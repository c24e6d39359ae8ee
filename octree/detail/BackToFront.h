#pragma once

#include "octree/Cut.h"
#include "octree/Octree.h"
#include "octree/View.h"

#include <vector>

namespace texsplat::octree::detail {

/// @brief Octant bits of the far child of @p node per axis (see `traverseBackToFront()`).
inline int farOctant(const Octree& octree, const NodeRef& node, const View& view) {
    const glm::dvec3 planes = octree.splitPlanes(node);
    int far = 0;
    for (int axis = 0; axis < 3; ++axis) {
        if (view.isUpperSideFar(axis, planes[axis])) {
            far |= 1 << axis;
        }
    }
    return far;
}

/// @brief The traversal behind `traverseBackToFront()`, inlined for the per-frame splat
/// emission so that visiting a node costs no indirect call.
///
/// Visiting children by increasing `key = octant ^ far` puts first the child that is far on every
/// axis (key 0) and last the one that is near on every axis (key 7); in general a child comes
/// before every sibling that is nearer on all the axes where the two differ, and siblings that
/// are nearer on one such axis and farther on another are never crossed by a common ray.
template <typename Visit> void forEachBackToFront(const Cut& cut, const View& view, Visit&& visit) {
    const Octree& octree = cut.octree();
    if (octree.isEmpty()) {
        return;
    }
    const bool perspective = view.isPerspective();
    // An orthographic view has the same far octant for every node.
    const int orthographicFar = perspective ? 0 : farOctant(octree, octree.root(), view);
    std::vector<NodeRef> pending{octree.root()};
    while (!pending.empty()) {
        const NodeRef node = pending.back();
        pending.pop_back();
        if (!cut.isSplit(node)) {
            if (!perspective || view.depth(octree.center(node)) > 0.0) {
                visit(node);
            }
            continue;
        }
        // A box behind the eye has its centre behind it too, so only subtrees need this test.
        if (perspective && view.isBoxBehindEye(octree.cellMin(node), octree.cellMax(node))) {
            continue;
        }
        const int far = perspective ? farOctant(octree, node, view) : orthographicFar;
        const unsigned mask = octree.nodes()[static_cast<std::size_t>(node.index)].childMask;
        if (node.level == 1) {
            // Voxel children are never split: visit them at once instead of through the stack.
            for (int key = 0; key < 8; ++key) {
                const int octant = key ^ far;
                if ((mask & (1u << octant)) == 0) {
                    continue;
                }
                const NodeRef voxel = octree.child(node, octant);
                if (!perspective || view.depth(octree.center(voxel)) > 0.0) {
                    visit(voxel);
                }
            }
            continue;
        }
        // The stack pops last-in first: push the nearest child (largest key) first.
        for (int key = 7; key >= 0; --key) {
            const int octant = key ^ far;
            if ((mask & (1u << octant)) != 0) {
                pending.push_back(octree.child(node, octant));
            }
        }
    }
}

} // namespace texsplat::octree::detail
