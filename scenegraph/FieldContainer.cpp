#include "scenegraph/FieldContainer.h"

#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"
#include "scenegraph/fields/Field.h"

#include <cctype>

namespace texsplat::sg {

namespace {

// Inventor's name rule (Coin's SbName::isBaseNameChar / isIdentStartChar).
bool isNameChar(char c) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte <= 0x20 || byte == 0x7f) {
        return false;
    }
    for (char bad : std::string_view("\"'+.\\{}")) {
        if (c == bad) {
            return false;
        }
    }
    return true;
}

} // namespace

FieldContainer::~FieldContainer() = default;

const NodeType& FieldContainer::classType() {
    static const NodeType type("FieldContainer", nullptr, nullptr);
    return type;
}

Field* FieldContainer::findField(std::string_view name) const {
    for (Field* field : mFields) {
        if (field->name() == name) {
            return field;
        }
    }
    return nullptr;
}

void FieldContainer::setName(std::string name) {
    bool isValid = name.empty() || std::isdigit(static_cast<unsigned char>(name.front())) == 0;
    for (char c : name) {
        isValid = isValid && isNameChar(c);
    }
    if (!isValid) {
        throw DataError(describe() + ": invalid name '" + name +
                        "' (a name must not start with a digit and must not contain "
                        "whitespace, control characters or any of \"'+.\\{})");
    }
    mName = std::move(name);
}

std::string FieldContainer::describe() const {
    return mName.empty() ? typeName() : typeName() + "(" + mName + ")";
}

void FieldContainer::notify(const Field* source) { notifyObservers(source); }

void FieldContainer::attachField(Field& field, std::string name) {
    TEXSPLAT_ASSERT(field.mContainer == nullptr, "FieldContainer::addField(): field added twice");
    TEXSPLAT_ASSERT(this->findField(name) == nullptr, "FieldContainer::addField(): duplicate name");
    field.mContainer = this;
    field.mName = std::move(name);
    field.mIsDefault = true;
    mFields.push_back(&field);
    field.attached();
}

} // namespace texsplat::sg
