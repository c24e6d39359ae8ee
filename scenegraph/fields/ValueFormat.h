#pragma once

/// @file
/// @brief Inventor ASCII formatting of single values, shared by fields and the scene writer.

#include <string>
#include <string_view>

namespace texsplat::sg {

/// @brief Shortest text that reads back to exactly the same float (`1.6`, `1e+20`, `-0`);
/// non-finite values print as `inf`, `-inf`, `nan`.
std::string formatFloat(float value);

/// @brief formatFloat() for a double: the shortest text that reads back to the same double.
std::string formatDouble(double value);

/// @brief A double-quoted string; `"` and `\` are escaped with a backslash.
std::string formatString(std::string_view text);

} // namespace texsplat::sg
