#pragma once

#include "nodes/volume/RawHeader.h"

#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace texsplat::volume {

/// @brief How the values of a NRRD file are stored.
enum class NrrdEncoding {
    Raw,  ///< the bytes as they are
    Gzip, ///< the bytes compressed with gzip (zlib)
};

/// @brief The header of a NRRD file (teem's "nearly raw raster data",
/// <http://teem.sourceforge.net/nrrd/format.html>), attached (`.nrrd`: header, a blank line,
/// the data) or detached (`.nhdr`: the header alone, naming its `data file`).
///
/// A header is the magic line `NRRD0001` ... `NRRD0005`, then one `field: value` per line;
/// `key:=value` lines and `#` comments are skipped. Read are `dimension`, `type`, `sizes`,
/// `endian`, `encoding`, `spacings`, `space`, `space dimension`, `space directions`,
/// `space origin`, `byte skip`, `line skip` and `data file`; the descriptive fields
/// (`content`, `kinds`, `centers`, `labels`, `units`, `thicknesses`, `axis mins`, `axis maxs`,
/// `min`, `max`, `old min`, `old max`, `measurement frame`, `space units`, `sample units`,
/// `number`) are accepted and not used.
///
/// Supported: 1-, 2- and 3-D scalars and 4-D arrays whose first (fastest) axis holds 3 values
/// (vectors, interleaved per voxel); the types of RawValueType (int64, uint64 and `block` are
/// not); encodings raw and gzip; axis-aligned space directions (each along one world axis, in
/// any order and sign; oblique ones are refused).
struct NrrdHeader {
    /// @brief The grid the data holds: dims (x, y, z: `sizes` of the spatial axes, put where
    /// gridAxis says), type, components (3 for a 4-D array), byte order, spacing and origin (the
    /// center of grid voxel (0,0,0); from `spacings` or from `space directions` and
    /// `space origin`; 1 and 0 when the header has none).
    RawHeader layout;
    /// @brief `type` as written ("unsigned short").
    std::string typeName;
    /// @brief `sizes`, fastest axis first, as written.
    std::vector<std::int64_t> sizes;
    /// @brief For each spatial axis of the file (fastest first), the grid axis it lies along
    /// (0 x, 1 y, 2 z): `space directions` may permute them; in order otherwise.
    glm::ivec3 gridAxis{0, 1, 2};
    /// @brief For each spatial axis of the file, whether its direction is negative: the grid
    /// then counts it from the other end, keeping its spacing positive and every sample where
    /// the header puts it.
    glm::bvec3 reversed{false};
    /// @brief `encoding`.
    NrrdEncoding encoding = NrrdEncoding::Raw;
    /// @brief `data file` as written; empty when the data follows the header in the same file.
    std::string dataFile;
    /// @brief Lines to skip at the start of the data (before decompression).
    std::int64_t lineSkip = 0;
    /// @brief Bytes to skip after the skipped lines (after decompression for gzip); -1 (raw
    /// only): the data are the last bytes of the file.
    std::int64_t byteSkip = 0;
    /// @brief Bytes from the start of the header to the byte after the blank line that ends it
    /// (where attached data start).
    std::int64_t dataOffset = 0;

    /// @brief Reads the header from `in` (standing at the start of the file), through the blank
    /// line that ends it or to the end of a detached header. `source` names the file in messages.
    /// @throws ParseError "<source>:<line>:<column>: ..." (or "<source>: ..." for the magic line)
    /// when the text is not a NRRD header, never quoting binary bytes; DataError
    /// "<source>:<line>:<column>: ..." for a well-formed header of data this reader does not
    /// read (another type, encoding or dimension, oblique space directions, a zero-size grid,
    /// several data files).
    static NrrdHeader parse(std::istream& in, const std::string& source);

    /// @brief "raw" or "gzip".
    const char* encodingName() const;

    /// @brief `sizes` as written: "3 64 64 32".
    std::string sizesText() const;
};

} // namespace texsplat::volume
