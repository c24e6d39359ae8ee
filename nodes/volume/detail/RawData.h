#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/IndexBox.h"
#include "nodes/volume/Progress.h"
#include "nodes/volume/RawHeader.h"
#include "scenegraph/io/DataRoots.h"

#include <cstddef>
#include <cstdint>
#include <functional>
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

/// @brief A file's raw values, checked and ready to decode: `in` stands on the first value and
/// holds exactly the values `layout` describes, stored in `order` (and `axes`).
struct RawDataView {
    std::istream& in;
    const std::string& path;
    const RawHeader& layout;
    RawOrder order;
    FileAxes axes;
};

/// @brief What is done with a file's raw values once they are checked: read into a grid
/// (readRawData()) or streamed (readRawValues(), `texsplat info`).
using RawDataDecoder = std::function<void(const RawDataView& data)>;

/// @brief Receives decoded values chunk by chunk in the file's order: `first` is the number of
/// values before `values[0]`; `count` is a whole number of voxels (of `components` values).
using RawValueChunk =
    std::function<void(std::int64_t first, const float* values, std::int64_t count)>;

/// @brief Decodes the values of `data` chunk by chunk (4 MiB of the file each) into `chunk`,
/// without holding the grid; `progress` hears "reading" after each chunk.
/// @throws IoError when reading fails; LoadCancelled when `progress` answered false.
void readRawValues(const RawDataView& data, const ProgressCallback& progress,
                   const RawValueChunk& chunk);

/// @brief Opens the texsplat-raw file `path`, checks its header and data size as
/// readRawVolume() does, and hands the data to `use`.
void withRawVolumeData(const std::string& path, const RawDataDecoder& use);

/// @brief The same for a headerless raw file laid out as `layout` after `headerBytes` bytes
/// (readHeaderlessRawVolume()).
void withHeaderlessRawData(const std::string& path, const RawHeader& layout,
                           std::int64_t headerBytes, const RawDataDecoder& use);

/// @brief The same for a NumPy .npy file (readNpyVolume()).
void withNpyData(const std::string& path, const RawDataDecoder& use);

/// @brief The same for a NRRD file (readNrrdVolume()): its attached data, or the detached data
/// file its header names; gzip data is decompressed as `use` reads it, and checked to end
/// where the header says after it returns. With `roots`, a detached data file must lie inside
/// them.
void withNrrdData(const std::string& path, const RawDataDecoder& use,
                  const sg::DataRoots* roots = nullptr);

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

/// @brief readRawData() of the voxels of `region` only (a box inside the grid, not empty: a
/// brick of a render split over processes), placed where they lie in the grid: a stream that can
/// seek is read only where the region's rows lie, one that cannot (gzip) is read through,
/// keeping the region's values. The voxels are not checked for finite values (the whole grid is,
/// by the render that split it).
/// @throws IoError when reading fails; DataError for a region outside the grid or one that does
/// not fit in memory; LoadCancelled when `progress` answered false.
AnyGrid readRawRegion(const RawDataView& data, const IndexBox& region,
                      const ProgressCallback& progress);

/// @brief readRawRegion() of the data that `with` (withNpyData() and the like, bound to a file)
/// hands its decoder.
AnyGrid readRawGridRegion(const std::function<void(const RawDataDecoder&)>& with,
                          const IndexBox& region, const ProgressCallback& progress);

/// @brief The geometry of the grid whose data `with` hands its decoder, from the header, without
/// reading a value.
GridGeometry rawGridGeometry(const std::function<void(const RawDataDecoder&)>& with);

/// @brief The grid readRawData() makes of the data that `with` (withNpyData() and the like, bound
/// to a file) hands its decoder.
AnyGrid readRawGrid(const std::function<void(const RawDataDecoder&)>& with,
                    const ProgressCallback& progress);

} // namespace texsplat::volume::detail
