#include "scenegraph/fields/SFTrigger.h"

namespace texsplat::sg {

void SFTrigger::readValue(FieldValueReader& /*reader*/) { setValue(); }

void SFTrigger::writeValue(FieldValueWriter& /*writer*/) const {}

void SFTrigger::copyValueFrom(const Field& other) {
    checkSameType(other);
    setValue();
}

} // namespace texsplat::sg
