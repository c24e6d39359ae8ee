#pragma once

// Sample values for every field type, chosen by the field's type name alone, so a test can set
// every field of every registered type to something other than its default without knowing the
// types: `sampleSceneText(type)` is a scene file that does it. Used by the round-trip and Coin
// interop tests.

#include "scenegraph/Engine.h"
#include "scenegraph/EngineOutputBase.h"
#include "scenegraph/EnumNames.h"
#include "scenegraph/FieldContainer.h"
#include "scenegraph/NodeType.h"
#include "scenegraph/fields/Field.h"
#include "scenegraph/fields/MFNode.h"
#include "scenegraph/fields/SFEnum.h"
#include "scenegraph/fields/SFNode.h"

#include <array>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>

namespace texsplat::sg::test {

/// Two values per single-valued type, as the writer formats them (so they can be compared with
/// `Field::valueText()`); a field gets the first unless that is its current value.
inline const std::map<std::string, std::array<std::string, 2>, std::less<>>& sampleValues() {
    static const std::map<std::string, std::array<std::string, 2>, std::less<>> kValues = {
        {"SFBool", {"TRUE", "FALSE"}},
        {"SFInt32", {"3", "4"}},
        {"SFFloat", {"0.25", "0.5"}},
        {"SFString", {"\"x y\"", "\"z\""}},
        {"SFVec2f", {"1 2", "3 4"}},
        {"SFVec3f", {"1 2 3", "4 5 6"}},
        {"SFColor", {"0.25 0.5 0.75", "1 0 0"}},
        {"SFRotation", {"0 1 0 0.5", "1 0 0 0.25"}},
        {"SFMatrix", {"2 0 0 0 0 2 0 0 0 0 2 0 1 2 3 1", "1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1"}},
    };
    return kValues;
}

/// Scene-file text of a value for `field` that differs from its current value: the sample of
/// its type above, a list of both samples for a multi-valued type (MFFloat `[ 0.25, 0.5 ]`), the
/// last name of an enum (its first if the last is current), a Group for an empty node field,
/// and nothing for a trigger (its name alone fires it). Throws std::logic_error for a type
/// without samples, so a new field type cannot slip past the tests that use this.
inline std::string sampleValueText(const Field& field) {
    const std::string type(field.typeName());
    const std::string current = field.valueText();
    if (type == "SFTrigger") {
        return "";
    }
    if (const auto* enumField = dynamic_cast<const SFEnum*>(&field)) {
        if (enumField->enumNames() == nullptr) {
            throw std::logic_error("SFEnum " + field.fullName() + " has no value names");
        }
        const std::string names = enumField->enumNames()->list(); // "A, B, C"
        const std::string first = names.substr(0, names.find(','));
        const std::string last = names.substr(names.rfind(' ') + 1);
        return last != current ? last : first;
    }
    if (const auto* nodeField = dynamic_cast<const SFNode*>(&field)) {
        return nodeField->value() ? "NULL" : "Group { }";
    }
    if (const auto* nodesField = dynamic_cast<const MFNode*>(&field)) {
        return nodesField->size() != 0 ? "[ ]" : "[ Group { }, Separator { } ]";
    }
    const bool isMulti = type.compare(0, 2, "MF") == 0;
    const auto found = sampleValues().find("SF" + type.substr(2));
    if (found == sampleValues().end()) {
        throw std::logic_error("no sample value for field type " + type + " (" +
                               field.fullName() + ")");
    }
    const auto& [a, b] = found->second;
    if (isMulti) {
        const std::string list = "[ " + a + ", " + b + " ]";
        return list != current ? list : "[ " + b + ", " + a + " ]";
    }
    return a != current ? a : b;
}

/// Fields ("Type.field") that their type keeps default on purpose, so no value written for them
/// survives a round trip: ElapsedTime's timeIn, the clock's reading. They get no sample.
inline const std::set<std::string>& fieldsKeptDefault() {
    static const std::set<std::string> kFields = {"ElapsedTime.timeIn"};
    return kFields;
}

/// `Type { field value ... }` with every field of `container` at its sample value (but those
/// in fieldsKeptDefault()).
inline std::string sampleContainerText(const FieldContainer& container) {
    std::string text = container.typeName() + " {\n";
    for (const Field* field : container.fields()) {
        if (fieldsKeptDefault().count(container.typeName() + "." + field->name()) == 0) {
            text += "    " + field->name() + " " + sampleValueText(*field) + "\n";
        }
    }
    return text + "}";
}

/// A scene file with one instance of `type` (not abstract) whose fields hold their sample
/// values. An engine is written where it can be: as the source of a connection, here into a
/// field of a `Holder` node (an unregistered type that describes itself) from its first output.
inline std::string sampleSceneText(const NodeType& type) {
    const std::shared_ptr<FieldContainer> instance = type.create();
    const std::string body = sampleContainerText(*instance);
    std::string text = "#Inventor V2.1 ascii\n\n";
    if (instance->asNode() != nullptr) {
        return text + body + "\n";
    }
    const auto& engine = static_cast<const Engine&>(*instance);
    if (engine.outputs().empty()) {
        throw std::logic_error("engine " + type.name() + " has no output to write it through");
    }
    const EngineOutputBase& output = *engine.outputs().front();
    return text + "Holder {\n    fields [ " + std::string(output.typeName()) + " input ]\n" +
           "    input = " + body + " . " + output.name() + "\n}\n";
}

} // namespace texsplat::sg::test
