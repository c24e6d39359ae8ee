#pragma once

#include "scenegraph/Node.h"

#include <cstddef>
#include <vector>

namespace texsplat::sg {

/// @brief A chain of nodes from a root down to one node (each the parent of the next), as
/// SearchAction returns it. Holds the nodes (shared ownership).
class Path {
public:
    /// @brief An empty path.
    Path() = default;

    /// @brief The path through `nodes`, root first.
    explicit Path(std::vector<Node::Ptr> nodes) : mNodes(std::move(nodes)) {}

    /// @brief Number of nodes.
    std::size_t length() const { return mNodes.size(); }

    /// @brief True when it has no nodes.
    bool isEmpty() const { return mNodes.empty(); }

    /// @brief The root (length() > 0).
    const Node::Ptr& head() const { return mNodes.front(); }

    /// @brief The last node (length() > 0).
    const Node::Ptr& tail() const { return mNodes.back(); }

    /// @brief Node `index` (< length()), 0 is the root.
    const Node::Ptr& node(std::size_t index) const { return mNodes[index]; }

    /// @brief All nodes, root first.
    const std::vector<Node::Ptr>& nodes() const { return mNodes; }

private:
    std::vector<Node::Ptr> mNodes;
};

} // namespace texsplat::sg
