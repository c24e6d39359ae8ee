#pragma once

#include <string_view>

namespace texsplat::sg::detail {

/// @brief True when `typeName` is a node or engine type built into Open Inventor 2.1 / Coin
/// (Separator, Material, ElapsedTime, ...). Other Inventor readers know those types, so the
/// writer describes the fields of every other type (`fields [ … ]`) to let them pass it through.
bool isInventorType(std::string_view typeName);

} // namespace texsplat::sg::detail
