#pragma once

/// @file
/// @brief Per value type: C++ type, Inventor type names, default, format and parse of one value.
/// The single place that knows the ASCII syntax of each field type (SField/MField use it).

#include "scenegraph/Rotation.h"
#include "scenegraph/fields/FieldValueReader.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace texsplat::sg::detail {

/// @brief The bytes a string holds on the heap: its capacity, or none when it is short enough to
/// live inside the string object (the small-string buffer).
inline std::size_t stringHeapBytes(const std::string& value) {
    return value.capacity() > std::string().capacity() ? value.capacity() + 1 : 0;
}

struct BoolTraits {
    using Value = bool;
    static constexpr std::string_view kSingleName = "SFBool";
    static constexpr std::string_view kMultiName = "MFBool";
    static Value defaultValue() { return false; }
    static std::string format(Value value);
    static Value read(FieldValueReader& reader);
};

struct Int32Traits {
    using Value = std::int32_t;
    static constexpr std::string_view kSingleName = "SFInt32";
    static constexpr std::string_view kMultiName = "MFInt32";
    static Value defaultValue() { return 0; }
    static std::string format(Value value);
    static Value read(FieldValueReader& reader);
};

struct FloatTraits {
    using Value = float;
    static constexpr std::string_view kSingleName = "SFFloat";
    static constexpr std::string_view kMultiName = "MFFloat";
    static Value defaultValue() { return 0.0f; }
    static std::string format(Value value);
    static Value read(FieldValueReader& reader);
};

struct StringTraits {
    using Value = std::string;
    static constexpr std::string_view kSingleName = "SFString";
    static constexpr std::string_view kMultiName = "MFString";
    static Value defaultValue() { return {}; }
    static std::string format(const Value& value);
    static Value read(FieldValueReader& reader);
};

struct Vec2fTraits {
    using Value = glm::vec2;
    static constexpr std::string_view kSingleName = "SFVec2f";
    static constexpr std::string_view kMultiName = "MFVec2f";
    static Value defaultValue() { return Value(0.0f); }
    static std::string format(const Value& value);
    static Value read(FieldValueReader& reader);
};

struct Vec3fTraits {
    using Value = glm::vec3;
    static constexpr std::string_view kSingleName = "SFVec3f";
    static constexpr std::string_view kMultiName = "MFVec3f";
    static Value defaultValue() { return Value(0.0f); }
    static std::string format(const Value& value);
    static Value read(FieldValueReader& reader);
};

/// Same value type as Vec3fTraits; a distinct type name so that SFColor and SFVec3f do not
/// connect to each other and are written under their own names.
struct ColorTraits : Vec3fTraits {
    static constexpr std::string_view kSingleName = "SFColor";
    static constexpr std::string_view kMultiName = "MFColor";
};

struct RotationTraits {
    using Value = Rotation;
    static constexpr std::string_view kSingleName = "SFRotation";
    static constexpr std::string_view kMultiName = "MFRotation";
    static Value defaultValue() { return {}; }
    static std::string format(const Value& value);
    static Value read(FieldValueReader& reader);
};

struct MatrixTraits {
    using Value = glm::mat4;
    static constexpr std::string_view kSingleName = "SFMatrix";
    static constexpr std::string_view kMultiName = "MFMatrix";
    static Value defaultValue() { return Value(1.0f); }
    static std::string format(const Value& value);
    static Value read(FieldValueReader& reader);
};

} // namespace texsplat::sg::detail
