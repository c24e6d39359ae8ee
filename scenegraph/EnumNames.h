#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace texsplat::sg {

/// @brief The scene-file names of an enumeration's values, declared once next to the enum:
/// @code
/// enum class Operator { Modulate, Blend };
/// const sg::EnumNames kOperatorNames{{"MODULATE", Operator::Modulate},
///                                    {"BLEND", Operator::Blend}};
/// @endcode
class EnumNames {
public:
    /// @brief One name and its value.
    struct Entry {
        /// @brief A name for an enumerator of any enum (or int) type.
        template <class E>
        Entry(std::string entryName, E entryValue)
            : name(std::move(entryName)), value(static_cast<int>(entryValue)) {}
        std::string name; ///< as written in files, e.g. "MODULATE"
        int value;        ///< the enumerator as int
    };

    /// @brief The names in the order they are listed in messages.
    EnumNames(std::initializer_list<Entry> entries);

    /// @brief The value named `name`, if any.
    std::optional<int> value(std::string_view name) const;

    /// @brief The name of `value`, or nullptr.
    const std::string* name(int value) const;

    /// @brief "MODULATE, BLEND": for messages.
    std::string list() const;

private:
    std::vector<Entry> mEntries;
};

} // namespace texsplat::sg
