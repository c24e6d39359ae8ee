#pragma once

#include "nodes/volume/RawHeader.h"
#include "scenegraph/io/DataRoots.h"

#include <cstdint>
#include <optional>
#include <string>

namespace texsplat::volume {

/// @brief The data file formats texsplat reads whole (a headerless raw file needs its layout
/// said, HeaderlessRawLayout, so it is not one of them).
enum class VolumeFileFormat {
    Unknown,     ///< none of these (a scene file, say)
    TexsplatRaw, ///< texsplat-raw (RawHeader)
    Npy,         ///< NumPy .npy (NpyHeader)
    Nrrd,        ///< NRRD, attached (.nrrd) or detached (.nhdr) (NrrdHeader)
    NetCdf,      ///< NetCDF classic, 64-bit offset, CDF-5 or NetCDF-4 (NetCdfVolume.h)
    Vdb,         ///< OpenVDB
};

/// @brief Which data format `path` holds, by its first bytes (`texsplat-raw`, `\x93NUMPY`,
/// `NRRD`, `CDF`, OpenVDB's magic number), else by its extension (.raw, .npy, .nrrd, .nhdr, .nc,
/// .nc4, .vdb); Unknown when neither says. Never throws: a file that cannot be read is Unknown.
VolumeFileFormat detectVolumeFileFormat(const std::string& path);

/// @brief How a headerless raw file is laid out (its dims, type, components and byte order;
/// spacing and origin are 1 and 0), which the file cannot say itself: VolumeData's
/// FILE_RAW_HEADERLESS fields, or `texsplat info ct.raw --dims 256,256,180 --type uint8`.
struct HeaderlessRawLayout {
    RawHeader layout;             ///< dims, type, components, endian
    std::int64_t headerBytes = 0; ///< bytes of some other header before the values
};

/// @brief What a user needs to write a scene for the data file `path` (`texsplat info FILE`):
/// the format and, for each grid (each grid of an OpenVDB file, the first time step of each 3-D or
/// 4-D variable of a NetCDF file, the one grid of the others), its kind (scalar or vector),
/// dimensions, voxel size, bounding box, active voxels, value range (of the magnitude for
/// vectors), a histogram of `histogramBins` bins drawn as text bars, and a VolumeData snippet
/// that reads it; for a NetCDF file, the vectors that three variables named like u, v and w make.
/// With `headerless`, `path` is read as a headerless raw file laid out so. With `roots`, a NRRD
/// header's detached data file must lie inside them (`path` itself is the caller's to check).
///
/// Raw, NumPy, NRRD and NetCDF values are streamed from the file in two passes (the range, then
/// the histogram), a few MiB at a time, so that the memory used does not grow with the grid (a
/// 1.7 GB raw file took 6.5 GB); an OpenVDB grid, and a NumPy array of vectors in Fortran order,
/// are read whole, as a scene would read them (checked against the memory limit first).
/// @throws what the format's reader throws (IoError, ParseError, DataError, ResourceError), and
/// IoError when `path` is not in a format detectVolumeFileFormat() knows.
std::string describeVolumeFile(const std::string& path, int histogramBins = 10,
                               const std::optional<HeaderlessRawLayout>& headerless = {},
                               const sg::DataRoots* roots = nullptr);

/// @brief A scene file (Inventor text) that draws the data file `path` as a first look: its
/// grid (the first one texsplat reads of a file of several) in a VolumeData node, a
/// TransferFunction over the data's 1st to 99th percentile (VIRIDIS, opacity rising with the
/// value, per voxel) and TextureSplat. `texsplat info FILE --scene` prints it; `texsplat render
/// FILE` draws it. Reads only the file's header (the grids' names), not its values.
/// @throws as describeVolumeFile().
std::string quickLookScene(const std::string& path,
                           const std::optional<HeaderlessRawLayout>& headerless = {});

} // namespace texsplat::volume
