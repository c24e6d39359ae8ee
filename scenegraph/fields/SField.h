#pragma once

#include "scenegraph/fields/Field.h"
#include "scenegraph/fields/FieldValueReader.h"
#include "scenegraph/fields/FieldValueWriter.h"
#include "scenegraph/fields/detail/ValueTraits.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>

namespace texsplat::sg {

/// @brief A single-valued field (SFFloat, SFVec3f, ...): one value of `Traits::Value`.
///
/// `Traits` (scenegraph/fields/detail/ValueTraits.h) supplies the value type, the type name,
/// the default, and the Inventor ASCII format and parse of one value. Use the aliases in
/// Fields.h rather than this template.
template <class Traits> class SField final : public Field {
public:
    /// @brief The C++ value type (float, glm::vec3, Rotation, ...).
    using Value = typename Traits::Value;

    /// @brief A field holding the type's zero value (0, "", identity rotation/matrix).
    SField() : mValue(Traits::defaultValue()) {}

    /// @copydoc Field::typeName
    std::string_view typeName() const override { return Traits::kSingleName; }

    /// @brief The current value.
    const Value& value() const { return mValue; }

    /// @brief Sets the value and notifies (even when it is equal to the old one).
    void setValue(const Value& value) {
        mValue = value;
        valueChanged();
    }

    /// @brief Same as setValue().
    SField& operator=(const Value& value) {
        setValue(value);
        return *this;
    }

    /// @copydoc Field::readValue
    void readValue(FieldValueReader& reader) override { setValue(Traits::read(reader)); }

    /// @copydoc Field::writeValue
    void writeValue(FieldValueWriter& writer) const override {
        writer.writeToken(Traits::format(mValue));
    }

    /// @copydoc Field::copyValueFrom
    void copyValueFrom(const Field& other) override {
        checkSameType(other);
        setValue(static_cast<const SField&>(other).mValue);
    }

    /// @copydoc Field::heapBytes
    std::size_t heapBytes() const override {
        if constexpr (std::is_same_v<Value, std::string>) {
            return detail::stringHeapBytes(mValue);
        } else {
            return 0;
        }
    }

private:
    Value mValue;
};

} // namespace texsplat::sg
