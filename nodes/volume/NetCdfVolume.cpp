#include "nodes/volume/NetCdfVolume.h"

#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/detail/Hdf5GlobalHeaps.h"
#include "nodes/volume/detail/NetCdfHeader.h"
#include "nodes/volume/detail/SourceSupport.h"
#include "scenegraph/Error.h"
#include "scenegraph/Log.h"
#include "scenegraph/MemoryLimit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <optional>

#ifdef TEXSPLAT_WITH_NETCDF
#include <netcdf.h>
#endif

namespace texsplat::volume {
namespace {

// Whether values of the CDL type `type` are numbers.
bool isNumberType(const std::string& type) {
    return type != "char" && type != "string" && type != "user-defined type";
}

} // namespace

bool NetCdfVariableInfo::isVolume() const {
    return isNumberType(type) && !isCoordinate &&
           (dimensions.size() == 3 || dimensions.size() == 4);
}

std::string NetCdfVariableInfo::declaration() const {
    std::string text = type + " " + name + "(";
    for (std::size_t i = 0; i < dimensions.size(); ++i)
        text += (i == 0 ? "" : ", ") + dimensions[i].name + "=" +
                std::to_string(dimensions[i].length);
    return text + ")";
}

#ifdef TEXSPLAT_WITH_NETCDF

namespace {

// netCDF-C is not thread-safe, and VolumeData nodes may load on several threads at once: every
// call into it holds this lock.
std::mutex sNetCdfMutex;

std::string variableList(const std::vector<NetCdfVariableInfo>& variables) {
    std::string names;
    for (const NetCdfVariableInfo& info : variables)
        if (!info.isCoordinate)
            names += (names.empty() ? "" : ", ") + info.declaration();
    return names.empty() ? "only coordinate variables" : names;
}

// nc_strerror() names itself: "NetCDF: Unknown file format".
void check(int status, const std::string& where, const std::string& what) {
    if (status != NC_NOERR)
        throw IoError(where + ": " + what + " (" + nc_strerror(status) + ")");
}

// An open file, closed when it goes.
class NetCdfFile {
public:
    explicit NetCdfFile(const std::string& path) : mPath(path) {
        // The same messages as every reader for missing files, folders and FIFOs.
        static_cast<void>(detail::openForReading(path));
        detail::checkNetCdfHeaderSizes(path);
        detail::checkHdf5GlobalHeaps(path);
        const int status = nc_open(path.c_str(), NC_NOWRITE, &mId);
        if (status == NC_ENOTNC)
            throw ParseError(path + ": not a NetCDF file: expected NetCDF classic, 64-bit offset, "
                                    "CDF-5 or NetCDF-4 (" +
                             nc_strerror(status) + ")");
        check(status, path, "cannot open NetCDF file");
    }
    ~NetCdfFile() { nc_close(mId); }
    NetCdfFile(const NetCdfFile&) = delete;
    NetCdfFile& operator=(const NetCdfFile&) = delete;

