#pragma once

#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>
#include <utility>

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
    std::uint64_t bigEndian(int bytes, std::string_view what);
    std::uint64_t littleEndian(int bytes, std::string_view what);

    /// @brief `bytes` bytes as they are (a bit mask), refused when the file ends before them.
    std::string bytes(std::uint64_t count, std::string_view what);

    /// @brief Skips `bytes`, refused when the file ends before them.
    void skip(std::uint64_t bytes, std::string_view what);

    /// @brief Moves to byte `offset`; false (and stays) when it is beyond the end of the file,
    /// a truncation that the library reports in its own words.
    bool seek(std::uint64_t offset);

    /// @brief `items` of at least `each` bytes, refused when they cannot fit in the rest of the
    /// file (checked before multiplying, so that the product cannot wrap); answers the bytes.
    std::uint64_t sized(std::uint64_t items, std::uint64_t each, std::string_view what) const;

    /// @brief Where the walk is: the byte it reads next.
    std::uint64_t offset() const { return std::uint64_t(mOffset); }
    /// @brief Bytes from offset() to the end of the file.
    std::uint64_t left() const { return std::uint64_t(mEnd - mOffset); }

    /// @brief What the walk is in ("grid 'density'"), said before `what` in each message until
    /// the next call; empty for none.
    void setContext(std::string context) { mContext = std::move(context); }

    /// @throws IoError "path: <damage>: <context>: <what>".
    [[noreturn]] void corrupt(std::string_view what) const;

private:
    void need(std::uint64_t bytes, std::string_view what) const;
    std::uint64_t read(int bytes, bool bigEndian, std::string_view what);

    std::string mPath;
    std::string mDamage;
    std::string mContext;
    std::ifstream mIn;
    std::int64_t mEnd;
    std::int64_t mOffset = 0;
};

} // namespace texsplat::volume::detail
