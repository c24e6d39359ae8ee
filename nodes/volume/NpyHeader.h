#pragma once

#include "nodes/volume/RawHeader.h"

#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace texsplat::volume {

/// @brief The value type and byte order that NumPy's `descr` (an array's `dtype.str`: "<f4",
/// "|u1", ">i2") names, as `.npy` files and in-memory arrays (ArrayGrid.h) share them: sets
/// `layout.type` and `layout.endian`. `source` names the array in messages.
/// @throws DataError "<source>: data type '<c8' is not supported; expected <f4, <f8, |u1, |i1,
/// <u2, <i2, <u4 or <i4 (or > for big endian)".
void parseNpyDescr(const std::string& descr, const std::string& source, RawHeader& layout);

/// @brief A shape as Python writes it: "(64, 64, 32)", "(5,)".
std::string npyShapeText(const std::vector<std::int64_t>& shape);

/// @brief The header of a NumPy `.npy` file (format versions 1.0, 2.0 and 3.0, as numpy.save()
/// writes them; <https://numpy.org/doc/stable/reference/generated/numpy.lib.format.html>).
///
/// A file is the magic bytes `\x93NUMPY`, the format version (two bytes), the header's length
/// (2 bytes little endian for version 1, 4 for versions 2 and 3), the header, and the array's
/// values. The header is a Python dict literal with exactly the keys `descr`, `fortran_order`
/// and `shape`, e.g. `{'descr': '<f4', 'fortran_order': False, 'shape': (64, 64, 32), }`.
///
/// Supported: `descr` `<f4 <f8 |u1 |i1 <u2 <i2 <u4 <i4` and their big-endian (`>`) variants;
/// C order and Fortran order; shapes (x), (y, x) and (z, y, x) for scalars and (z, y, x, 3) for
/// vectors, so that the last axis of a C-order array becomes our x (the fastest).
struct NpyHeader {
    /// @brief Major format version (1, 2 or 3).
    int majorVersion = 1;
    /// @brief `descr` as written ("<f4").
    std::string descr;
    /// @brief Whether the values are stored with the first axis fastest.
    bool fortranOrder = false;
    /// @brief `shape` as written.
    std::vector<std::int64_t> shape;
    /// @brief The grid the array holds: dims (x, y, z), type, components (1, or 3 for a 4-axis
    /// shape), byte order; spacing 1 and origin 0, which `.npy` files do not record.
    RawHeader layout;
    /// @brief Bytes from the start of the file to the first value.
    std::int64_t dataOffset = 0;

    /// @brief Reads the header from `in` (standing at the start of the file) up to the first
    /// value. `source` names the file in messages.
    /// @throws ParseError "<source>: ..." when the bytes are not an `.npy` header (never quoting
    /// binary bytes), DataError "<source>: ..." for a well-formed header of an array this reader
    /// does not support (another dtype, a shape of 0 or more than 4 axes, ...).
    static NpyHeader parse(std::istream& in, const std::string& source);

    /// @brief The shape as Python writes it: "(64, 64, 32)".
    std::string shapeText() const { return npyShapeText(shape); }
};

} // namespace texsplat::volume
