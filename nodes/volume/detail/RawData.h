#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/Progress.h"
#include "nodes/volume/RawHeader.h"

#include <istream>
#include <string>

namespace texsplat::volume::detail {

/// @brief The order in which a file stores the values of a grid.
enum class RawOrder {
    XFastest, ///< x fastest, then y, then z; vector components interleaved per voxel (our order)
    ZFastest, ///< z fastest, then y, then x, then the component (NumPy's Fortran order of a
              ///< (z, y, x[, 3]) array)
};

/// @brief Reads the values of the grid `layout` describes (dims, type, components, byte order,
/// spacing, origin) from `in`, which stands on the first value, into a dense grid; the one decoder
/// of texsplat-raw, headerless raw and NumPy files. The caller has checked that exactly
/// `layout.dataBytes()` bytes follow (each with a message of its own format). `path` names the
/// file in messages and progress.
/// @throws IoError when reading fails; DataError when the grid does not fit in memory (checked
/// against the machine's memory before allocating) or every voxel is NaN or infinite;
/// LoadCancelled when `progress` answered false.
AnyGrid readRawData(std::istream& in, const std::string& path, const RawHeader& layout,
                    RawOrder order, const ProgressCallback& progress);

} // namespace texsplat::volume::detail
