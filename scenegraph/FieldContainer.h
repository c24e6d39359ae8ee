#pragma once

#include "scenegraph/Notifier.h"
#include "scenegraph/NodeType.h"

#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace texsplat::sg {

/// @brief Common base of Node and Engine: something that owns named, typed fields.
///
/// Fields are public members of the derived class, registered once in its constructor with
/// `addField(member, "name", default, "meaning")`. That one registration is what the reader, the writer
/// and the registry use: `fields()` lists them in declaration order, `findField(name)` finds one.
/// Containers are always owned by `std::shared_ptr` (created by `T::create()`).
class FieldContainer : public Notifier, public std::enable_shared_from_this<FieldContainer> {
public:
    /// @brief Shared ownership, as used by DEF/USE and connections.
    using Ptr = std::shared_ptr<FieldContainer>;

    ~FieldContainer() override;

    /// @brief The root of the type hierarchy ("FieldContainer", abstract).
    static const NodeType& classType();

    /// @brief The run-time type of this instance.
    virtual const NodeType& type() const = 0;

    /// @brief Shorthand for `type().name()`, e.g. "Separator".
    const std::string& typeName() const { return type().name(); }

    /// @brief The fields in declaration order (base class fields first).
    const std::vector<Field*>& fields() const { return mFields; }

    /// @brief The field named `name`, or nullptr.
    Field* findField(std::string_view name) const;

    /// @brief The name used for DEF/USE and SearchAction; empty when unnamed.
    const std::string& name() const;

    /// @brief Sets the name. Throws DataError unless it is a valid Inventor name that scene files
    /// can hold: it must not start with a digit or `#` and must not contain whitespace, control
    /// characters or any of `"'+,.[\]{}`. An empty name removes it.
    void setName(std::string name);

    /// @brief "Type" or "Type(name)": how error messages refer to this container.
    std::string describe() const;

    /// @brief This object as a Node, or nullptr for an engine. Cheaper than dynamic_cast.
    virtual Node* asNode() { return nullptr; }

    /// @brief Notifies observers that this container changed (`source` may be nullptr);
    /// nodes pass the notification on to their parents, engines re-evaluate.
    virtual void notify(const Field* source);

protected:
    FieldContainer() = default;

    /// @brief Registers `field` under `name`, gives it its default value (it then reports
    /// `isDefault()`) and declares its one-line meaning (NodeType::fieldDescription(); say what
    /// it does, its unit and its range, not its type or default, which the reference shows).
    /// Call once per field, in the constructor. The value type is whatever the field's
    /// `setValue()` accepts.
    template <class F, class V>
    void addField(F& field, std::string_view name, V&& defaultValue, const char* description) {
        field.setValue(std::forward<V>(defaultValue));
        attachField(field, internedName(name), description);
    }

    /// @brief Registers an enumerated field: its value names, default and meaning, declared once.
    template <class F, class E>
    void addField(F& field, std::string_view name, E defaultValue, const EnumNames& names,
                  const char* description) {
        field.setEnumNames(names);
        addField(field, name, defaultValue, description);
    }

    /// @brief As addField(), for a name that no class declares (an unknown node's field, named
    /// in a file). The fields of a declared name share one interned string, kept for the life of
    /// the process; this one is not interned: the caller keeps `name` unchanged for the field's
    /// life.
    template <class F, class V>
    void addFieldNamedBy(F& field, const std::string& name, V&& defaultValue,
                         const char* description) {
        field.setValue(std::forward<V>(defaultValue));
        attachField(field, name, description);
    }

private:
    static const std::string& internedName(std::string_view name);
    void attachField(Field& field, const std::string& name, const char* description);

    std::vector<Field*> mFields;
    // Made when a name is set: most nodes have none (8 bytes, not a string's 32).
    std::unique_ptr<std::string> mName;
};

} // namespace texsplat::sg
