#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/type_precision.hpp>

#include <cstdint>
#include <istream>
#include <string>

namespace texsplat::volume {

/// @brief Binary type of the values in a texsplat-raw file (and of headerless raw and NumPy data,
/// which share the decoding).
enum class RawValueType { Float32, Float64, UInt8, UInt16, Int8, Int16, UInt32, Int32 };

/// @brief Byte order of the values in a texsplat-raw file.
enum class RawEndian { Little, Big };

/// @brief The text header of a texsplat-raw file (format spec: docs/data.md).
///
/// A file is a few lines of ASCII text followed by the voxel values, x fastest:
/// @code
/// texsplat-raw 1
/// dims 64 64 32
/// type float32
/// components 1
/// spacing 1 1 2
/// origin 0 0 0
/// endian little
/// data
/// @endcode
/// `dims` and `type` are required; `components` (1 or 3) defaults to 1, `spacing` to 1 1 1,
/// `origin` to 0 0 0, `endian` to little. Lines starting with `#` are comments. The values start
/// on the byte after the newline of the `data` line.
struct RawHeader {
    /// @brief Voxels along x, y and z.
    glm::i64vec3 dims{1, 1, 1};
    /// @brief Binary value type.
    RawValueType type = RawValueType::Float32;
    /// @brief 1 for a scalar field, 3 for a vector field (x, y, z interleaved per voxel).
    int components = 1;
    /// @brief World distance between voxel centers.
    glm::dvec3 spacing{1.0, 1.0, 1.0};
    /// @brief World position of the center of voxel (0,0,0).
    glm::dvec3 origin{0.0, 0.0, 0.0};
    /// @brief Byte order of multi-byte values.
    RawEndian endian = RawEndian::Little;

    /// @brief Reads a header from `in` up to and including the `data` line. `source` is the file
    /// name used in messages.
    /// @throws ParseError "file:line:col: ..." when the text does not follow the grammar, and
    /// DataError "file:line:col: ..." for a zero-size grid or an unusable spacing or origin.
    static RawHeader parse(std::istream& in, const std::string& source);

    /// @brief The header text, ending with the `data` line, that parse() reads back unchanged.
    std::string format() const;

    /// @brief Bytes of one value of `type`.
    int bytesPerValue() const;
    /// @brief Bytes of voxel data that must follow the header.
    /// @throws DataError when that number does not fit in 64 bits.
    std::int64_t dataBytes() const;
};

/// @brief The header keyword of a value type ("float32").
const char* toString(RawValueType type);

/// @brief Bytes of one value of `type`.
int bytesPerValue(RawValueType type);

} // namespace texsplat::volume
