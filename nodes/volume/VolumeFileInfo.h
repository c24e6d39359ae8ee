#pragma once

#include <string>

namespace texsplat::volume {

/// @brief The data file formats texsplat reads whole (a headerless raw file needs the scene to
/// describe it, so it is not one of them).
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

/// @brief What a user needs to write a scene for the data file `path` (`texsplat info FILE`):
/// the format and, for each grid (each grid of an OpenVDB file, the first time step of each 3-D or
/// 4-D variable of a NetCDF file, the one grid of the others), its kind (scalar or vector),
/// dimensions, voxel size, bounding box, active voxels, value range (of the magnitude for
/// vectors), a histogram of `histogramBins` bins drawn as text bars, and a VolumeData snippet
/// that reads it. Reads every grid it describes.
/// @throws what the format's reader throws (IoError, ParseError, DataError), and IoError when
/// `path` is not in a format detectVolumeFileFormat() knows.
std::string describeVolumeFile(const std::string& path, int histogramBins = 10);

} // namespace texsplat::volume
