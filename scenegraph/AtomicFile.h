#pragma once

#include <fstream>
#include <functional>
#include <string>

namespace texsplat {

/// @brief Writes `path` all at once: `write` streams the contents into a new temporary file in
/// the same directory, which is then renamed over `path`.
///
/// A reader never sees a half-written file, and a failed write (an exception from `write`, a
/// full disk, an unwritable directory) leaves neither `path` nor the temporary file behind; an
/// existing `path` stays as it was. Failures throw IoError("path: what"); errors `write` throws
/// itself (texsplat::Error) pass through unchanged. A `path` that is a symbolic link is written
/// through: the file it points to gets the contents (and its name is in messages), the link
/// stays a link.
void writeFileAtomically(const std::string& path,
                         const std::function<void(std::ofstream& stream)>& write);

/// @brief Writes `contents` (bytes as they are) to `path` all at once, as above.
void writeFileAtomically(const std::string& path, const std::string& contents);

} // namespace texsplat
