#pragma once

#include <string>
#include <vector>

namespace texsplat::image::detail {

/// @brief The whole contents of a file. Throws IoError("path: cannot open: <reason>") when it
/// cannot be opened or read.
std::vector<char> readFileBytes(const std::string& path);

} // namespace texsplat::image::detail
