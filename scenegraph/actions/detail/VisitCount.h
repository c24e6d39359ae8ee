#pragma once

#include "scenegraph/Fwd.h"

#include <cstdint>

namespace texsplat::sg::detail {

/// @brief What countVisits() found.
struct VisitCount {
    /// @brief Node visits a traversal of the whole graph makes (the root's count), or, when
    /// `overLimit` is set, the visits under that node.
    std::uint64_t visits = 0;
    /// @brief The first node (children before parents) whose subgraph alone takes more visits
    /// than the limit, or nullptr when the whole graph is within it.
    const Node* overLimit = nullptr;
};

/// @brief How many times a traversal that visits every child of every Group visits a node of
/// the graph under `root`: a node shared with DEF/USE is visited once per path to it, so a
/// graph of n nodes can take 2^n visits. Counted without traversing: each node's count is
/// 1 + its children's counts, memoized for nodes with several parents, so this costs one step
/// per distinct node and reference. Stops at the first node over `limit` and returns it.
/// Iterative, so any depth is fine.
VisitCount countVisits(const Node& root, std::uint64_t limit);

} // namespace texsplat::sg::detail
