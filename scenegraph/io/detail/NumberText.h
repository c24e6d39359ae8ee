#pragma once

#include <cstdint>
#include <string_view>

namespace texsplat::sg::detail {

/// @brief How a word parses as a number.
enum class ParsedNumber { Valid, Malformed, OutOfRange };

/// @brief Parses Inventor's number syntax into `value`: [sign] digits [. digits] [e [sign]
/// digits] with at least one mantissa digit (`1`, `-.5`, `2.`, `1e-3`), and `inf` and `nan` with
/// an optional sign, which formatFloat() writes for non-finite values. The same in every C and
/// C++ locale. A value beyond the largest float is OutOfRange; one too small for a float reads as
/// a denormal or a zero of its sign.
ParsedNumber parseFloat(std::string_view text, float& value);

/// @brief Parses a decimal or `0x` hexadecimal integer with an optional sign into `value`.
ParsedNumber parseInt32(std::string_view text, std::int32_t& value);

} // namespace texsplat::sg::detail
