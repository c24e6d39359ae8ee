#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/Progress.h"

#include <cstdint>
#include <string>
#include <vector>

namespace texsplat::volume {

/// @brief One dimension of a NetCDF variable.
struct NetCdfDimension {
    /// @brief The dimension's name ("lat").
    std::string name;
    /// @brief Its length.
    std::int64_t length = 0;
};

/// @brief One variable of a NetCDF file, as listNetCdfVariables() describes it.
struct NetCdfVariableInfo {
    /// @brief The variable's name ("temperature").
    std::string name;
    /// @brief Its type as CDL writes it ("float", "short", "ubyte", "char", ...).
    std::string type;
    /// @brief Its dimensions as declared: slowest first (C order), so the last one is our x.
    std::vector<NetCdfDimension> dimensions;
    /// @brief Whether it is a coordinate variable: one dimension, named like it ("lat(lat)").
    bool isCoordinate = false;

    /// @brief Whether readNetCdfVariable() reads it: a number type, 3 dimensions (z, y, x) or
    /// 4 (time, z, y, x), and not a coordinate variable.
    bool isVolume() const;
    /// @brief As CDL declares it: "float temperature(time=2, level=4, lat=3, lon=5)".
    std::string declaration() const;
};

/// @brief Whether this build reads NetCDF files (CMake option TEXSPLAT_WITH_NETCDF).
bool isNetCdfAvailable();

/// @brief The variables of a NetCDF file (classic, 64-bit offset, CDF-5 or NetCDF-4), in the
/// file's order.
/// @throws IoError when the file cannot be opened or read, or texsplat was built without
/// NetCDF; ParseError when it is not a NetCDF file.
std::vector<NetCdfVariableInfo> listNetCdfVariables(const std::string& path);

/// @brief Reads the NetCDF variable `variable` into a dense ScalarGrid (the only variable that
/// isVolume() when `variable` is empty). A variable of dimensions (z, y, x), C order, slowest
/// first, gives voxel (x, y, z) = v[z][y][x]; one of (time, z, y, x) gives time step `timeStep`
/// of its first dimension.
///
/// Values become `raw * scale_factor + add_offset` (when the attributes are there), as doubles,
/// then floats. Raw values equal to `_FillValue` (else the type's default fill value, except for
/// bytes) or to one of `missing_value` become NaN: empty, transparent voxels, counted in the
/// loader's warning. Spacing and origin come from the coordinate variables (a 1-D variable named
/// like the dimension) when they are evenly spaced and increasing; otherwise that axis is
/// indexed 0, 1, 2, ... (with a warning through texsplat::log). `progress` is called with
/// "reading variable '<name>'" after each z slice; it may cancel.
/// @throws IoError when the file cannot be opened or read (or NetCDF is not built in);
/// ParseError when it is not a NetCDF file; DataError when no variable has that name or `variable`
/// is empty and not exactly one variable is a volume (the messages list the variables), for a
/// variable of another number of dimensions or a type that is not a number, a `timeStep`
/// outside the time dimension (or not 0 for a 3-D variable), a grid too large for memory, or a
/// variable with no finite value; LoadCancelled when `progress` answered false.
AnyGrid readNetCdfVariable(const std::string& path, const std::string& variable,
                           std::int64_t timeStep = 0, const ProgressCallback& progress = {});

} // namespace texsplat::volume
