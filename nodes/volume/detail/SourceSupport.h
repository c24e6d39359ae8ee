#pragma once

#include "nodes/volume/GridStatistics.h"

#include <fstream>
#include <string>

namespace texsplat::volume::detail {

/// @brief Opens `path` for binary reading.
/// @throws IoError "path: cannot open file (reason)" when it is missing, unreadable or a folder.
std::ifstream openForReading(const std::string& path);

/// @brief Logs the one warning a loader gives for empty (NaN or infinite) voxels, naming the
/// source and the count; nothing when there are none.
void warnAboutNonFiniteVoxels(const std::string& source, const GridStatistics& statistics);

} // namespace texsplat::volume::detail
