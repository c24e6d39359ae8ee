#include "scenegraph/io/UnknownNode.h"

#include "scenegraph/EnumNames.h"
#include "scenegraph/Error.h"
#include "scenegraph/fields/Fields.h"
#include "scenegraph/fields/MFNode.h"
#include "scenegraph/fields/SFEnum.h"
#include "scenegraph/fields/SFNode.h"

#include <utility>

namespace texsplat::sg {

namespace {

// The value a described field starts with: its type's zero value, as for a declared field.
template <class Traits> typename Traits::Value zeroValue(const SField<Traits>& /*field*/) {
    return Traits::defaultValue();
}
template <class Traits>
std::vector<typename Traits::Value> zeroValue(const MField<Traits>& /*field*/) {
    return {};
}
int zeroValue(const SFEnum& /*field*/) { return 0; }
std::shared_ptr<Node> zeroValue(const SFNode& /*field*/) { return nullptr; }
std::vector<std::shared_ptr<Node>> zeroValue(const MFNode& /*field*/) { return {}; }

} // namespace

const NodeType& UnknownNode::classType() {
    static const NodeType type("UnknownNode", &Group::classType(), nullptr);
    return type;
}

UnknownNode::UnknownNode(Key /*key*/, std::string typeName)
    : mType(std::make_unique<NodeType>(std::move(typeName), &classType(), nullptr)) {}

UnknownNode::Ptr UnknownNode::create(std::string typeName) {
    return std::make_shared<UnknownNode>(Key{}, std::move(typeName));
}

bool UnknownNode::isDescribableFieldType(std::string_view fieldType) {
    return adderFor(fieldType) != nullptr;
}

Field& UnknownNode::addDescribedField(std::string_view fieldType, std::string name) {
    const AddField add = adderFor(fieldType);
    if (add == nullptr) {
        throw DataError(describe() + ": unsupported field type '" + std::string(fieldType) +
                        "' for field '" + name + "'");
    }
    if (findField(name) != nullptr) {
        throw DataError(describe() + ": field '" + name + "' is described twice");
    }
    return (this->*add)(std::move(name));
}

void UnknownNode::setEnumValue(SFEnum& field, std::string valueName) {
    auto names = std::make_unique<EnumNames>(
        std::initializer_list<EnumNames::Entry>{{std::move(valueName), 0}});
    field.setEnumNames(*names);
    field.setValue(0);
    mEnumNames[&field] = std::move(names);
}

// MFBool, MFVec2f, MFRotation and MFMatrix have no alias in Fields.h but are Inventor types
// that other programs' nodes use, so they pass through too.
UnknownNode::AddField UnknownNode::adderFor(std::string_view fieldType) {
    static const std::pair<std::string_view, AddField> kAdders[] = {
        {"SFBool", &UnknownNode::addOwnedField<SFBool>},
        {"SFInt32", &UnknownNode::addOwnedField<SFInt32>},
        {"SFFloat", &UnknownNode::addOwnedField<SFFloat>},
        {"SFString", &UnknownNode::addOwnedField<SFString>},
        {"SFVec2f", &UnknownNode::addOwnedField<SFVec2f>},
        {"SFVec3f", &UnknownNode::addOwnedField<SFVec3f>},
        {"SFColor", &UnknownNode::addOwnedField<SFColor>},
        {"SFRotation", &UnknownNode::addOwnedField<SFRotation>},
        {"SFMatrix", &UnknownNode::addOwnedField<SFMatrix>},
        {"SFEnum", &UnknownNode::addOwnedField<SFEnum>},
        {"SFNode", &UnknownNode::addOwnedField<SFNode>},
        {"MFBool", &UnknownNode::addOwnedField<MField<detail::BoolTraits>>},
        {"MFInt32", &UnknownNode::addOwnedField<MFInt32>},
        {"MFFloat", &UnknownNode::addOwnedField<MFFloat>},
        {"MFString", &UnknownNode::addOwnedField<MFString>},
        {"MFVec2f", &UnknownNode::addOwnedField<MField<detail::Vec2fTraits>>},
        {"MFVec3f", &UnknownNode::addOwnedField<MFVec3f>},
        {"MFColor", &UnknownNode::addOwnedField<MFColor>},
        {"MFRotation", &UnknownNode::addOwnedField<MField<detail::RotationTraits>>},
        {"MFMatrix", &UnknownNode::addOwnedField<MField<detail::MatrixTraits>>},
        {"MFNode", &UnknownNode::addOwnedField<MFNode>},
    };
    for (const auto& [name, add] : kAdders) {
        if (name == fieldType) {
            return add;
        }
    }
    return nullptr;
}

template <class F> Field& UnknownNode::addOwnedField(std::string name) {
    auto owned = std::make_unique<F>();
    F& field = *owned;
    mOwnedFields.push_back(std::move(owned));
    addFieldNamedBy(field, mFieldNames.emplace_back(std::move(name)), zeroValue(field),
                    "A field of a type this program does not know, kept to be written back");
    return field;
}

} // namespace texsplat::sg
