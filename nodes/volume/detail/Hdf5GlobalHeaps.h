#pragma once

#include <string>

namespace texsplat::volume::detail {

/// @brief Refuses an HDF5 file (a NetCDF-4 file) with a global heap collection that HDF5 1.10
/// would read forever: a free-space object (index 0) of 0 bytes, which its parser
/// (H5HG__cache_heap_deserialize) steps over by its size, so it never moves on. A 7 KB file did
/// that to `texsplat info` (found by fuzz_netcdf_reader). The collections, signature "GCOL", are
/// found by a scan of the whole file and walked object by object as HDF5 walks them. A file that
/// is not HDF5 is left alone.
/// @throws IoError "path: truncated or corrupt NetCDF file: the HDF5 global heap at byte 2048
/// has a free-space object of 0 bytes at byte 2160, which HDF5 1.10 reads forever".
void checkHdf5GlobalHeaps(const std::string& path);

} // namespace texsplat::volume::detail
