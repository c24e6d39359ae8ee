#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/RawHeader.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace texsplat::volume {

/// @brief An array of voxel values in a program's memory, described as NumPy's array interface
/// describes one: where its first value is, its value type, its shape and its strides.
struct ArrayLayout {
    const void* data = nullptr;        ///< the first value
    std::string descr;                 ///< NumPy's `dtype.str`: "<f4", "|u1", ">i2"
    std::vector<std::int64_t> shape;   ///< axis lengths, slowest first: (z, y, x) or (z, y, x, 3)
    std::vector<std::int64_t> strides; ///< bytes from one value to the next along each axis
};

/// @brief The value type and byte order of an array's `descr`: parseNpyDescr(), which the
/// `.npy` reader uses, so an array and a `.npy` file of it are refused alike.
/// @throws DataError "<source>: data type '<c8' is not supported; expected <f4, <f8, |u1, |i1,
/// <u2, <i2, <u4 or <i4 (or > for big endian)".
RawHeader arrayValueType(const std::string& descr, const std::string& source);

/// @brief The grid of a program's array of shape (z, y, x) (scalars) or (z, y, x, 3) (vectors),
/// NumPy's order, so the last spatial axis becomes x, the fastest, as in a `.npy` file: the way a
/// Python program renders its array (docs/python.md).
///
/// An array of native-endian float32 values laid out one after the other (C order) is read where
/// it lies, without a copy (volume::ExternalGrid, holding `owner`, which must keep the values
/// alive); any other array (another value type, Fortran order, a strided view) is converted once
/// into a dense float grid, its values decoded as the file readers decode them. `origin` and
/// `spacing` place the voxels (GridGeometry). NaN or infinite values are empty voxels: one
/// warning counts them, as the readers log it. `source` names the array in messages.
/// @throws DataError (messages as the `.npy` reader's, after `source`) for a value type
/// arrayValueType() refuses, a shape of other than 3 axes or 4 with 3 components ("array of
/// shape (4, 5) is not supported; expected (z, y, x) or (z, y, x, 3)"), an empty array ("array
/// of shape (0, 4, 4): ..."), a bad origin or spacing, or
/// values that are all NaN or infinite; ResourceError when the conversion would need more than
/// the memory limit.
AnyGrid gridFromArray(const ArrayLayout& array, const std::string& source,
                      std::shared_ptr<const void> owner = nullptr,
                      const glm::dvec3& origin = glm::dvec3(0.0),
                      const glm::dvec3& spacing = glm::dvec3(1.0));

} // namespace texsplat::volume
