#include "scenegraph/actions/SearchAction.h"

namespace texsplat::sg {

SearchAction::SearchAction() : Action(methods()) {}

MethodTable& SearchAction::methods() {
    static MethodTable table = [] {
        MethodTable initial;
        initial.add<&Node::search>();
        return initial;
    }();
    return table;
}

void SearchAction::setType(const NodeType& type, bool derived) {
    mType = &type;
    mIsDerivedTypeMatching = derived;
}

bool SearchAction::matches(const Node& node) const {
    if (mName && node.name() != *mName) {
        return false;
    }
    if (mType != nullptr) {
        return mIsDerivedTypeMatching ? node.type().isDerivedFrom(*mType) : &node.type() == mType;
    }
    return true;
}

void SearchAction::checkCurrent(const Node& node) {
    if (matches(node)) {
        mPaths.push_back(currentPath());
        if (mInterest == Interest::First) {
            setTerminated();
        }
    }
}

void SearchAction::beginTraversal(Node& /*root*/) { mPaths.clear(); }

} // namespace texsplat::sg