    int id() const { return mId; }
    const std::string& path() const { return mPath; }

private:
    std::string mPath;
    int mId = -1;
};

std::string typeName(nc_type type) {
    switch (type) {
    case NC_BYTE: return "byte";
    case NC_CHAR: return "char";
    case NC_SHORT: return "short";
    case NC_INT: return "int";
    case NC_FLOAT: return "float";
    case NC_DOUBLE: return "double";
    case NC_UBYTE: return "ubyte";
    case NC_USHORT: return "ushort";
    case NC_UINT: return "uint";
    case NC_INT64: return "int64";
    case NC_UINT64: return "uint64";
    case NC_STRING: return "string";
    default: return "user-defined type";
    }
}

// The fill value netCDF writes where nothing was written, for a variable without _FillValue;
// none for bytes, whose whole range is data by convention (NetCDF users' guide, "Fill Values").
std::optional<double> defaultFill(nc_type type) {
    switch (type) {
    case NC_SHORT: return NC_FILL_SHORT;
    case NC_INT: return NC_FILL_INT;
    case NC_FLOAT: return NC_FILL_FLOAT;
    case NC_DOUBLE: return NC_FILL_DOUBLE;
    case NC_USHORT: return NC_FILL_USHORT;
    case NC_UINT: return NC_FILL_UINT;
    case NC_INT64: return static_cast<double>(NC_FILL_INT64);
    case NC_UINT64: return static_cast<double>(NC_FILL_UINT64);
    default: return std::nullopt;
    }
}

NetCdfVariableInfo variableInfo(const NetCdfFile& file, int variable) {
    char name[NC_MAX_NAME + 1] = {};
    nc_type type = NC_NAT;
    int dimensionCount = 0;
    check(nc_inq_var(file.id(), variable, name, &type, &dimensionCount, nullptr, nullptr),
          file.path(), "cannot read variable " + std::to_string(variable));
    std::vector<int> dimensionIds(static_cast<std::size_t>(dimensionCount));
    check(nc_inq_vardimid(file.id(), variable, dimensionIds.data()), file.path(),
          std::string("cannot read the dimensions of variable '") + name + "'");
    NetCdfVariableInfo info;
    info.name = name;
    info.type = typeName(type);
    for (const int id : dimensionIds) {
        char dimensionName[NC_MAX_NAME + 1] = {};
        std::size_t length = 0;
        check(nc_inq_dim(file.id(), id, dimensionName, &length), file.path(),
              "cannot read dimension " + std::to_string(id));
        info.dimensions.push_back({dimensionName, static_cast<std::int64_t>(length)});
    }
    info.isCoordinate = info.dimensions.size() == 1 && info.dimensions[0].name == info.name;
    return info;
}

std::vector<NetCdfVariableInfo> variableInfos(const NetCdfFile& file) {
    int count = 0;
    check(nc_inq_nvars(file.id(), &count), file.path(), "cannot list the variables");
    std::vector<NetCdfVariableInfo> infos;
    for (int variable = 0; variable < count; ++variable)
        infos.push_back(variableInfo(file, variable));
    return infos;
}

// A number attribute's values; empty when the variable has no such attribute.
std::vector<double> numberAttribute(const NetCdfFile& file, int variable, const char* name) {
    nc_type type = NC_NAT;
    std::size_t length = 0;
    if (nc_inq_att(file.id(), variable, name, &type, &length) != NC_NOERR || type == NC_CHAR ||
        type == NC_STRING || length == 0)
        return {};
    std::vector<double> values(length);
    check(nc_get_att_double(file.id(), variable, name, values.data()), file.path(),
          std::string("cannot read attribute '") + name + "'");
    return values;
}

// Origin and spacing of one axis from its coordinate variable, if that is evenly spaced and
// increasing; nullopt otherwise.
std::optional<std::pair<double, double>> coordinateAxis(const NetCdfFile& file,
                                                        const NetCdfDimension& dimension) {
    int variable = -1;
    if (nc_inq_varid(file.id(), dimension.name.c_str(), &variable) != NC_NOERR)
        return std::nullopt;
    const NetCdfVariableInfo info = variableInfo(file, variable);
    if (!info.isCoordinate || !isNumberType(info.type))
        return std::nullopt;
    std::vector<double> values(static_cast<std::size_t>(dimension.length));
    check(nc_get_var_double(file.id(), variable, values.data()), file.path(),
          "cannot read coordinate variable '" + dimension.name + "'");
    if (values.size() == 1)
        return std::isfinite(values[0]) ? std::optional(std::pair(values[0], 1.0)) : std::nullopt;
    const double step = (values.back() - values.front()) / double(values.size() - 1);
    if (!(std::isfinite(step) && step > 0.0))
        return std::nullopt;
    constexpr double kTolerance = 1e-4; // of a step: float coordinates written as 0.1, 0.2, ...
    for (std::size_t i = 0; i < values.size(); ++i)
        if (!(std::abs(values[i] - (values.front() + double(i) * step)) <= kTolerance * step))
            return std::nullopt;
    return std::pair(values.front(), step);
}

// The one variable to read: `name`, or the only volume when `name` is empty.
int findVariable(const NetCdfFile& file, const std::string& name) {
    const std::vector<NetCdfVariableInfo> variables = variableInfos(file);
    if (name.empty()) {
        int found = -1;
        int volumes = 0;
        for (std::size_t i = 0; i < variables.size(); ++i)
            if (variables[i].isVolume()) {
                found = static_cast<int>(i);
                ++volumes;
            }
        if (volumes == 1)
            return found;
        if (volumes == 0)
            throw DataError(file.path() + ": no 3-D or 4-D variable to read; the file has: " +
                            variableList(variables));
        throw DataError(file.path() + ": no variable named, and the file has " +
                        std::to_string(volumes) +
                        " 3-D or 4-D variables; name one (VolumeData's gridName) of: " +
                        variableList(variables));
    }
    for (std::size_t i = 0; i < variables.size(); ++i)
        if (variables[i].name == name)
            return static_cast<int>(i);
    throw DataError(file.path() + ": no variable named '" + name + "'; the file has: " +
                    variableList(variables));
}

// Refuses variables of another number of dimensions or type, and time steps they do not have.
void checkShape(const NetCdfVariableInfo& info, const std::string& where, std::int64_t timeStep) {
    const std::size_t axes = info.dimensions.size();
    if (axes != 3 && axes != 4)
        throw DataError(where + " has " + std::to_string(axes) + " dimension" +
                        (axes == 1 ? "" : "s") + " (" + info.declaration() +
                        "); texsplat reads 3-D variables (z, y, x) and 4-D ones (time, z, y, x)");
    if (!info.isVolume())
        throw DataError(where + " holds " + info.type + " values; texsplat reads numbers");
    if (axes == 3 && timeStep != 0)
        throw DataError(where + ": timeStep " + std::to_string(timeStep) +
                        " asks for a time step of a variable without a time dimension");
    const std::int64_t steps = axes == 4 ? info.dimensions[0].length : 1;
    if (axes == 4 && (timeStep < 0 || timeStep >= steps))
        throw DataError(where + ": timeStep " + std::to_string(timeStep) + " is outside its " +
                        std::to_string(steps) + " steps along '" + info.dimensions[0].name +
                        "'" + (steps > 0 ? " (0 to " + std::to_string(steps - 1) + ")" : ""));
}

GridGeometry geometryOf(const glm::i64vec3& dims, const glm::dvec3& origin,
                        const glm::dvec3& spacing, const std::string& where) {
    try {
        return GridGeometry(dims, origin, spacing);
    } catch (const DataError& error) {
        throw DataError(where + ": " + error.what());
    }
}

// Dims from the last three dimensions (x the last); origin and spacing from their coordinate
// variables where those are evenly spaced and increasing.
GridGeometry variableGeometry(const NetCdfFile& file, const NetCdfVariableInfo& info,
                              const std::string& where) {
    const std::size_t first = info.dimensions.size() - 3;
    glm::i64vec3 dims;
    for (int axis = 0; axis < 3; ++axis)
        dims[axis] = info.dimensions[first + std::size_t(2 - axis)].length;
    // The grid is checked against the memory limit before its coordinates are read: they are as
    // long as its sides, which a NetCDF-4 file may declare of any length.
    detail::checkGridFitsInMemory(where, geometryOf(dims, glm::dvec3(0.0), glm::dvec3(1.0), where),
                                  1);
    glm::dvec3 origin(0.0);
    glm::dvec3 spacing(1.0);
    for (int axis = 0; axis < 3; ++axis) {
        const NetCdfDimension& dimension = info.dimensions[first + std::size_t(2 - axis)];
        if (const auto coordinates = coordinateAxis(file, dimension)) {
            origin[axis] = coordinates->first;
            spacing[axis] = coordinates->second;
        } else if (int coordinate = -1;
                   nc_inq_varid(file.id(), dimension.name.c_str(), &coordinate) == NC_NOERR) {
            log(LogLevel::Warning, where + ": coordinate '" + dimension.name +
                                       "' is not evenly spaced and increasing; its axis (" +
                                       "xyz"[axis] + ") is indexed 0, 1, 2, ...");
        }
    }
    return geometryOf(dims, origin, spacing, where);
}

// A NetCDF-4 variable stored in chunks is read a chunk at a time, which HDF5 allocates and
// decompresses whole: the file declares the chunks' size (up to 4 GiB each, along an unlimited
// dimension beyond the variable), checked before reading.
void checkChunksFitInMemory(const NetCdfFile& file, int variable, const std::string& where) {
    int axes = 0;
    nc_type type = NC_NAT;
    std::size_t typeBytes = 0;
    check(nc_inq_varndims(file.id(), variable, &axes), where, "cannot read the dimensions");
    check(nc_inq_vartype(file.id(), variable, &type), where, "cannot read the type");
    check(nc_inq_type(file.id(), type, nullptr, &typeBytes), where, "cannot read the type");
    int storage = NC_CONTIGUOUS;
    std::vector<std::size_t> chunk(static_cast<std::size_t>(axes));
    check(nc_inq_var_chunking(file.id(), variable, &storage, chunk.data()), where,
          "cannot read the chunking");
    if (storage != NC_CHUNKED)
        return;
    std::uint64_t bytes = typeBytes;
    std::string shape;
    for (const std::size_t length : chunk) {
        bytes = byteProduct(bytes, length);
        shape += (shape.empty() ? "" : " x ") + std::to_string(length);
    }
    detail::checkFitsInMemory(where + ": its chunks of " + shape + " values of " +
                                  std::to_string(typeBytes) +
                                  " bytes (HDF5 reads a chunk whole)",
                              bytes);
}

// Stored values to voxel values, by the CF conventions' attributes of the variable.
struct ValueMapping {
    double scale = 1.0;           // scale_factor
    double offset = 0.0;          // add_offset
    std::vector<double> missing;  // _FillValue (or the default fill) and missing_value

