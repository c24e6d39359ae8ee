#pragma once

#include <string>

namespace texsplat {

/// @brief Throws IoError "<path>: cannot read <what>: it is a FIFO, not a regular file" (or a
/// folder, character device, block device, socket) when `path` names something that is not a
/// regular file (symbolic links are followed).
///
/// Every reader of a file named by a user asks this before opening it: opening a FIFO blocks
/// until someone writes to it, and reading `/dev/zero` or `/dev/urandom` never ends. A path
/// that does not exist passes, so that opening it reports the system's reason.
void requireRegularFile(const std::string& path, const std::string& what);

} // namespace texsplat
