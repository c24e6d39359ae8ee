#include "scenegraph/fields/SFEnum.h"

#include "scenegraph/Error.h"
#include "scenegraph/fields/FieldValueReader.h"
#include "scenegraph/fields/FieldValueWriter.h"

#include <optional>
#include <string>
#include <string_view>

namespace texsplat::sg {

namespace {

// The value `name` names in `names`, or the message saying why there is none.
std::optional<int> namedValue(const EnumNames* names, std::string_view name,
                              const std::string& fieldName, std::string& message) {
    if (names == nullptr) {
        message = "SFEnum " + fieldName + " has no value names, cannot read '" +
                  std::string(name) + "'";
        return std::nullopt;
    }
    const std::optional<int> value = names->value(name);
    if (!value) {
        message = "unknown value '" + std::string(name) + "' for SFEnum " + fieldName +
                  " (expected one of " + names->list() + ")";
    }
    return value;
}

} // namespace

void SFEnum::readValue(FieldValueReader& reader) {
    const std::string name = reader.readName();
    std::string message;
    const std::optional<int> value = namedValue(mNames, name, fullName(), message);
    if (!value) {
        reader.fail(message);
    }
    setInt(*value);
}

void SFEnum::setValueName(std::string_view name) {
    std::string message;
    const std::optional<int> value = namedValue(mNames, name, fullName(), message);
    if (!value) {
        throw DataError(message);
    }
    setInt(*value);
}

std::string SFEnum::valueName() const {
    const std::string* name = mNames != nullptr ? mNames->name(mValue) : nullptr;
    return name != nullptr ? *name : std::to_string(mValue);
}

void SFEnum::writeValue(FieldValueWriter& writer) const { writer.writeToken(valueName()); }

void SFEnum::copyValueFrom(const Field& other) {
    checkSameType(other);
    setInt(static_cast<const SFEnum&>(other).mValue);
}

void SFEnum::setInt(int value) {
    if (mNames != nullptr && mNames->name(value) == nullptr) {
        throw DataError("SFEnum " + fullName() + ": " + std::to_string(value) +
                        " is not a value of this enum (expected one of " + mNames->list() + ")");
    }
    mValue = value;
    valueChanged();
}

} // namespace texsplat::sg
