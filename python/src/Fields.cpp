#include "Bindings.h"

#include "scenegraph/Error.h"
#include "scenegraph/fields/Fields.h"
#include "scenegraph/fields/MFNode.h"
#include "scenegraph/fields/SFEnum.h"
#include "scenegraph/fields/SFNode.h"
#include "scenegraph/fields/SFTrigger.h"

#include <nanobind/stl/shared_ptr.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace texsplat::python {
namespace {

// One value of a field type as Python holds it: bool, int, float, str, a tuple of floats for
// vectors and colours, (x, y, z, angle) for a rotation, rows of four for a matrix.
nb::object toPython(bool value) { return nb::bool_(value); }
nb::object toPython(std::int32_t value) { return nb::int_(value); }
nb::object toPython(float value) { return nb::float_(value); }
nb::object toPython(const std::string& value) { return nb::str(value.c_str(), value.size()); }
nb::object toPython(const glm::vec2& value) { return nb::make_tuple(value.x, value.y); }
nb::object toPython(const glm::vec3& value) { return nb::make_tuple(value.x, value.y, value.z); }
nb::object toPython(const sg::Rotation& value) {
    return nb::make_tuple(value.axis().x, value.axis().y, value.axis().z, value.angle());
}
nb::object toPython(const glm::mat4& value) {
    nb::list rows;
    for (int row = 0; row < 4; ++row) {
        rows.append(nb::make_tuple(value[row][0], value[row][1], value[row][2], value[row][3]));
    }
    return nb::tuple(rows);
}

// The numbers of a sequence of `count` numbers, or a TypeError naming the field.
std::vector<float> numbers(nb::handle value, std::size_t count, const sg::Field& field) {
    const auto fail = [&] {
        return nb::type_error((field.fullName() + ": expected " + std::to_string(count) +
                               " numbers, got " + nb::repr(value).c_str())
                                  .c_str());
    };
    if (!nb::isinstance<nb::sequence>(value) || nb::isinstance<nb::str>(value) ||
        nb::len(value) != count) {
        throw fail();
    }
    std::vector<float> result;
    for (nb::handle item : value) {
        if (!nb::isinstance<nb::float_>(item) && !nb::isinstance<nb::int_>(item) &&
            !PyNumber_Check(item.ptr())) {
            throw fail();
        }
        result.push_back(nb::cast<float>(item));
    }
    return result;
}

template <class Value> Value fromPython(nb::handle value, const sg::Field& field);

template <> bool fromPython<bool>(nb::handle value, const sg::Field& field) {
    if (!nb::isinstance<nb::bool_>(value) && !nb::isinstance<nb::int_>(value)) {
        throw nb::type_error((field.fullName() + ": expected True or False, got " +
                              nb::repr(value).c_str())
                                 .c_str());
    }
    return nb::cast<bool>(value);
}
template <> std::int32_t fromPython<std::int32_t>(nb::handle value, const sg::Field& field) {
    if (!nb::isinstance<nb::int_>(value) || nb::isinstance<nb::bool_>(value)) {
        throw nb::type_error((field.fullName() + ": expected a whole number, got " +
                              nb::repr(value).c_str())
                                 .c_str());
    }
    const long long number = nb::cast<long long>(value);
    if (number < INT32_MIN || number > INT32_MAX) {
        throw DataError(field.fullName() + ": " + std::to_string(number) +
                        " does not fit in a 32-bit integer");
    }
    return static_cast<std::int32_t>(number);
}
template <> float fromPython<float>(nb::handle value, const sg::Field& field) {
    if (nb::isinstance<nb::str>(value) || !PyNumber_Check(value.ptr())) {
        throw nb::type_error((field.fullName() + ": expected a number, got " +
                              nb::repr(value).c_str())
                                 .c_str());
    }
    return nb::cast<float>(nb::float_(value));
}
template <> std::string fromPython<std::string>(nb::handle value, const sg::Field& field) {
    if (!nb::isinstance<nb::str>(value)) {
        throw nb::type_error((field.fullName() + ": expected a string, got " +
                              nb::repr(value).c_str())
                                 .c_str());
    }
    return nb::cast<std::string>(value);
}
template <> glm::vec2 fromPython<glm::vec2>(nb::handle value, const sg::Field& field) {
    const std::vector<float> v = numbers(value, 2, field);
    return {v[0], v[1]};
}
template <> glm::vec3 fromPython<glm::vec3>(nb::handle value, const sg::Field& field) {
    const std::vector<float> v = numbers(value, 3, field);
    return {v[0], v[1], v[2]};
}
template <> sg::Rotation fromPython<sg::Rotation>(nb::handle value, const sg::Field& field) {
    const std::vector<float> v = numbers(value, 4, field);
    return {{v[0], v[1], v[2]}, v[3]};
}
template <> glm::mat4 fromPython<glm::mat4>(nb::handle value, const sg::Field& field) {
    glm::mat4 matrix(1.0f);
    if (!nb::isinstance<nb::sequence>(value) || nb::len(value) != 4) {
        throw nb::type_error((field.fullName() + ": expected 4 rows of 4 numbers, got " +
                              nb::repr(value).c_str())
                                 .c_str());
    }
    int row = 0;
    for (nb::handle item : value) {
        const std::vector<float> v = numbers(item, 4, field);
        matrix[row++] = glm::vec4(v[0], v[1], v[2], v[3]);
    }
    return matrix;
}

// A multiple-value field takes any iterable of values, or one value alone (as a file may write
// it without brackets).
template <class Traits>
std::vector<typename Traits::Value> manyFromPython(nb::handle value, const sg::Field& field) {
    using Value = typename Traits::Value;
    std::vector<Value> values;
    const bool isOne = nb::isinstance<nb::str>(value) ||
                       !PyObject_HasAttrString(value.ptr(), "__iter__");
    if (isOne) {
        values.push_back(fromPython<Value>(value, field));
        return values;
    }
    // A NumPy array of numbers iterates as NumPy scalars, which the number checks accept.
    for (nb::handle item : nb::iter(value)) {
        values.push_back(fromPython<Value>(item, field));
    }
    return values;
}

template <class Traits> bool getTyped(const sg::Field& field, nb::object& out) {
    if (const auto* single = dynamic_cast<const sg::SField<Traits>*>(&field)) {
        out = toPython(single->value());
        return true;
    }
    if (const auto* many = dynamic_cast<const sg::MField<Traits>*>(&field)) {
        nb::list list;
        for (const auto& value : many->values()) {
            list.append(toPython(value));
        }
        out = list;
        return true;
    }
    return false;
}

template <class Traits> bool setTyped(sg::Field& field, nb::handle value) {
    if (auto* single = dynamic_cast<sg::SField<Traits>*>(&field)) {
        single->setValue(fromPython<typename Traits::Value>(value, field));
        return true;
    }
    if (auto* many = dynamic_cast<sg::MField<Traits>*>(&field)) {
        many->setValue(manyFromPython<Traits>(value, field));
        return true;
    }
    return false;
}

template <class... Traits> bool getAny(const sg::Field& field, nb::object& out) {
    return (getTyped<Traits>(field, out) || ...);
}

template <class... Traits> bool setAny(sg::Field& field, nb::handle value) {
    return (setTyped<Traits>(field, value) || ...);
}

// Every value field type: SFBool ... MFMatrix (scenegraph/fields/Fields.h).
#define TEXSPLAT_VALUE_TRAITS                                                                    \
    sg::detail::BoolTraits, sg::detail::Int32Traits, sg::detail::FloatTraits,                   \
        sg::detail::StringTraits, sg::detail::Vec2fTraits, sg::detail::Vec3fTraits,              \
        sg::detail::ColorTraits, sg::detail::RotationTraits, sg::detail::MatrixTraits

sg::Node::Ptr nodeFromPython(nb::handle value, const sg::Field& field) {
    if (value.is_none()) {
        return nullptr;
    }
    if (!nb::isinstance<sg::Node>(value)) {
        throw nb::type_error((field.fullName() + ": expected a Node or None, got " +
                              nb::repr(value).c_str())
                                 .c_str());
    }
    return nb::cast<sg::Node::Ptr>(value);
}

} // namespace

