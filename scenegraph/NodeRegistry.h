#pragma once

#include "scenegraph/NodeType.h"

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace texsplat::sg {

/// @brief The types the scene-file reader can create by name: built-ins and the application's.
///
/// The one process-wide singleton of the scene graph (`instance()`); it only maps names to the
/// static NodeType objects, and is thread-safe. The core types (Group, Separator, Switch) are
/// registered when it is first used; other libraries register theirs with one call (e.g.
/// `texsplat::nodes::registerNodeTypes()`), and an application adds its own:
/// `NodeRegistry::instance().add<MyNode>()`. Registered types are read and written exactly like
/// built-ins, since both use the type's field declaration.
class NodeRegistry {
public:
    NodeRegistry(const NodeRegistry&) = delete;
    NodeRegistry& operator=(const NodeRegistry&) = delete;

    /// @brief The process-wide registry.
    static NodeRegistry& instance();

    /// @brief Registers a type (again is a no-op). Throws DataError if another type already
    /// has its name.
    void add(const NodeType& type);

    /// @brief Registers `T::classType()`.
    template <class T> void add() { add(T::classType()); }

    /// @brief The type named `name`, or nullptr.
    const NodeType* find(std::string_view name) const;

    /// @brief A new instance of the type named `name`. Throws DataError for unknown or
    /// abstract types.
    std::shared_ptr<FieldContainer> create(std::string_view name) const;

    /// @brief Every registered type, sorted by name.
    std::vector<const NodeType*> types() const;

private:
    NodeRegistry();

    mutable std::mutex mMutex;
    std::map<std::string, const NodeType*, std::less<>> mTypes;
};

} // namespace texsplat::sg
