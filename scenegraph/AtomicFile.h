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
/// existing `path` stays as it was. Where the folder's file system can make a file without a
/// name (Linux' O_TMPFILE: ext4, XFS, Btrfs, tmpfs), the temporary file has none until it is
/// complete, so that a process killed while writing (Ctrl-C, SIGKILL, the OOM killer) leaves
/// nothing behind either; elsewhere it is a hidden sibling (".NAME.tmpPID-N"). Failures throw IoError("path: what"); errors `write` throws
/// itself (texsplat::Error) pass through unchanged. A `path` that is a symbolic link is written
/// through: the file it points to gets the contents (and its name is in messages), the link
/// stays a link.
void writeFileAtomically(const std::string& path,
                         const std::function<void(std::ofstream& stream)>& write);

/// @brief Throws IoError("out/x.png: cannot write the image: folder 'out' does not exist") unless
/// writeFileAtomically() could make `path`: its folder (the folder of the file a symbolic link
/// points to) exists, is a folder and is writable, and `path` is not itself a folder; `what`
/// names the file in the message ("the image"). Commands ask it for every output before any
/// work, so that a typo in a folder name does not cost a whole render or benchmark.
void requireWritableFile(const std::string& path, const std::string& what);

/// @brief Writes `contents` (bytes as they are) to `path` all at once, as above.
void writeFileAtomically(const std::string& path, const std::string& contents);

} // namespace texsplat
