#include "scenegraph/actions/Action.h"

#include "scenegraph/Error.h"
#include "scenegraph/actions/detail/VisitCount.h"

#include <string>

namespace texsplat::sg {

Action::~Action() = default;

void Action::apply(Node& root) {
    mState.reset();
    mPath.clear();
    mHasTerminated = false;
    if (!visitsSharedNodesOnce()) {
        const detail::VisitCount count = detail::countVisits(root, kMaxVisits);
        if (count.overLimit != nullptr) {
            DataError error("scene graph is too large to traverse: " +
                            count.overLimit->describe() + " and the nodes under it would be " +
                            "visited " + std::to_string(count.visits) +
                            " times (a node shared with DEF/USE is visited once per use), more "
                            "than the limit of " + std::to_string(kMaxVisits) + " (in the graph "
                            "under " + root.describe() + ")");
            // Where the file defines the node that multiplies the visits.
            error.locateAtNode(count.overLimit->sourceLocation());
            throw error;
        }
    }
    beginTraversal(root);
    traverse(root);
}

void Action::traverse(Node& node) {
    if (mPath.size() >= kMaxDepth) {
        throw DataError("scene graph is nested deeper than the limit of " +
                        std::to_string(kMaxDepth) + " levels (reached at " + node.describe() +
                        " under " + mPath.front()->describe() + ")");
    }
    mPath.push_back(&node);
    struct PopPath {
        std::vector<Node*>& path;
        ~PopPath() { path.pop_back(); }
    } popPath{mPath};
    // An error raised while the action is at a node starts with where the node was read, so
    // that checks made after parsing point into the scene file as syntax errors do.
    try {
        if (MethodTable::Method method = mMethods->find(node.type())) {
            method(*this, node);
        } else {
            node.doAction(*this);
        }
    } catch (Error& error) {
        error.locateAtNode(node.sourceLocation());
        throw;
    }
}

Path Action::currentPath() const {
    std::vector<Node::Ptr> nodes;
    nodes.reserve(mPath.size());
    for (Node* node : mPath) {
        nodes.push_back(node->sharedNode());
    }
    return Path(std::move(nodes));
}

void Action::beginTraversal(Node& /*root*/) {}

} // namespace texsplat::sg
