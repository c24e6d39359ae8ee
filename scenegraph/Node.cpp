#include "scenegraph/Node.h"

#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/BoundingBoxAction.h"
#include "scenegraph/actions/SearchAction.h"

#include <algorithm>
#include <unordered_set>

namespace texsplat::sg {

Node::~Node() {
    TEXSPLAT_ASSERT(mParents.empty(), "Node::~Node(): a parent still references the node");
}

const NodeType& Node::classType() {
    static const NodeType type("Node", &FieldContainer::classType(), nullptr);
    return type;
}

void Node::doAction(Action& /*action*/) {}

std::string Node::sourceLocation() const {
    if (mSourceFile == 0) {
        return {};
    }
    return sourceFileName(mSourceFile) + ":" + std::to_string(mSourceLine) + ":" +
           std::to_string(mSourceColumn);
}

void Node::getBoundingBox(BoundingBoxAction& action) { doAction(action); }

void Node::search(SearchAction& action) {
    action.checkCurrent(*this);
    if (!action.hasTerminated()) {
        doAction(action);
    }
}

bool Node::hasAncestor(const Node& candidate) const {
    // Iterative, with a visited set: shared subgraphs are walked once, deep chains do not
    // recurse.
    std::vector<const Node*> pending{this};
    std::unordered_set<const Node*> visited{this};
    while (!pending.empty()) {
        const Node* node = pending.back();
        pending.pop_back();
        if (node == &candidate) {
            return true;
        }
        for (FieldContainer* parent : node->mParents) {
            const Node* parentNode = parent->asNode();
            if (parentNode != nullptr && visited.insert(parentNode).second) {
                pending.push_back(parentNode);
            }
        }
    }
    return false;
}

void Node::checkNoCycle(FieldContainer& parent, const Node& child, const std::string& relation) {
    const Node* parentNode = parent.asNode();
    // A child that references nothing cannot lead back up; this keeps building deep graphs
    // top-down linear.
    if (parentNode == nullptr || (&child != parentNode && child.mReferenceCount == 0)) {
        return;
    }
    if (parentNode->hasAncestor(child)) {
        throw DataError("cannot make " + child.describe() + " " + relation +
                        ": the scene graph would contain a cycle");
    }
}

void Node::touch() { notify(nullptr); }

void Node::notify(const Field* source) {
    if (mParents.empty()) {
        notifyObservers(source);
        return;
    }
    // Each ancestor hears once per change, and deep graphs do not recurse.
    std::vector<Node*> pending{this};
    std::unordered_set<FieldContainer*> visited{this};
    while (!pending.empty()) {
        Node* node = pending.back();
        pending.pop_back();
        node->notifyObservers(source);
        for (FieldContainer* parent : node->mParents) {
            if (!visited.insert(parent).second) {
                continue;
            }
            if (Node* parentNode = parent->asNode()) {
                pending.push_back(parentNode);
            } else {
                parent->notify(source);
            }
        }
    }
}

Node::Ptr Node::sharedNode() { return std::static_pointer_cast<Node>(shared_from_this()); }

void Node::addParent(FieldContainer& parent) {
    mParents.push_back(&parent);
    if (Node* parentNode = parent.asNode()) {
        ++parentNode->mReferenceCount;
    }
}

void Node::removeParent(FieldContainer& parent) {
    auto found = std::find(mParents.begin(), mParents.end(), &parent);
    TEXSPLAT_ASSERT(found != mParents.end(), "Node::removeParent(): not a parent");
    mParents.erase(found);
    if (Node* parentNode = parent.asNode()) {
        --parentNode->mReferenceCount;
    }
}

} // namespace texsplat::sg
