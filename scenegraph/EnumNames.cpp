#include "scenegraph/EnumNames.h"

namespace texsplat::sg {

EnumNames::EnumNames(std::initializer_list<Entry> entries) : mEntries(entries) {}

std::optional<int> EnumNames::value(std::string_view name) const {
    for (const Entry& entry : mEntries) {
        if (entry.name == name) {
            return entry.value;
        }
    }
    return std::nullopt;
}

const std::string* EnumNames::name(int value) const {
    for (const Entry& entry : mEntries) {
        if (entry.value == value) {
            return &entry.name;
        }
    }
    return nullptr;
}

std::string EnumNames::list() const {
    std::string text;
    for (const Entry& entry : mEntries) {
        text += text.empty() ? entry.name : ", " + entry.name;
    }
    return text;
}

} // namespace texsplat::sg
