#pragma once

#include "scenegraph/EnumNames.h"
#include "scenegraph/fields/Field.h"

#include <string>
#include <string_view>

namespace texsplat::sg {

/// @brief An enumerated value, written by name (`operator BLEND`).
///
/// Its names come from the EnumNames given to `addField(field, "name", default, names)`; the
/// C++ enum is converted through int, so any enum type works:
/// `textureOperator.setValue(Operator::Blend)`, `textureOperator.as<Operator>()`.
class SFEnum final : public Field {
public:
    /// @copydoc Field::typeName
    std::string_view typeName() const override { return "SFEnum"; }

    /// @brief The value as int.
    int value() const { return mValue; }

    /// @brief The value as the enum type `E`.
    template <class E> E as() const { return static_cast<E>(mValue); }

    /// @brief Sets the value (any enum type or int). Throws DataError when the names are known
    /// and `value` is not among them.
    template <class E> void setValue(E value) { setInt(static_cast<int>(value)); }

    /// @brief Sets the value named `name` ("BLEND"), as a scene file names it.
    /// @throws DataError "unknown value 'X' for SFEnum Node.field (expected one of A, B)" (the
    /// reader's message) for a name that is not among the value names.
    void setValueName(std::string_view name);

    /// @brief The name of the value ("BLEND"), or its number as text when it has no name.
    std::string valueName() const;

    /// @brief The value names; nullptr until set by addField().
    const EnumNames* enumNames() const { return mNames; }

    /// @brief Sets the value names (not owned: they must outlive the field; usually static).
    void setEnumNames(const EnumNames& names) { mNames = &names; }

    /// @copydoc Field::readValue
    void readValue(FieldValueReader& reader) override;

    /// @copydoc Field::writeValue
    void writeValue(FieldValueWriter& writer) const override;

    /// @copydoc Field::copyValueFrom
    void copyValueFrom(const Field& other) override;

private:
    void setInt(int value);

    int mValue = 0;
    const EnumNames* mNames = nullptr;
};

} // namespace texsplat::sg
