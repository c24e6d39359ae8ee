#include "scenegraph/FieldContainer.h"

#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"
#include "scenegraph/detail/FieldDescriptions.h"
#include "scenegraph/detail/FieldNames.h"
#include "scenegraph/fields/Field.h"

#include <cctype>
#include <string>
#include <string_view>

namespace texsplat::sg {

namespace {

// Inventor's name rule (Coin's SbName::isBaseNameChar), made exactly what the scene reader reads
// back whole (SceneLexer::readName()): names also end at the list punctuation `[`, `]` and `,`,
// and '+' starts the `+N` suffix that the reader strips (a leading '#' starts a comment, and a
// leading digit is excluded by setName()).
constexpr std::string_view kForbiddenNameChars = "\"'+,.[\\]{}";

bool isNameChar(char c) {
    const auto byte = static_cast<unsigned char>(c);
    return byte > 0x20 && byte != 0x7f && kForbiddenNameChars.find(c) == std::string_view::npos;
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
    bool isValid = name.empty() || (std::isdigit(static_cast<unsigned char>(name.front())) == 0 &&
                                    name.front() != '#');
    for (char c : name) {
        isValid = isValid && isNameChar(c);
    }
    if (name == "_") {
        throw DataError(describe() + ": invalid name '_' (it is reserved: Inventor writers name "
                                     "a node that has no name '_+N')");
    }
    if (!isValid) {
        throw DataError(describe() + ": invalid name '" + name +
                        "' (a name must not start with a digit or '#' and must not contain "
                        "whitespace, control characters or any of " +
                        std::string(kForbiddenNameChars) + ")");
    }
    if (name.empty()) {
        mName.reset();
    } else {
        mName = std::make_unique<std::string>(std::move(name));
    }
}

const std::string& FieldContainer::name() const { return mName ? *mName : detail::noName(); }

std::string FieldContainer::describe() const {
    return mName ? typeName() + "(" + *mName + ")" : typeName();
}

void FieldContainer::notify(const Field* source) { notifyObservers(source); }

const std::string& FieldContainer::internedName(std::string_view name) {
    return detail::internFieldName(name);
}

void FieldContainer::attachField(Field& field, const std::string& name, const char* description) {
    TEXSPLAT_ASSERT(field.mContainer == nullptr, "FieldContainer::addField(): field added twice");
    TEXSPLAT_ASSERT(this->findField(name) == nullptr, "FieldContainer::addField(): duplicate name");
    detail::recordFieldDescription(*this, name, description);
    field.mContainer = this;
    field.mName = &name;
    field.mIsDefault = true;
    mFields.push_back(&field);
    field.attached();
}

} // namespace texsplat::sg
