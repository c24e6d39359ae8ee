#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/Progress.h"

#include <string>

namespace texsplat::volume {

/// @brief Reads a NumPy `.npy` file (NpyHeader, docs/data.md) into a dense grid: an array of
/// shape (z, y, x) (or (y, x), (x)) gives a ScalarGrid, (z, y, x, 3) a VectorGrid, its last axis
/// becoming our x, the fastest, in C order and in Fortran order alike. Spacing is 1 and voxel
/// (0,0,0) lies at the origin (`.npy` files record neither; place the grid with a Transform).
/// Values decode as readRawVolume()'s; NaN or infinite ones become empty voxels.
/// @throws IoError when the file cannot be opened or read; ParseError when it is not an `.npy`
/// file; DataError for an unsupported dtype or shape, when the data is shorter or longer than
/// the header says, or when every voxel is NaN or infinite; LoadCancelled when `progress`
/// answered false.
AnyGrid readNpyVolume(const std::string& path, const ProgressCallback& progress = {});

} // namespace texsplat::volume
