#pragma once

#include "octree/Cut.h"
#include "octree/Octree.h"
#include "octree/View.h"

#include <array>
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

/// @brief How a cut's back-to-front traversal for one view goes down the octree: which split
/// nodes it enters and in which order it takes their children. `forEachBackToFront()` and the
/// parallel emission's split of the traversal into pieces (SplatEmission.cpp) share it, so
/// both give the same order.
///
/// Taking children by increasing `key = octant ^ far` puts first the child that is far on every
/// axis (key 0) and last the one that is near on every axis (key 7); in general a child comes
/// before every sibling that is nearer on all the axes where the two differ, and siblings that
/// are nearer on one such axis and farther on another are never crossed by a common ray.
class BackToFrontDescent {
public:
    BackToFrontDescent(const Cut& cut, const View& view)
        : mCut(cut), mOctree(cut.octree()), mView(view), mPerspective(view.isPerspective()) {
        // An orthographic view has the same far octant for every node, whatever its planes.
        for (int axis = 0; axis < 3 && !mPerspective; ++axis) {
            mOrthographicFar |= view.isUpperSideFar(axis, 0.0) ? 1 << axis : 0;
        }
    }

    /// @brief Whether @p node, a node of the cut, is drawn: its centre is in front of the eye.
    [[nodiscard]] bool isDrawn(const NodeRef& node) const {
        return !mPerspective || mView.depth(mOctree.center(node)) > 0.0;
    }

    /// @brief Whether the traversal enters @p node, a split node: not when its cells lie wholly
    /// behind the eye (a box behind the eye has its centre behind it too, so only split nodes
    /// need this test).
    [[nodiscard]] bool isEntered(const NodeRef& node) const {
        return !(mPerspective &&
                 mView.isBoxBehindEye(mOctree.cellMin(node), mOctree.cellMax(node)));
    }

    /// @brief Whether @p node draws nothing in the view's sight (View::seeingOnly()): its own
    /// splat when it is a node of the cut, its subtree's when it is split.
    [[nodiscard]] bool isOutOfSight(const NodeRef& node) const {
        if (!mView.hasSides()) {
            return false;
        }
        const glm::dvec3 low = mOctree.cellMin(node);
        const glm::dvec3 high = mOctree.cellMax(node);
        return mCut.isSplit(node) ? mView.isSubtreeOutOfSight(low, high)
                                  : mView.isOutOfSight(low, high);
    }

    /// @brief Whether every node below @p node (itself included) is in sight.
    [[nodiscard]] bool isWhollyInSight(const NodeRef& node) const {
        return !mView.hasSides() ||
               mView.isWhollyInSight(mOctree.cellMin(node), mOctree.cellMax(node));
    }

    /// @brief Writes the children of @p node, a split node, back to front to @p children and
    /// returns how many there are.
    int children(const NodeRef& node, std::array<NodeRef, 8>& children) const {
        const int far = mPerspective ? farOctant(mOctree, node, mView) : mOrthographicFar;
        const unsigned mask = mOctree.nodes()[static_cast<std::size_t>(node.index)].childMask;
        int count = 0;
        for (int key = 0; key < 8; ++key) {
            const int octant = key ^ far;
            if ((mask & (1u << octant)) != 0) {
                children[static_cast<std::size_t>(count++)] = mOctree.child(node, octant);
            }
        }
        return count;
    }

    [[nodiscard]] const Cut& cut() const { return mCut; }

private:
    const Cut& mCut;
    const Octree& mOctree;
    const View& mView;
    bool mPerspective;
    int mOrthographicFar = 0;
};

/// @brief The traversal behind `traverseBackToFront()` from @p start (a node of the cut or a
/// split node above it), inlined for the per-frame splat emission so that visiting a node costs
/// no indirect call.
template <typename Visit>
void forEachBackToFrontFrom(const BackToFrontDescent& descent, const NodeRef& start,
                            Visit&& visit) {
    const Cut& cut = descent.cut();
    // With each node, whether everything below it is known to be in sight: then no node below
    // needs the test (a view without sides never needs it).
    struct Pending {
        NodeRef node;
        bool inSight;
    };
    std::vector<Pending> pending{{start, descent.isWhollyInSight(start)}};
    std::array<NodeRef, 8> children;
    while (!pending.empty()) {
        const auto [node, inSight] = pending.back();
        pending.pop_back();
        if (!inSight && descent.isOutOfSight(node)) {
            continue; // it covers no pixel, nor does anything below it
        }
        if (!cut.isSplit(node)) {
            if (descent.isDrawn(node)) {
                visit(node);
            }
            continue;
        }
        if (!descent.isEntered(node)) {
            continue;
        }
        const bool below = inSight || descent.isWhollyInSight(node);
        const int count = descent.children(node, children);
        if (node.level == 1) {
            // Voxel children are never split: visit them at once instead of through the stack.
            for (int i = 0; i < count; ++i) {
                const NodeRef& voxel = children[static_cast<std::size_t>(i)];
                if ((below || !descent.isOutOfSight(voxel)) && descent.isDrawn(voxel)) {
                    visit(voxel);
                }
            }
            continue;
        }
        // The stack pops last-in first: push the nearest child first.
        for (int i = count - 1; i >= 0; --i) {
            pending.push_back({children[static_cast<std::size_t>(i)], below});
        }
    }
}

/// @brief The whole traversal behind `traverseBackToFront()`, from the root.
template <typename Visit> void forEachBackToFront(const Cut& cut, const View& view, Visit&& visit) {
    if (cut.octree().isEmpty()) {
        return;
    }
    forEachBackToFrontFrom(BackToFrontDescent(cut, view), cut.octree().root(),
                           std::forward<Visit>(visit));
}

} // namespace texsplat::octree::detail
