#pragma once

#include "nodes/volume/GridGeometry.h"
#include "nodes/volume/GridStatistics.h"

#include <cstdint>
#include <fstream>
#include <string>

namespace texsplat::volume::detail {

/// @brief Opens `path` for binary reading.
/// @throws IoError "path: cannot open file (reason)" when it is missing, unreadable or a folder;
/// "path: cannot read file: it is a FIFO, not a regular file" (or a device, a socket) before
/// opening it, which for a FIFO would block.
std::ifstream openForReading(const std::string& path);

/// @brief The size of the file `path` in bytes.
/// @throws IoError "path: cannot read file size (reason)".
std::int64_t fileSize(const std::string& path);

/// @brief Checks a loader's estimate before it allocates: throws ResourceError "<what> would need
/// <bytes text>, more than the memory limit of <bytes text>; use …" when `bytes` exceeds
/// texsplat::memoryLimit() (`--memory-limit`; the physical memory unless set), so a small file
/// that declares a huge grid fails at once, saying what it would cost, instead of swapping or
/// dying of std::bad_alloc.
void checkFitsInMemory(const std::string& what, std::uint64_t bytes);

/// @brief checkFitsInMemory() for the dense grid of `geometry` with `components` floats a voxel,
/// before a loader allocates it: "<source>: a grid of 4 x 3 x 2 voxels x 1 float would need ...".
void checkGridFitsInMemory(const std::string& source, const GridGeometry& geometry,
                           int components);

/// @brief The most bytes deflate (gzip, zlib, NetCDF-4's compression) expands one byte into: its
/// longest match, 258 bytes, coded in two bits.
inline constexpr std::uint64_t kMaxDeflateRatio = 1032;

/// @brief The most bytes `compressedBytes` of deflate data can hold (kMaxDeflateRatio times, and
/// one longest match more for rounding), saturating.
std::uint64_t maxDeflatedBytes(std::uint64_t compressedBytes);

/// @brief The one check a loader makes of the voxels it read. Logs one warning for empty (NaN or
/// infinite) voxels, naming the source and the count ("f.raw: 3 voxels are NaN or infinite;
/// treated as empty"); nothing when there are none.
/// @throws DataError "<source>: all N voxels are NaN or infinite; nothing to draw" when no voxel
/// is finite: such a grid would render as an empty image that hides the bad input.
void checkFiniteVoxels(const std::string& source, const GridStatistics& statistics);

} // namespace texsplat::volume::detail
