#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/Progress.h"
#include "nodes/volume/RawHeader.h"

#include <cstdint>
#include <string>

namespace texsplat::volume {

/// @brief Reads a texsplat-raw file (RawHeader, docs/data.md) into a dense grid: a ScalarGrid
/// for `components 1`, a VectorGrid for `components 3`. Values of every type become float as
/// they are (uint8 255 reads as 255.0); NaN or infinite values become empty voxels and are
/// reported in one warning through texsplat::log.
///
/// `progress` is called with the message "reading" as the data is read (about every 4 MiB) and
/// may cancel.
/// @throws IoError when the file cannot be opened or read; ParseError for a malformed header;
/// DataError for a zero-size grid, when the data after the header is shorter or longer than the
/// header says, or when every voxel is NaN or infinite; LoadCancelled when `progress` answered
/// false.
AnyGrid readRawVolume(const std::string& path, const ProgressCallback& progress = {});

/// @brief Reads a raw file without a texsplat-raw header, laid out as `layout` says (dims, type,
/// components, byte order, spacing and origin; as a scene describes it with VolumeData's
/// FILE_RAW_HEADERLESS fields), after skipping `headerBytes` bytes of some other header. Values
/// are stored x fastest and decoded as readRawVolume() does.
/// @throws IoError when the file cannot be opened or read; DataError when the file's size is not
/// exactly `headerBytes` plus the data `layout` describes ("f.raw: file size mismatch: the scene
/// describes 4 x 4 x 4 voxels x 1 component x 4 bytes (float32) = 256 bytes, plus 0 header
/// bytes = 256 bytes, but the file has 300 bytes"), when `headerBytes` is negative, or when
/// every voxel is NaN or infinite; LoadCancelled when `progress` answered false.
AnyGrid readHeaderlessRawVolume(const std::string& path, const RawHeader& layout,
                                std::int64_t headerBytes, const ProgressCallback& progress = {});

/// @brief Writes `grid` as a texsplat-raw file of float32, little endian, 1 component; empty
/// voxels are written as the background. The file appears complete or not at all (written to a
/// temporary file, then renamed).
/// @throws IoError when the file cannot be written.
void writeRawVolume(const std::string& path, const ScalarGrid& grid);

/// @brief Writes `grid` as a texsplat-raw file of float32, little endian, 3 components;
/// otherwise as the scalar overload.
void writeRawVolume(const std::string& path, const VectorGrid& grid);

} // namespace texsplat::volume
