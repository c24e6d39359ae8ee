#pragma once

#include "scenegraph/NodeType.h"

#include <cstddef>
#include <memory>
#include <type_traits>

namespace texsplat::sg {

/// @brief Gives a node or engine class its type, its `Ptr` and its `create()`: derive from
/// `Declare<Derived, Base>` instead of `Base`, and declare the scene-file name once:
/// @code
/// class Cube : public sg::Declare<Cube, sg::Node> {
/// public:
///     static constexpr const char* kTypeName = "Cube";
///     sg::SFFloat size;
/// protected:
///     Cube() { addField(size, "size", 2.0f, "Length of each edge, in model units"); }
/// };
/// @endcode
/// Keep the constructor protected (or public) and non-final: `create()` is the only way to make
/// an instance, so that every node is owned by a `std::shared_ptr`.
template <class Derived, class Base> class Declare : public Base {
public:
    /// @brief Shared ownership of the concrete type.
    using Ptr = std::shared_ptr<Derived>;

    /// @brief A new instance with default field values.
    static Ptr create() {
        // A derived helper reaches a protected constructor that make_shared cannot.
        struct Made final : Derived {};
        return std::make_shared<Made>();
    }

    /// @brief The type of `Derived`: name `Derived::kTypeName`, parent `Base::classType()`,
    /// abstract when `Derived` is.
    static const NodeType& classType() {
        static const NodeType type(Derived::kTypeName, &Base::classType(), factory(),
                                   instanceBytes());
        return type;
    }

    /// @copydoc FieldContainer::type
    const NodeType& type() const override { return classType(); }

protected:
    Declare() = default;

private:
    static std::size_t instanceBytes() {
        if constexpr (std::is_abstract_v<Derived>) {
            return 0;
        } else {
            return sizeof(Derived);
        }
    }

    static NodeType::Factory factory() {
        if constexpr (std::is_abstract_v<Derived>) {
            return nullptr;
        } else {
            return []() -> std::shared_ptr<FieldContainer> { return create(); };
        }
    }
};

} // namespace texsplat::sg
