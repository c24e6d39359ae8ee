#pragma once

#include <string>

namespace texsplat::kernel::detail {

/// @brief Writes contents (bytes as they are) to path + ".tmp" and renames it onto path, so a
/// reader never sees a half-written file. Throws IoError naming path when either step fails.
void writeFileAtomically(const std::string& path, const std::string& contents);

} // namespace texsplat::kernel::detail
