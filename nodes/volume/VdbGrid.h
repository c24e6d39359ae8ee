#pragma once

// OpenVDB grids an application holds in memory, as texsplat grids: the one public header that
// includes OpenVDB (the others keep it out), for code that has OpenVDB grids anyway. Link
// OpenVDB::openvdb yourself, as such code does.
#ifndef TEXSPLAT_WITH_OPENVDB
#error "nodes/volume/VdbGrid.h needs texsplat built with OpenVDB (TEXSPLAT_WITH_OPENVDB=ON)"
#endif

#include "nodes/volume/Grid.h"

#include <openvdb/openvdb.h>

namespace texsplat::volume {

/// @brief `grid` as a texsplat grid, for VolumeData::setGrid(): its active voxels (tiles
/// expanded) copied into a SparseGrid as readVdbGrid() copies a grid it read from a file, with
/// the same rules (axis-aligned transforms only; index (0,0,0) at the low corner of the active
/// voxels; NaN or infinite values become empty voxels, with one warning).
/// @throws DataError as readVdbGrid() for a grid it cannot take, or when the copy would not fit
/// in memory.
ScalarGridPtr gridFromVdb(const openvdb::FloatGrid& grid);

/// @brief `grid` as a texsplat vector grid; see the float overload.
VectorGridPtr gridFromVdb(const openvdb::Vec3SGrid& grid);

} // namespace texsplat::volume
