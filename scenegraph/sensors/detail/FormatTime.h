#pragma once

#include <string>

namespace texsplat::sg::detail {

/// @brief Shortest text that reads back to the same double (`0.1`, `-1`, `inf`, `nan`): times
/// and intervals in the sensors' error messages.
std::string formatTime(double seconds);

} // namespace texsplat::sg::detail