    float operator()(double raw) const {
        if (std::find(missing.begin(), missing.end(), raw) != missing.end())
            return std::numeric_limits<float>::quiet_NaN();
        return static_cast<float>(raw * scale + offset);
    }
};

ValueMapping valueMapping(const NetCdfFile& file, int variable, const std::string& where) {
    ValueMapping mapping;
    const std::vector<double> scale = numberAttribute(file, variable, "scale_factor");
    const std::vector<double> offset = numberAttribute(file, variable, "add_offset");
    const std::vector<double> fill = numberAttribute(file, variable, "_FillValue");
    mapping.missing = numberAttribute(file, variable, "missing_value");
    nc_type type = NC_NAT;
    check(nc_inq_vartype(file.id(), variable, &type), where, "cannot read the type");
    if (!fill.empty())
        mapping.missing.push_back(fill.front());
    else if (const auto fallback = defaultFill(type))
        mapping.missing.push_back(*fallback);
    if (!scale.empty())
        mapping.scale = scale.front();
    if (!offset.empty())
        mapping.offset = offset.front();
    return mapping;
}

} // namespace

bool isNetCdfAvailable() { return true; }

std::vector<NetCdfVariableInfo> listNetCdfVariables(const std::string& path) {
    const std::lock_guard<std::mutex> lock(sNetCdfMutex);
    const NetCdfFile file(path);
    return variableInfos(file);
}

AnyGrid readNetCdfVariable(const std::string& path, const std::string& variable,
                           std::int64_t timeStep, const ProgressCallback& progress) {
    const std::lock_guard<std::mutex> lock(sNetCdfMutex);
    const NetCdfFile file(path);
    const int id = findVariable(file, variable);
    const NetCdfVariableInfo info = variableInfo(file, id);
    const std::string where = path + ": variable '" + info.name + "'";
    checkShape(info, where, timeStep);
    const bool hasTime = info.dimensions.size() == 4;
    const GridGeometry geometry = variableGeometry(file, info, where);
    checkChunksFitInMemory(file, id, where);
    const ValueMapping mapping = valueMapping(file, id, where);

    auto grid = std::make_shared<DenseScalarGrid>(geometry);
    float* target = grid->values().data();
    const glm::i64vec3 dims = geometry.dims();
    std::vector<double> slice(static_cast<std::size_t>(dims.x * dims.y));
    const std::string message = "reading variable '" + info.name + "'";
    reportProgress(progress, path, 0.0, message);
    for (std::int64_t z = 0; z < dims.z; ++z) {
        // One z slice: (time step,) z, all y, all x.
        std::size_t start[4] = {};
        std::size_t count[4] = {};
        const std::size_t zAxis = hasTime ? 1 : 0;
        if (hasTime) {
            start[0] = static_cast<std::size_t>(timeStep);
            count[0] = 1;
        }
        start[zAxis] = static_cast<std::size_t>(z);
        count[zAxis] = 1;
        count[zAxis + 1] = static_cast<std::size_t>(dims.y);
        count[zAxis + 2] = static_cast<std::size_t>(dims.x);
        check(nc_get_vara_double(file.id(), id, start, count, slice.data()), where,
              "cannot read z slice " + std::to_string(z));
        for (const double raw : slice)
            *target++ = mapping(raw);
        reportProgress(progress, path, double(z + 1) / double(dims.z), message);
    }
    detail::checkFiniteVoxels(where, grid->statistics());
    return grid;
}

#else

namespace {

[[noreturn]] void notBuiltIn(const std::string& path) {
    throw IoError(path + ": cannot read NetCDF files: texsplat was built without NetCDF "
                         "(TEXSPLAT_WITH_NETCDF=OFF)");
}

} // namespace

bool isNetCdfAvailable() { return false; }

std::vector<NetCdfVariableInfo> listNetCdfVariables(const std::string& path) { notBuiltIn(path); }

AnyGrid readNetCdfVariable(const std::string& path, const std::string&, std::int64_t,
                           const ProgressCallback&) {
    notBuiltIn(path);
}

#endif

} // namespace texsplat::volume
