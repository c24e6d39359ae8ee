#include "scenegraph/Group.h"

#include "scenegraph/Error.h"
#include "scenegraph/actions/Action.h"

#include <string>

namespace texsplat::sg {

Group::~Group() {
    // Releasing a deep chain recursively would overflow the stack: take over the children of
    // every group that dies with this one and release them from this loop instead.
    std::vector<Node::Ptr> pending = std::move(mChildren);
    mChildren.clear();
    for (const Node::Ptr& child : pending) {
        child->removeParent(*this);
    }
    while (!pending.empty()) {
        Node::Ptr node = std::move(pending.back());
        pending.pop_back();
        auto* group = node.use_count() == 1 ? dynamic_cast<Group*>(node.get()) : nullptr;
        if (group != nullptr) {
            for (Node::Ptr& child : group->mChildren) {
                child->removeParent(*group);
                pending.push_back(std::move(child));
            }
            group->mChildren.clear();
        }
    }
}

void Group::addChild(Node::Ptr child) { insertChild(std::move(child), mChildren.size()); }

void Group::insertChild(Node::Ptr child, std::size_t index) {
    checkIndex(index, mChildren.size() + 1);
    checkChild(child);
    child->addParent(*this);
    mChildren.insert(mChildren.begin() + static_cast<std::ptrdiff_t>(index), std::move(child));
    touch();
}

void Group::replaceChild(std::size_t index, Node::Ptr child) {
    checkIndex(index, mChildren.size());
    checkChild(child);
    child->addParent(*this);
    mChildren[index]->removeParent(*this);
    // Keep the old child alive until the notification is over.
    Node::Ptr old = std::exchange(mChildren[index], std::move(child));
    touch();
}

void Group::removeChild(std::size_t index) {
    checkIndex(index, mChildren.size());
    Node::Ptr old = std::move(mChildren[index]);
    mChildren.erase(mChildren.begin() + static_cast<std::ptrdiff_t>(index));
    old->removeParent(*this);
    touch();
}

void Group::removeAllChildren() {
    std::vector<Node::Ptr> old = std::move(mChildren);
    mChildren.clear();
    for (const Node::Ptr& child : old) {
        child->removeParent(*this);
    }
    touch();
}

std::optional<std::size_t> Group::findChild(const Node& node) const {
    for (std::size_t i = 0; i < mChildren.size(); ++i) {
        if (mChildren[i].get() == &node) {
            return i;
        }
    }
    return std::nullopt;
}

void Group::doAction(Action& action) {
    for (std::size_t i = 0; i < mChildren.size() && !action.hasTerminated(); ++i) {
        traverseChild(action, i);
    }
}

void Group::traverseChild(Action& action, std::size_t index) {
    // A copy keeps the child alive if the traversal removes it from this group.
    const Node::Ptr child = mChildren[index];
    action.traverse(*child);
}

void Group::checkChild(const Node::Ptr& child) {
    if (!child) {
        throw DataError(describe() + ": cannot add a null child");
    }
    Node::checkNoCycle(*this, *child, "a child of " + describe());
}

void Group::checkIndex(std::size_t index, std::size_t limit) const {
    if (index >= limit) {
        throw DataError(describe() + ": child index " + std::to_string(index) +
                        " is out of range (" + std::to_string(mChildren.size()) + " children)");
    }
}

} // namespace texsplat::sg
