#pragma once

#include "scenegraph/fields/Field.h"

#include <string_view>

namespace texsplat::sg {

/// @brief A field without a value that only notifies (Inventor's SoSFTrigger): an event input
/// such as ElapsedTime's `reset`.
///
/// `setValue()` fires it: it notifies its observers, the fields connected from it and its
/// container, as any field change does, and clears the default flag. In a scene file a trigger
/// is its name alone (`reset`); reading it fires it, and the writer writes a fired trigger the
/// same way, as Coin does. A value after the name is not part of the field (`reset TRUE` is an
/// unknown field `TRUE`, in Coin too). Triggers connect only to triggers.
class SFTrigger final : public Field {
public:
    /// @brief The value type: empty, a trigger carries none (for `addField(field, name, {})`).
    struct Value {};

    /// @copydoc Field::typeName
    std::string_view typeName() const override { return "SFTrigger"; }

    /// @brief Fires the trigger.
    void setValue(Value = {}) { valueChanged(); }

    /// @brief Fires the trigger; reads nothing.
    void readValue(FieldValueReader& reader) override;

    /// @brief Writes nothing: the field's name is all of it.
    void writeValue(FieldValueWriter& writer) const override;

    /// @brief Fires the trigger (after checking that `other` is a trigger too).
    void copyValueFrom(const Field& other) override;
};

} // namespace texsplat::sg
