#pragma once

#include "scenegraph/Group.h"
#include "scenegraph/NodeType.h"

#include <deque>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace texsplat::sg {

/// @brief A node of a type this program does not know, read from its `fields [ … ]`
/// self-description and written back the same way (Coin's SoUnknownNode).
///
/// Inventor files may hold nodes of other programs' extension types; such a node declares its
/// fields in the file (`MyNode { fields [ SFFloat width, MFVec3f points ] width 2 }`). The
/// reader turns it into an UnknownNode whose type name is the file's (`MyNode`) and whose
/// fields are the described ones, so WriteAction writes it back identically and other code can
/// inspect it generically (`findField("width")->valueText()`). Like Coin's, it may also have
/// children, which actions traverse as a Group's.
///
/// Its run-time type is its own NodeType (named as in the file, derived from
/// UnknownNode::classType(), which derives from Group), so `SearchAction::setType(
/// UnknownNode::classType())` finds all of them.
///
/// File format: `AnyName { fields [ <type> <name>, … ] <field values> <children> }`.
class UnknownNode final : public Group {
public:
    /// @brief Shared ownership.
    using Ptr = std::shared_ptr<UnknownNode>;

    /// @brief A node of the unknown type `typeName`, without fields yet.
    static Ptr create(std::string typeName);

    /// @brief The common type of all unknown nodes ("UnknownNode", derived from Group).
    static const NodeType& classType();

    /// @brief This node's own type, named as in the file.
    const NodeType& type() const override { return *mType; }

    /// @brief True for the field types a description may use: every SF and MF type of
    /// scenegraph/fields (and SFEnum, SFNode, MFNode).
    static bool isDescribableFieldType(std::string_view fieldType);

    /// @brief Adds a field of type `fieldType` named `name`, holding that type's zero value.
    /// Throws DataError for a type isDescribableFieldType() rejects or a name already used.
    Field& addDescribedField(std::string_view fieldType, std::string name);

    /// @brief Sets an SFEnum field of this node to the value named `valueName`. The names of
    /// an unknown enum are not declared anywhere, so each field keeps the one it was given.
    void setEnumValue(SFEnum& field, std::string valueName);

private:
    struct Key {};

public:
    /// @brief Use create().
    UnknownNode(Key key, std::string typeName);

private:
    using AddField = Field& (UnknownNode::*)(std::string name);
    static AddField adderFor(std::string_view fieldType);
    template <class F> Field& addOwnedField(std::string name);

    std::unique_ptr<NodeType> mType;
    // Declared before the fields so that it outlives them: SFEnum fields point into it.
    std::map<const Field*, std::unique_ptr<EnumNames>> mEnumNames;
    // The fields' names, read from the file (not interned: see addFieldNamedBy()); a deque keeps
    // them in place. Declared before the fields, which point to them.
    std::deque<std::string> mFieldNames;
    std::vector<std::unique_ptr<Field>> mOwnedFields;
};

} // namespace texsplat::sg
