#include "scenegraph/fields/SFEnum.h"

#include "scenegraph/Error.h"
#include "scenegraph/fields/FieldValueReader.h"
#include "scenegraph/fields/FieldValueWriter.h"

#include <string>

namespace texsplat::sg {

void SFEnum::readValue(FieldValueReader& reader) {
    const std::string name = reader.readName();
    if (mNames == nullptr) {
        reader.fail("SFEnum " + fullName() + " has no value names, cannot read '" + name + "'");
    }
    const std::optional<int> value = mNames->value(name);
    if (!value) {
        reader.fail("unknown value '" + name + "' for SFEnum " + fullName() +
                    " (expected one of " + mNames->list() + ")");
    }
    setInt(*value);
}

void SFEnum::writeValue(FieldValueWriter& writer) const {
    const std::string* name = mNames != nullptr ? mNames->name(mValue) : nullptr;
    writer.writeToken(name != nullptr ? *name : std::to_string(mValue));
}

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
