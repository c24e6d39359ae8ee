#pragma once

#include "scenegraph/actions/MethodTable.h"
#include "scenegraph/actions/Path.h"
#include "scenegraph/WorkProgress.h"
#include "scenegraph/actions/State.h"

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace texsplat::sg {

/// @brief Base of every action: a traversal of the graph with a State and the current path.
///
/// `apply(root)` resets the state, calls `beginTraversal()` and traverses `root`.
/// `traverse(node)` dispatches on the node's type through the action's MethodTable (nearest
/// registered ancestor type), falling back to `Node::doAction()`; groups call `traverse()` on
/// their children. Traversal deeper than kMaxDepth throws DataError, so a pathological graph
/// cannot exhaust the stack; so does a graph whose traversal would visit more than kMaxVisits
/// nodes (nodes shared with DEF/USE are visited once per use, so 64 groups that each USE the
/// previous one twice would take 2^64 visits), checked by counting before traversing, so such a
/// graph fails at once instead of hanging.
///
/// A new action: derive, give it `static MethodTable& methods()` (entries for the node types
/// it treats specially, e.g. `Node` → a virtual on Node, or per-class render methods), pass
/// that table to this constructor, and read/write State elements from the node methods.
class Action {
public:
    /// @brief Deepest path a traversal may reach.
    static constexpr std::size_t kMaxDepth = 4096;

    /// @brief Most node visits one traversal may make (about a second of traversal).
    static constexpr std::uint64_t kMaxVisits = 10'000'000;

    Action(const Action&) = delete;
    Action& operator=(const Action&) = delete;
    virtual ~Action();

    /// @brief Traverses the graph under `root` from a fresh state.
    void apply(Node& root);

    /// @brief Visits one node (called by groups for their children).
    void traverse(Node& node);

    /// @brief The traversal state.
    State& state() { return mState; }

    /// @brief Nodes from the root to the node being visited (non-owning).
    const std::vector<Node*>& pathNodes() const { return mPath; }

    /// @brief The current path as a Path (shares the nodes).
    Path currentPath() const;

    /// @brief True after setTerminated(): groups stop visiting children.
    bool hasTerminated() const { return mHasTerminated; }

    /// @brief Ends the traversal early (e.g. SearchAction found its first match).
    void setTerminated() { mHasTerminated = true; }

    /// @brief Where the long steps of this action's traversals (classification, the octree
    /// build) report how they go, and may be cancelled; none by default.
    void setWorkProgress(WorkProgress progress) { mWorkProgress = std::move(progress); }

    /// @brief What setWorkProgress() set (empty when nothing).
    const WorkProgress& workProgress() const { return mWorkProgress; }

protected:
    /// @brief An action dispatching through `methods` (usually the subclass's static table).
    explicit Action(const MethodTable& methods) : mMethods(&methods) {}

    /// @brief Called by apply() after the reset, before traversing: clear per-apply results.
    virtual void beginTraversal(Node& root);

    /// @brief Whether this action visits a shared node once however often it is used (as the
    /// writer does, writing USE); such an action is not bound by kMaxVisits.
    virtual bool visitsSharedNodesOnce() const { return false; }

private:
    const MethodTable* mMethods;
    State mState;
    std::vector<Node*> mPath;
    bool mHasTerminated = false;
    WorkProgress mWorkProgress;
};

} // namespace texsplat::sg
