#include "scenegraph/NodeType.h"

#include "scenegraph/Error.h"
#include "scenegraph/detail/FieldDescriptions.h"

namespace texsplat::sg {

NodeType::NodeType(std::string name, const NodeType* parent, Factory factory,
                   std::size_t instanceBytes)
    : mName(std::move(name)), mParent(parent), mFactory(factory),
      mInstanceBytes(factory == nullptr ? 0 : instanceBytes) {}

bool NodeType::isDerivedFrom(const NodeType& other) const {
    for (const NodeType* type = this; type != nullptr; type = type->mParent) {
        if (type == &other) {
            return true;
        }
    }
    return false;
}

std::shared_ptr<FieldContainer> NodeType::create() const {
    if (mFactory == nullptr) {
        throw DataError("cannot create a " + mName + ": it is an abstract type");
    }
    return mFactory();
}

const std::string& NodeType::fieldDescription(std::string_view fieldName) const {
    std::call_once(mDescriptionsOnce,
                   [this] { mDescriptions = detail::collectFieldDescriptions(*this); });
    static const std::string kNone;
    const auto found = mDescriptions.find(fieldName);
    return found == mDescriptions.end() ? kNone : found->second;
}

} // namespace texsplat::sg
