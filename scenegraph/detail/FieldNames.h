#pragma once

#include <string>
#include <string_view>

namespace texsplat::sg::detail {

/// @brief The one string of every field named `name`: fields point to it rather than each
/// holding a copy (32 bytes a field, and an allocation for a name of more than 15 characters).
/// Names are kept for the life of the process, so only names that a class declares are
/// interned, never names read from a file. Thread-safe.
const std::string& internFieldName(std::string_view name);

/// @brief The empty name of a field or container that has none, which keeps no string of its
/// own.
const std::string& noName();

} // namespace texsplat::sg::detail
