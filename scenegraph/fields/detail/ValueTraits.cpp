#include "scenegraph/fields/detail/ValueTraits.h"

#include "scenegraph/fields/ValueFormat.h"

#include <glm/gtc/type_ptr.hpp>

namespace texsplat::sg::detail {

namespace {

std::string formatFloats(const float* values, int count) {
    std::string text;
    for (int i = 0; i < count; ++i) {
        if (i > 0) {
            text += ' ';
        }
        text += formatFloat(values[i]);
    }
    return text;
}

void readFloats(FieldValueReader& reader, float* values, int count) {
    for (int i = 0; i < count; ++i) {
        values[i] = reader.readFloat();
    }
}

} // namespace

std::string BoolTraits::format(Value value) { return value ? "TRUE" : "FALSE"; }

BoolTraits::Value BoolTraits::read(FieldValueReader& reader) {
    const std::string name = reader.readName();
    if (name == "FALSE" || name == "0") {
        return false;
    }
    if (name != "TRUE" && name != "1") {
        reader.fail("expected TRUE or FALSE, got '" + name + "'");
    }
    return true;
}

std::string Int32Traits::format(Value value) { return std::to_string(value); }

Int32Traits::Value Int32Traits::read(FieldValueReader& reader) { return reader.readInt32(); }

std::string FloatTraits::format(Value value) { return formatFloat(value); }

FloatTraits::Value FloatTraits::read(FieldValueReader& reader) { return reader.readFloat(); }

std::string StringTraits::format(const Value& value) { return formatString(value); }

StringTraits::Value StringTraits::read(FieldValueReader& reader) { return reader.readString(); }

std::string Vec2fTraits::format(const Value& value) {
    return formatFloats(glm::value_ptr(value), 2);
}

Vec2fTraits::Value Vec2fTraits::read(FieldValueReader& reader) {
    Value value;
    readFloats(reader, glm::value_ptr(value), 2);
    return value;
}

std::string Vec3fTraits::format(const Value& value) {
    return formatFloats(glm::value_ptr(value), 3);
}

Vec3fTraits::Value Vec3fTraits::read(FieldValueReader& reader) {
    Value value;
    readFloats(reader, glm::value_ptr(value), 3);
    return value;
}

std::string RotationTraits::format(const Value& value) {
    return formatFloats(glm::value_ptr(value.axis()), 3) + " " + formatFloat(value.angle());
}

RotationTraits::Value RotationTraits::read(FieldValueReader& reader) {
    glm::vec3 axis;
    readFloats(reader, glm::value_ptr(axis), 3);
    return Rotation(axis, reader.readFloat());
}

std::string MatrixTraits::format(const Value& value) {
    return formatFloats(glm::value_ptr(value), 16);
}

MatrixTraits::Value MatrixTraits::read(FieldValueReader& reader) {
    Value value;
    readFloats(reader, glm::value_ptr(value), 16);
    return value;
}

} // namespace texsplat::sg::detail
