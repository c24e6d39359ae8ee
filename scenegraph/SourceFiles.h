#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace texsplat::sg {

/// @brief A file name as nodes keep it: an index into the process's table of the scene files
/// it has read, so that a node records where it was read in a few bytes (Node::sourceLocation()).
/// 0 means no file.
using SourceFileId = std::uint32_t;

/// @brief The id of `fileName`, the same for every call with the same name. Thread-safe; the
/// table only grows (by one entry per distinct file read).
SourceFileId internSourceFile(std::string_view fileName);

/// @brief The name whose id is `file`; empty for 0.
std::string sourceFileName(SourceFileId file);

} // namespace texsplat::sg