nb::object fieldValue(const sg::Field& field) {
    nb::object out;
    if (getAny<TEXSPLAT_VALUE_TRAITS>(field, out)) {
        return out;
    }
    if (const auto* enumerated = dynamic_cast<const sg::SFEnum*>(&field)) {
        return nb::str(enumerated->valueName().c_str());
    }
    if (const auto* node = dynamic_cast<const sg::SFNode*>(&field)) {
        return nb::cast(node->value());
    }
    if (const auto* nodes = dynamic_cast<const sg::MFNode*>(&field)) {
        return nb::cast(nodes->values());
    }
    if (dynamic_cast<const sg::SFTrigger*>(&field) != nullptr) {
        return nb::none();
    }
    return nb::str(field.valueText().c_str());
}

void setFieldValue(sg::Field& field, nb::handle value) {
    if (setAny<TEXSPLAT_VALUE_TRAITS>(field, value)) {
        return;
    }
    if (auto* enumerated = dynamic_cast<sg::SFEnum*>(&field)) {
        if (!nb::isinstance<nb::str>(value)) {
            throw nb::type_error((field.fullName() + ": expected a value name (a string), got " +
                                  nb::repr(value).c_str())
                                     .c_str());
        }
        enumerated->setValueName(nb::cast<std::string>(value));
        return;
    }
    if (auto* node = dynamic_cast<sg::SFNode*>(&field)) {
        node->setValue(nodeFromPython(value, field));
        return;
    }
    if (auto* nodes = dynamic_cast<sg::MFNode*>(&field)) {
        std::vector<sg::Node::Ptr> list;
        for (nb::handle item : nb::iter(value)) {
            list.push_back(nodeFromPython(item, field));
        }
        nodes->setValue(std::move(list));
        return;
    }
    if (auto* trigger = dynamic_cast<sg::SFTrigger*>(&field)) {
        trigger->setValue();
        return;
    }
    throw nb::type_error((field.fullName() + ": a field of type " + std::string(field.typeName()) +
                          " cannot be set from Python")
                             .c_str());
}

} // namespace texsplat::python
