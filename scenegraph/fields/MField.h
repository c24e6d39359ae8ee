#pragma once

#include "scenegraph/fields/Field.h"
#include "scenegraph/fields/FieldValueReader.h"
#include "scenegraph/fields/FieldValueWriter.h"
#include "scenegraph/fields/detail/ValueTraits.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace texsplat::sg {

/// @brief A multi-valued field (MFFloat, MFVec3f, ...): a vector of `Traits::Value`.
///
/// In Inventor ASCII one value is written bare (`1.5`) and any other count in brackets
/// (`[ 1, 2, 3 ]`, `[ ]`); commas between values are optional when reading. Use the aliases in
/// Fields.h rather than this template.
template <class Traits> class MField final : public Field {
public:
    /// @brief The C++ type of one value.
    using Value = typename Traits::Value;

    /// @copydoc Field::typeName
    std::string_view typeName() const override { return Traits::kMultiName; }

    /// @brief All values.
    const std::vector<Value>& values() const { return mValues; }

    /// @brief Number of values.
    std::size_t size() const { return mValues.size(); }

    /// @brief True when there are no values.
    bool isEmpty() const { return mValues.empty(); }

    /// @brief Value `index` (< size()).
    typename std::vector<Value>::const_reference operator[](std::size_t index) const {
        return mValues[index];
    }

    /// @brief Replaces all values and notifies.
    void setValue(std::vector<Value> values) {
        mValues = std::move(values);
        valueChanged();
    }

    /// @brief Sets value `index`, growing the field with zero values if needed, and notifies.
    void set1Value(std::size_t index, const Value& value) {
        if (index >= mValues.size()) {
            mValues.resize(index + 1, Traits::defaultValue());
        }
        mValues[index] = value;
        valueChanged();
    }

    /// @copydoc Field::readValue
    void readValue(FieldValueReader& reader) override {
        std::vector<Value> values;
        if (reader.readChar('[')) {
            while (!reader.readChar(']')) {
                values.push_back(Traits::read(reader));
                reader.readChar(',');
            }
        } else {
            values.push_back(Traits::read(reader));
        }
        setValue(std::move(values));
    }

    /// @copydoc Field::writeValue
    void writeValue(FieldValueWriter& writer) const override {
        if (mValues.size() == 1) {
            writer.writeToken(Traits::format(mValues.front()));
            return;
        }
        writer.beginList();
        for (const Value& value : mValues) {
            writer.writeToken(Traits::format(value));
        }
        writer.endList();
    }

    /// @copydoc Field::copyValueFrom
    void copyValueFrom(const Field& other) override {
        checkSameType(other);
        setValue(static_cast<const MField&>(other).mValues);
    }

    /// @copydoc Field::heapBytes
    std::size_t heapBytes() const override {
        std::size_t bytes = mValues.capacity() * sizeof(Value);
        if constexpr (std::is_same_v<Value, std::string>) {
            for (const std::string& value : mValues) {
                bytes += detail::stringHeapBytes(value);
            }
        }
        return bytes;
    }

private:
    std::vector<Value> mValues;
};

} // namespace texsplat::sg
