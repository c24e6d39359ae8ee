#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/GridGeometry.h"
#include "nodes/volume/IndexBox.h"
#include "nodes/volume/Progress.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace texsplat::volume {

/// @brief One dimension of a NetCDF variable.
struct NetCdfDimension {
    /// @brief The dimension's name ("lat").
    std::string name;
    /// @brief Its length.
    std::int64_t length = 0;

    /// @brief Same name and length.
    bool operator==(const NetCdfDimension& other) const {
        return name == other.name && length == other.length;
    }
    /// @brief Not operator==.
    bool operator!=(const NetCdfDimension& other) const { return !(*this == other); }
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

/// @brief A NetCDF file (classic, 64-bit offset, CDF-5 or NetCDF-4), opened once to list its
/// variables and read any of them: `texsplat info` describes every variable of a file through
/// one reader (opening the file once per variable cost time quadratic in their number: each open
/// reads every variable's description).
///
/// What to read is named as VolumeData's `gridName` names it: a variable ("t"); empty for the
/// file's only 3-D or 4-D variable; or, when no variable has the name, three names separated by
/// spaces ("u v w"), the x, y and z components of vectors, which must have the same dimensions.
/// A variable of dimensions (z, y, x), C order, slowest first, gives voxel (x, y, z) = v[z][y][x];
/// one of (time, z, y, x) gives time step `timeStep` of its first dimension.
///
/// Values become `raw * scale_factor + add_offset` (when the attributes are there), as doubles,
/// then floats. Raw values equal to `_FillValue` (else the type's default fill value, except for
/// bytes) or to one of `missing_value` become NaN: empty, transparent voxels, counted in the
/// loader's warning. Spacing and origin come from the coordinate variables (a 1-D variable named
/// like the dimension) when they are evenly spaced: increasing, or decreasing (pressure levels,
/// latitudes from north to south), in which case the axis runs from the other end, so that
/// voxel 0 lies at the smallest coordinate and the spacing stays positive. A coordinate that is
/// not evenly spaced indexes its axis 0, 1, 2, ... (with a warning through texsplat::log).
///
/// netCDF-C is not thread-safe: a reader holds the process's lock on it from its construction to
/// its end, so readers on several threads work one after the other; a thread must not make a
/// second reader while it holds one.
class NetCdfReader {
public:
    /// @brief Opens `path` and lists its variables.
    /// @throws IoError when the file cannot be opened or read (or NetCDF is not built in);
    /// ParseError when it is not a NetCDF file.
    explicit NetCdfReader(const std::string& path);
    ~NetCdfReader();
    NetCdfReader(const NetCdfReader&) = delete;
    NetCdfReader& operator=(const NetCdfReader&) = delete;

    /// @brief The file's variables, in the file's order.
    const std::vector<NetCdfVariableInfo>& variables() const;

    /// @brief Where the voxels of `names` lie and how many values a voxel has (1, or 3 for
    /// vectors), without reading them.
    /// @throws DataError as read() does before it reads a value.
    std::pair<GridGeometry, int> geometry(const std::string& names,
                                          std::int64_t timeStep = 0) const;

    /// @brief Reads `names` into a dense ScalarGrid, or a VectorGrid for three names.
    /// `progress` is called with "reading variable 't'" ("reading variables 'u', 'v', 'w'")
    /// after each z slice; it may cancel.
    /// @throws DataError when no variable has that name or `names` is empty and not exactly one
    /// variable is a volume (the messages list the variables), for a variable of another number
    /// of dimensions or a type that is not a number, vector components of different dimensions,
    /// a `timeStep` outside the time dimension (or not 0 for a 3-D variable), a NetCDF-4
    /// variable declared larger than its compressed data could hold (the rest would be fill
    /// values, never written), or a variable with no finite value; ResourceError for a grid or
    /// chunks too large for the memory limit; LoadCancelled when `progress` answered false.
    /// With `region` (a box of the grid's voxels, not empty), reads only its hyperslab, into a
    /// grid of the region placed where it lies (a brick of a render split over processes; its
    /// values are not checked for finite ones, and none need be).
    AnyGrid read(const std::string& names, std::int64_t timeStep = 0,
                 const ProgressCallback& progress = {},
                 const std::optional<IndexBox>& region = std::nullopt) const;

    /// @brief The values read() would hold, a z slice at a time in the grid's order (x fastest,
    /// then y; `components` values a voxel), without holding the grid: `slice(z, values)` for
    /// each z of the grid (not necessarily in increasing z). What `texsplat info` measures.
    /// @throws as read(), but never ResourceError for the grid.
    void forEachSlice(const std::string& names, std::int64_t timeStep,
                      const std::function<void(std::int64_t z, const std::vector<float>& values)>&
                          slice) const;

private:
    struct File;
    std::unique_ptr<File> mFile;
};

/// @brief The variables of a NetCDF file, in the file's order (NetCdfReader::variables()).
/// @throws as NetCdfReader's constructor.
std::vector<NetCdfVariableInfo> listNetCdfVariables(const std::string& path);

/// @brief Reads `variable` of the NetCDF file `path` (NetCdfReader::read(): a variable, three
/// separated by spaces for vectors, or empty for the only 3-D or 4-D one).
/// @throws as NetCdfReader's constructor and NetCdfReader::read().
AnyGrid readNetCdfVariable(const std::string& path, const std::string& variable,
                           std::int64_t timeStep = 0, const ProgressCallback& progress = {});

} // namespace texsplat::volume
