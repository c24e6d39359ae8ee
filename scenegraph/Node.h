#pragma once

#include "scenegraph/Error.h"
#include "scenegraph/FieldContainer.h"
#include "scenegraph/SourceFiles.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace texsplat::sg {

/// @brief Base of every scene-graph node.
///
/// Nodes hold fields, are shared (`Ptr`; a node may have several parents, as with DEF/USE) and
/// take part in actions. Each action calls one virtual on the node: `getBoundingBox()`,
/// `search()`, and, for actions added by other libraries, the method registered in that
/// action's MethodTable; when a node has nothing specific to do it uses `doAction()`, the
/// generic traversal (Group: visit children; Separator: also save/restore state; a transform:
/// change the model matrix).
///
/// A change of a field, or `touch()`, notifies the node's observers and then those of every
/// ancestor (each once, iteratively, so deep graphs do not exhaust the stack).
class Node : public FieldContainer {
public:
    /// @brief Shared ownership.
    using Ptr = std::shared_ptr<Node>;

    ~Node() override;

    /// @brief The abstract type "Node".
    static const NodeType& classType();

    /// @brief What every action does unless the node has a more specific method: nothing for a
    /// leaf; groups traverse their children.
    virtual void doAction(Action& action);

    /// @brief BoundingBoxAction: extend the box by this node's geometry. Default: doAction().
    virtual void getBoundingBox(BoundingBoxAction& action);

    /// @brief SearchAction: report a match, then doAction() unless the search terminated.
    virtual void search(SearchAction& action);

    /// @brief Nodes and engines that reference this node (children lists, SFNode/MFNode
    /// fields), once per reference. Non-owning.
    const std::vector<FieldContainer*>& parents() const { return mParents; }

    /// @brief True when `candidate` is this node or one of its ancestors (through children and
    /// node fields). Used to reject cycles.
    bool hasAncestor(const Node& candidate) const;

    /// @brief Throws DataError when making `child` referenced by `parent` would put a cycle in
    /// the graph. `relation` says how, for the message: "a child of Group(g)".
    static void checkNoCycle(FieldContainer& parent, const Node& child,
                             const std::string& relation);

    /// @brief Notifies observers and ancestors without a field change (`source` nullptr).
    void touch();

    /// @copydoc FieldContainer::asNode
    Node* asNode() override { return this; }

    /// @copydoc FieldContainer::notify
    void notify(const Field* source) override;

    /// @brief This node as a shared pointer (nodes are always created by `create()`).
    Ptr sharedNode();

    /// @brief Records where the node was read: at `line`, `column` (from 1) of `file`. The
    /// scene reader calls it; errors raised while an action is at the node start with it.
    void setSourceLocation(SourceFileId file, std::uint32_t line, std::uint32_t column) {
        mSourceFile = file;
        mSourceLine = line;
        mSourceColumn = column;
    }

    /// @brief "scene.iv:12:5", where the node was read; empty for a node made in code.
    std::string sourceLocation() const;

protected:
    Node() = default;

private:
    friend class Group;
    friend class SFNode;
    friend class MFNode;

    void addParent(FieldContainer& parent);
    void removeParent(FieldContainer& parent);

    std::vector<FieldContainer*> mParents;
    // How many nodes this node references (children, node fields): zero means no cycle can
    // pass through it. 32 bits, like the location, so that the location costs 8 bytes a node.
    std::uint32_t mReferenceCount = 0;
    SourceFileId mSourceFile = 0;
    std::uint32_t mSourceLine = 0;
    std::uint32_t mSourceColumn = 0;
};

/// @brief Runs `work` and answers what it answers; a texsplat::Error it throws gets `node`'s place
/// in its scene file in front (Error::locateAtNode()), as when an action is at the node. For
/// checks made outside a traversal (a colour bar's transfer function, the command line's zoom
/// of the scene's camera), so that they point into the file as traversals do.
template <class Work> decltype(auto) withNodeLocation(const Node& node, Work&& work) {
    try {
        return work();
    } catch (Error& error) {
        error.locateAtNode(node.sourceLocation());
        throw;
    }
}

} // namespace texsplat::sg
