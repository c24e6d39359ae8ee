#pragma once

#include <cstdint>
#include <string>

namespace texsplat::volume::detail {

/// @brief Checks the sizes that the header of a NetCDF classic, 64-bit offset or CDF-5 file
/// declares (the counts of dimensions, attributes and variables, the lengths of names and of
/// attribute values) against the bytes the file has, before libnetcdf allocates for them: it
/// allocates what a name's length says (a 40-byte file made it ask for 3.8 GB). A file of another
/// format (NetCDF-4 is HDF5) is left to libnetcdf.
/// @throws IoError "path: truncated or corrupt NetCDF file: a name at byte 16 needs
/// 3806520052 bytes, but the file ends at byte 40".
void checkNetCdfHeaderSizes(const std::string& path);

} // namespace texsplat::volume::detail
