#include "scenegraph/actions/MethodTable.h"

#include "scenegraph/NodeType.h"

namespace texsplat::sg {

MethodTable::Method MethodTable::find(const NodeType& type) const {
    for (const NodeType* current = &type; current != nullptr; current = current->parent()) {
        auto found = mMethods.find(current);
        if (found != mMethods.end()) {
            return found->second;
        }
    }
    return nullptr;
}

} // namespace texsplat::sg
