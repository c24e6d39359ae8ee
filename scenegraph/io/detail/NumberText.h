#pragma once

#include <cstdint>
#include <string_view>

namespace texsplat::sg::detail {

/// @brief True for Inventor's number syntax: [sign] digits [. digits] [e [sign] digits] with
/// at least one mantissa digit (`1`, `-.5`, `2.`, `1e-3`), and for `inf` and `nan` with an
/// optional sign, which formatFloat() writes for non-finite values.
bool isFloatText(std::string_view text);

/// @brief How a word parses as a 32-bit integer.
enum class IntegerText { Valid, Malformed, OutOfRange };

/// @brief Parses a decimal or `0x` hexadecimal integer with an optional sign into `value`.
IntegerText parseInt32(std::string_view text, std::int32_t& value);

} // namespace texsplat::sg::detail
