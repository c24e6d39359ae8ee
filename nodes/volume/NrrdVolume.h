#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/Progress.h"
#include "scenegraph/io/DataRoots.h"

#include <string>

namespace texsplat::volume {

/// @brief Reads a NRRD volume (NrrdHeader, docs/data.md): a `.nrrd` file with its data attached,
/// or a detached `.nhdr` header and the `data file` it names (relative to the header's folder).
/// A 1- to 3-D array gives a ScalarGrid, a 4-D array of sizes 3 X Y Z a VectorGrid; the first
/// spatial axis of `sizes` is the fastest, our x, unless `space directions` put the axes in
/// another order or sign: then each sample goes where the header puts it (NrrdHeader::gridAxis,
/// NrrdHeader::reversed). Spacing and origin come from `spacings` or from `space directions`
/// and `space origin`, else 1 and 0.
/// `line skip` lines, then `byte skip` bytes (counted after decompression for gzip) are
/// skipped before the data. Values decode as readRawVolume()'s; NaN or infinite ones become
/// empty voxels.
/// @throws IoError when a file cannot be opened or read; ParseError when the header is not NRRD;
/// DataError for a header of data this reader does not read, when the data are shorter or longer
/// than the header says (or the gzip data is damaged), when the grid does not fit in memory or
/// every voxel is NaN or infinite; LoadCancelled when `progress` answered false. With `roots`,
/// a detached data file is read only inside them (sg::DataRoots::check()); the header itself is
/// the caller's to check.
AnyGrid readNrrdVolume(const std::string& path, const ProgressCallback& progress = {},
                       const sg::DataRoots* roots = nullptr);

} // namespace texsplat::volume
