#pragma once

#include <cstdint>
#include <fstream>
#include <string>

namespace texsplat::volume::detail {

/// @brief Walks the header of a file whose format declares the sizes of what follows (names,
/// attribute values, metadata), checking each against the bytes the file has before a
/// third-party reader (libnetcdf, OpenVDB) allocates what a damaged size says: a string of 4 GB
/// cannot be in a file of 40 bytes. The format's own walk (NetCdfHeader, VdbHeader) says what
/// each field is.
class DeclaredSizes {
public:
    /// @brief Opens `path` (openForReading()); `damage` starts each message ("truncated or
    /// corrupt NetCDF file").
    DeclaredSizes(const std::string& path, std::string damage);

    /// @brief Whether the file starts with `magic`; reads past it.
    bool startsWith(const std::string& magic);

    /// @brief An unsigned integer of `bytes` bytes (1 to 8), big- or little-endian.
    std::uint64_t bigEndian(int bytes, const std::string& what);
    std::uint64_t littleEndian(int bytes, const std::string& what);

    /// @brief Skips `bytes`, refused when the file ends before them.
    void skip(std::uint64_t bytes, const std::string& what);

    /// @brief Moves to byte `offset`; false (and stays) when it is beyond the end of the file,
    /// a truncation that the library reports in its own words.
    bool seek(std::uint64_t offset);

    /// @brief `items` of at least `each` bytes, refused when they cannot fit in the rest of the
    /// file (checked before multiplying, so that the product cannot wrap); answers the bytes.
    std::uint64_t sized(std::uint64_t items, std::uint64_t each, const std::string& what) const;

    /// @throws IoError "path: <damage>: <what>".
    [[noreturn]] void corrupt(const std::string& what) const;

private:
    void need(std::uint64_t bytes, const std::string& what) const;
    std::uint64_t read(int bytes, bool bigEndian, const std::string& what);

    std::string mPath;
    std::string mDamage;
    std::ifstream mIn;
    std::int64_t mEnd;
    std::int64_t mOffset = 0;
};

} // namespace texsplat::volume::detail
