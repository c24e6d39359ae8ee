#pragma once

#include "scenegraph/Fwd.h"

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

namespace texsplat::sg {

/// @brief Run-time type of a node or engine: its scene-file name, its parent type and how to
/// create one.
///
/// Every concrete class gets exactly one NodeType from `Declare<Derived, Base>::classType()`;
/// types are compared by address. The reader finds types by name in the NodeRegistry, the
/// writer prints `typeName()`, and actions look up their per-type methods with `parent()`
/// fallback (see MethodTable). Engines use the same type system because the scene-file
/// syntax treats them like nodes (`Calculator { a 1 }`).
class NodeType {
public:
    /// @brief Creates an instance; nullptr for abstract types.
    using Factory = std::shared_ptr<FieldContainer> (*)();

    /// @brief Declares a type named `name` (as written in scene files) derived from `parent`
    /// (nullptr only for the root, FieldContainer); `factory` is nullptr for abstract types.
    /// `instanceBytes`: the size of an instance (sizeof), 0 when not known.
    NodeType(std::string name, const NodeType* parent, Factory factory,
             std::size_t instanceBytes = 0);
    NodeType(const NodeType&) = delete;
    NodeType& operator=(const NodeType&) = delete;

    /// @brief The scene-file name, e.g. "Separator".
    const std::string& name() const { return mName; }

    /// @brief The parent type, nullptr for the root type FieldContainer.
    const NodeType* parent() const { return mParent; }

    /// @brief True for types that cannot be instantiated (Node, Engine, ...).
    bool isAbstract() const { return mFactory == nullptr; }

    /// @brief The bytes of an instance itself (its sizeof, without what its fields hold on the
    /// heap); 0 for abstract types. What the scene reader counts against the memory limit.
    std::size_t instanceBytes() const { return mInstanceBytes; }

    /// @brief True when this type is `other` or derives from it.
    bool isDerivedFrom(const NodeType& other) const;

    /// @brief A new default instance. Throws DataError for abstract types.
    std::shared_ptr<FieldContainer> create() const;

    /// @brief The one-line meaning of the field, engine input or engine output named
    /// `fieldName`, as its class declared it (`addField(size, "size", 1.6f, "meaning")`);
    /// empty for a name the type does not have and for abstract types.
    ///
    /// Kept here, once per type, not in the fields: the first call makes one instance and keeps
    /// what its constructors declared (thread-safe). The reference, `texsplat info --reference`
    /// and tools show it.
    const std::string& fieldDescription(std::string_view fieldName) const;

private:
    std::string mName;
    const NodeType* mParent;
    Factory mFactory;
    std::size_t mInstanceBytes;
    mutable std::once_flag mDescriptionsOnce;
    mutable std::map<std::string, std::string, std::less<>> mDescriptions;
};

} // namespace texsplat::sg
