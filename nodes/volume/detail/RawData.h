#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/Progress.h"
#include "nodes/volume/RawHeader.h"

#include <cstddef>
#include <istream>
#include <string>

namespace texsplat::volume::detail {

/// @brief The order in which a file stores the values of a grid.
enum class RawOrder {
    XFastest, ///< x fastest, then y, then z; vector components interleaved per voxel (our order)
    ZFastest, ///< z fastest, then y, then x, then the component (NumPy's Fortran order of a
              ///< (z, y, x[, 3]) array)
};

/// @brief Where the spatial axes of an XFastest file lie in the grid: file axis `a` (0 the
/// fastest) is grid axis `gridAxis[a]`, counted from its far end when `reversed[a]` (a NRRD's
/// permuted or negative space directions). The identity is the file order itself.
struct FileAxes {
    glm::ivec3 gridAxis{0, 1, 2};
    glm::bvec3 reversed{false};

    /// @brief Whether the file's order is the grid's.
    bool isIdentity() const { return gridAxis == glm::ivec3(0, 1, 2) && !glm::any(reversed); }
};

/// @brief Decodes `count` values of `type` from `bytes` (byte-swapped first when `swapBytes`) into
/// floats, as they are (uint8 255 becomes 255.0): the one conversion of stored values, for files
/// and in-memory arrays alike.
void decodeValues(RawValueType type, const unsigned char* bytes, std::size_t count,
                  bool swapBytes, float* out);

/// @brief Reads the values of the grid `layout` describes (dims, type, components, byte order,
/// spacing, origin) from `in`, which stands on the first value, into a dense grid; the one decoder
/// of texsplat-raw, headerless raw, NumPy and NRRD files. `layout.dims` are the grid's; `axes`
/// (XFastest only) says where the file's axes lie in it. The caller has checked that exactly
/// `layout.dataBytes()` bytes follow (each with a message of its own format). `path` names the
/// file in messages and progress.
/// @throws IoError when reading fails; DataError when the grid does not fit in memory (checked
/// against the machine's memory before allocating) or every voxel is NaN or infinite;
/// LoadCancelled when `progress` answered false.
AnyGrid readRawData(std::istream& in, const std::string& path, const RawHeader& layout,
                    RawOrder order, const ProgressCallback& progress,
                    const FileAxes& axes = {});

} // namespace texsplat::volume::detail
