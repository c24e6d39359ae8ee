#pragma once

#include "octree/Fwd.h"
#include "octree/NodeRef.h"

#include <functional>

namespace texsplat::octree {

/// @brief Visits the nodes of @p cut back to front for @p view: the order in which their
/// splats must be composited with the "over" operator (Crawfis & Max 1993: "the
/// splats are built up in back to front order").
///
/// The octree is walked from the root, each split node's children far to near: per axis, the
/// child on the far side of the node's centre plane (for a perspective view, the side away from
/// the eye; for an orthographic view, the side the direction points to) comes first. This is a
/// visibility order of the nodes' cells, with no sort (docs/octree.md has the proof sketch).
/// For a perspective view, subtrees whose cells lie wholly behind the eye plane and nodes whose
/// centre is not in front of it are culled: they cannot be projected. For a view with sides
/// (View::seeingOnly()), nodes of the cut whose splats lie wholly out of sight are left out, and
/// split nodes whose subtree does (View::isSubtreeOutOfSight()) with everything below them: they
/// cover no pixel. Kernels reach past their
/// cells, so overlapping splats may be out of centre-depth order; `sortByDepth()` fixes that.
void traverseBackToFront(const Cut& cut, const View& view,
                         const std::function<void(const NodeRef&)>& visit);

} // namespace texsplat::octree
