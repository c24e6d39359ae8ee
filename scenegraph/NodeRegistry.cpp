#include "scenegraph/NodeRegistry.h"

#include "scenegraph/Error.h"
#include "scenegraph/FieldContainer.h"
#include "scenegraph/Group.h"
#include "scenegraph/Separator.h"
#include "scenegraph/Switch.h"

namespace texsplat::sg {

NodeRegistry::NodeRegistry() {
    add<Group>();
    add<Separator>();
    add<Switch>();
}

NodeRegistry& NodeRegistry::instance() {
    static NodeRegistry registry;
    return registry;
}

void NodeRegistry::add(const NodeType& type) {
    const std::lock_guard<std::mutex> lock(mMutex);
    auto [entry, isNew] = mTypes.emplace(type.name(), &type);
    if (!isNew && entry->second != &type) {
        throw DataError("cannot register node type '" + type.name() +
                        "': another type is already registered under that name");
    }
}

const NodeType* NodeRegistry::find(std::string_view name) const {
    const std::lock_guard<std::mutex> lock(mMutex);
    auto found = mTypes.find(name);
    return found != mTypes.end() ? found->second : nullptr;
}

std::shared_ptr<FieldContainer> NodeRegistry::create(std::string_view name) const {
    const NodeType* type = find(name);
    if (type == nullptr) {
        throw DataError("unknown node type '" + std::string(name) + "'");
    }
    return type->create();
}

std::vector<const NodeType*> NodeRegistry::types() const {
    const std::lock_guard<std::mutex> lock(mMutex);
    std::vector<const NodeType*> types;
    types.reserve(mTypes.size());
    for (const auto& entry : mTypes) {
        types.push_back(entry.second);
    }
    return types;
}

} // namespace texsplat::sg
