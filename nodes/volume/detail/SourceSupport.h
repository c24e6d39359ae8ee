#pragma once

#include "nodes/volume/GridStatistics.h"

#include <fstream>
#include <string>

namespace texsplat::volume::detail {

/// @brief Opens `path` for binary reading.
/// @throws IoError "path: cannot open file (reason)" when it is missing, unreadable or a folder.
std::ifstream openForReading(const std::string& path);

/// @brief The one check a loader makes of the voxels it read. Logs one warning for empty (NaN or
/// infinite) voxels, naming the source and the count ("f.raw: 3 voxels are NaN or infinite;
/// treated as empty"); nothing when there are none.
/// @throws DataError "<source>: all N voxels are NaN or infinite; nothing to draw" when no voxel
/// is finite: such a grid would render as an empty image that hides the bad input.
void checkFiniteVoxels(const std::string& source, const GridStatistics& statistics);

} // namespace texsplat::volume::detail
