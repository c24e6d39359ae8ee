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
#include <iterator>
#include <limits>
#include <mutex>
#include <optional>
#include <sstream>

#ifdef TEXSPLAT_WITH_NETCDF
#include <netcdf.h>
#include <netcdf_filter.h>
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
// call into it holds this lock (a NetCdfReader holds it for its life).
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

// One axis of the grid from its coordinate variable: origin and spacing, and whether the file
// stores it from its far end (a decreasing coordinate).
struct Axis {
    double origin = 0.0;
    double spacing = 1.0;
    bool reversed = false;
};

// What a reader reads for one `names`: the variables (one, or three for vectors) and where their
// voxels lie.
struct Selection {
    std::vector<int> ids;
    std::vector<NetCdfVariableInfo> infos;
    std::string where;   // "f.nc: variable 't'" or "f.nc: variables 'u', 'v', 'w'"
    std::string message; // the progress message: "reading variable 't'"
    GridGeometry geometry{glm::i64vec3(1)};
    glm::bvec3 reversed{false};
};

} // namespace

// The open file, with netCDF-C's lock held.
struct NetCdfReader::File {
    std::lock_guard<std::mutex> lock{sNetCdfMutex};
    struct SelectionFor {
        std::string names;
        std::int64_t timeStep = 0;
        Selection selection;
    };

    std::string path;
    int id = -1;
    std::vector<NetCdfVariableInfo> variables;
    mutable std::optional<SelectionFor> lastSelection;

    explicit File(const std::string& filePath) : path(filePath) {
        // The same messages as every reader for missing files, folders and FIFOs.
        static_cast<void>(detail::openForReading(path));
        detail::checkNetCdfHeaderSizes(path);
        detail::checkHdf5GlobalHeaps(path);
        const int status = nc_open(path.c_str(), NC_NOWRITE, &id);
        if (status == NC_ENOTNC)
            throw ParseError(path + ": not a NetCDF file: expected NetCDF classic, 64-bit offset, "
                                    "CDF-5 or NetCDF-4 (" +
                             nc_strerror(status) + ")");
        check(status, path, "cannot open NetCDF file");
        try {
            int count = 0;
            check(nc_inq_nvars(id, &count), path, "cannot list the variables");
            variables.reserve(static_cast<std::size_t>(count));
            for (int variable = 0; variable < count; ++variable)
                variables.push_back(variableInfo(variable));
        } catch (...) {
            nc_close(id);
            throw;
        }
    }
    ~File() { nc_close(id); }
    File(const File&) = delete;
    File& operator=(const File&) = delete;

    NetCdfVariableInfo variableInfo(int variable) const {
        char name[NC_MAX_NAME + 1] = {};
        nc_type type = NC_NAT;
        int dimensionCount = 0;
        check(nc_inq_var(id, variable, name, &type, &dimensionCount, nullptr, nullptr), path,
              "cannot read variable " + std::to_string(variable));
        std::vector<int> dimensionIds(static_cast<std::size_t>(dimensionCount));
        check(nc_inq_vardimid(id, variable, dimensionIds.data()), path,
              std::string("cannot read the dimensions of variable '") + name + "'");
        NetCdfVariableInfo info;
        info.name = name;
        info.type = typeName(type);
        for (const int dimension : dimensionIds) {
            char dimensionName[NC_MAX_NAME + 1] = {};
            std::size_t length = 0;
            check(nc_inq_dim(id, dimension, dimensionName, &length), path,
                  "cannot read dimension " + std::to_string(dimension));
            info.dimensions.push_back({dimensionName, static_cast<std::int64_t>(length)});
        }
        info.isCoordinate = info.dimensions.size() == 1 && info.dimensions[0].name == info.name;
        return info;
    }

    // The variable named `name` (looked up, not searched: a file may have thousands).
    std::optional<int> find(const std::string& name) const {
        int variable = -1;
        if (nc_inq_varid(id, name.c_str(), &variable) != NC_NOERR)
            return std::nullopt;
        return variable;
    }

    // The ids `names` means: one variable, the only volume when empty, or three names of
    // vector components.
    std::vector<int> resolve(const std::string& names) const {
        if (names.empty()) {
            std::vector<int> volumes;
            for (std::size_t i = 0; i < variables.size(); ++i)
                if (variables[i].isVolume())
                    volumes.push_back(static_cast<int>(i));
            if (volumes.size() == 1)
                return volumes;
            if (volumes.empty())
                throw DataError(path + ": no 3-D or 4-D variable to read; the file has: " +
                                variableList(variables));
            throw DataError(path + ": no variable named, and the file has " +
                            std::to_string(volumes.size()) +
                            " 3-D or 4-D variables; name one (VolumeData's gridName) of: " +
                            variableList(variables));
        }
        if (const std::optional<int> variable = find(names))
            return {*variable};
        std::istringstream words(names);
        std::vector<std::string> components{std::istream_iterator<std::string>(words),
                                            std::istream_iterator<std::string>()};
        if (components.size() == 1)
            throw DataError(path + ": no variable named '" + names + "'; the file has: " +
                            variableList(variables));
        if (components.size() != 3)
            throw DataError(path + ": '" + names + "' names " +
                            std::to_string(components.size()) +
                            " variables; vectors take three, their x, y and z components "
                            "('u v w')");
        std::vector<int> ids;
        for (const std::string& component : components) {
            const std::optional<int> variable = find(component);
            if (!variable)
                throw DataError(path + ": no variable named '" + component + "' (of the vector '" +
                                names + "'); the file has: " + variableList(variables));
            ids.push_back(*variable);
        }
        return ids;
    }

    // A number attribute's values; empty when the variable has no such attribute.
    std::vector<double> numberAttribute(int variable, const char* name) const {
        nc_type type = NC_NAT;
        std::size_t length = 0;
        if (nc_inq_att(id, variable, name, &type, &length) != NC_NOERR || type == NC_CHAR ||
            type == NC_STRING || length == 0)
            return {};
        std::vector<double> values(length);
        check(nc_get_att_double(id, variable, name, values.data()), path,
              std::string("cannot read attribute '") + name + "'");
        return values;
    }

    // The axis of `dimension` from its coordinate variable, if that is evenly spaced; nullopt
    // otherwise (also without a coordinate variable).
    std::optional<Axis> coordinateAxis(const NetCdfDimension& dimension) const {
        const std::optional<int> variable = find(dimension.name);
        if (!variable)
            return std::nullopt;
        const NetCdfVariableInfo info = variableInfo(*variable);
        if (!info.isCoordinate || !isNumberType(info.type))
            return std::nullopt;
        std::vector<double> values(static_cast<std::size_t>(dimension.length));
        check(nc_get_var_double(id, *variable, values.data()), path,
              "cannot read coordinate variable '" + dimension.name + "'");
        if (values.size() == 1)
            return std::isfinite(values[0]) ? std::optional(Axis{values[0], 1.0, false})
                                            : std::nullopt;
        const double step = (values.back() - values.front()) / double(values.size() - 1);
        if (!(std::isfinite(step) && step != 0.0))
            return std::nullopt;
        constexpr double kTolerance = 1e-4; // of a step: float coordinates written as 0.1, 0.2...
        for (std::size_t i = 0; i < values.size(); ++i)
            if (!(std::abs(values[i] - (values.front() + double(i) * step)) <=
                  kTolerance * std::abs(step)))
                return std::nullopt;
        // A decreasing axis runs from its last value, the smallest.
        return step > 0.0 ? Axis{values.front(), step, false} : Axis{values.back(), -step, true};
    }

    // Dims from the last three dimensions (x the last); origin and spacing from their
    // coordinate variables where those are evenly spaced.
    void placeVoxels(Selection& selection) const {
        const NetCdfVariableInfo& info = selection.infos.front();
        const std::size_t first = info.dimensions.size() - 3;
        glm::i64vec3 dims;
        for (int axis = 0; axis < 3; ++axis)
            dims[axis] = info.dimensions[first + std::size_t(2 - axis)].length;
        // The grid is checked before its coordinates are read: they are as long as its sides,
        // which a NetCDF-4 file may declare of any length.
        geometryOf(dims, glm::dvec3(0.0), glm::dvec3(1.0), selection.where);
        glm::dvec3 origin(0.0);
        glm::dvec3 spacing(1.0);
        for (int axis = 0; axis < 3; ++axis) {
            const NetCdfDimension& dimension = info.dimensions[first + std::size_t(2 - axis)];
            if (const std::optional<Axis> coordinates = coordinateAxis(dimension)) {
                origin[axis] = coordinates->origin;
                spacing[axis] = coordinates->spacing;
                selection.reversed[axis] = coordinates->reversed;
            } else if (find(dimension.name)) {
                log(LogLevel::Warning, selection.where + ": coordinate '" + dimension.name +
                                           "' is not evenly spaced; its axis (" + "xyz"[axis] +
                                           ") is indexed 0, 1, 2, ...");
            }
        }
        selection.geometry = geometryOf(dims, origin, spacing, selection.where);
    }

    // What `names` selects at `timeStep`, made once for the calls about one selection in a
    // row (info asks its geometry, then streams it twice): a coordinate's warning is logged once.
    const Selection& select(const std::string& names, std::int64_t timeStep) const {
        if (!lastSelection || lastSelection->names != names ||
            lastSelection->timeStep != timeStep)
            lastSelection = SelectionFor{names, timeStep, makeSelection(names, timeStep)};
        return lastSelection->selection;
    }

    Selection makeSelection(const std::string& names, std::int64_t timeStep) const {
        Selection selection;
        selection.ids = resolve(names);
        std::string quoted;
        for (const int variable : selection.ids) {
            selection.infos.push_back(variables[static_cast<std::size_t>(variable)]);
            quoted += (quoted.empty() ? "'" : ", '") + selection.infos.back().name + "'";
        }
        const bool vectors = selection.ids.size() == 3;
        selection.where = path + (vectors ? ": variables " : ": variable ") + quoted;
        selection.message = (vectors ? "reading variables " : "reading variable ") + quoted;
        for (const NetCdfVariableInfo& info : selection.infos) {
            checkShape(info, vectors ? path + ": variable '" + info.name + "'" : selection.where,
                       timeStep);
            if (info.dimensions != selection.infos.front().dimensions)
                throw DataError(selection.where + ": the components of vectors must have the same "
                                                  "dimensions, but " +
                                selection.infos.front().declaration() + " and " +
                                info.declaration() + " differ");
        }
        placeVoxels(selection);
        return selection;
    }

    // A NetCDF-4 variable is stored in chunks, which HDF5 allocates and decompresses whole
    // (the file declares their size, up to 4 GiB each along an unlimited dimension); chunks
    // never written are not stored at all and read as fill values. Both are checked before
    // reading: the chunks against the memory limit, the variable against what the file could
    // hold (a 20 KB file declared 3.8 GB of fill values, converted for minutes).
    void checkStorage(const Selection& selection) const {
        int format = 0;
        check(nc_inq_format(id, &format), path, "cannot read the format");
        const bool isHdf5 = format == NC_FORMAT_NETCDF4 || format == NC_FORMAT_NETCDF4_CLASSIC;
        for (const int variable : selection.ids) {
            const std::string where = path + ": variable '" +
                                      variables[static_cast<std::size_t>(variable)].name + "'";
            int axes = 0;
            nc_type type = NC_NAT;
            std::size_t typeBytes = 0;
            check(nc_inq_varndims(id, variable, &axes), where, "cannot read the dimensions");
            check(nc_inq_vartype(id, variable, &type), where, "cannot read the type");
            check(nc_inq_type(id, type, nullptr, &typeBytes), where, "cannot read the type");
            int storage = NC_CONTIGUOUS;
            std::vector<std::size_t> chunk(static_cast<std::size_t>(axes));
            check(nc_inq_var_chunking(id, variable, &storage, chunk.data()), where,
                  "cannot read the chunking");
            if (storage == NC_CHUNKED) {
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
            if (isHdf5)
                checkDeclaredSize(variable, where, typeBytes, selection.geometry);
        }
    }

    // Refuses a NetCDF-4 variable whose one step holds more values than the file could store,
    // compressed with deflate (the filters netCDF-C writes: deflate, shuffle, checksums) or not:
    // the rest would be fill values, chunks never written.
    void checkDeclaredSize(int variable, const std::string& where, std::size_t typeBytes,
                           const GridGeometry& geometry) const {
        std::size_t filterCount = 0;
        if (nc_inq_var_filter_ids(id, variable, &filterCount, nullptr) != NC_NOERR)
            return;
        std::vector<unsigned int> filters(filterCount);
        if (filterCount > 0)
            check(nc_inq_var_filter_ids(id, variable, &filterCount, filters.data()), where,
                  "cannot read the filters");
        constexpr unsigned int kDeflate = 1;
        constexpr unsigned int kShuffle = 2;
        constexpr unsigned int kFletcher32 = 3;
        bool deflated = false;
        for (const unsigned int filter : filters) {
            if (filter == kDeflate)
                deflated = true;
            else if (filter != kShuffle && filter != kFletcher32)
                return; // another compressor's ratio is not known here
        }
        const auto fileBytes = static_cast<std::uint64_t>(detail::fileSize(path));
        const std::uint64_t most = deflated ? detail::maxDeflatedBytes(fileBytes) : fileBytes;
        const glm::i64vec3 dims = geometry.dims();
        const std::uint64_t declared =
            byteProduct(static_cast<std::uint64_t>(geometry.voxelCount()), typeBytes);
        if (declared <= most)
            return;
        throw DataError(where + ": a step of " + std::to_string(dims.x) + " x " +
                        std::to_string(dims.y) + " x " + std::to_string(dims.z) + " values of " +
                        std::to_string(typeBytes) + " bytes (" + std::to_string(declared) +
                        " bytes) cannot come from a file of " + std::to_string(fileBytes) +
                        " bytes, which " +
                        (deflated ? "compressed with deflate holds at most "
                                  : "uncompressed holds at most ") +
                        std::to_string(most) +
                        " bytes of values: the rest would be fill values, never written (empty "
                        "voxels)");
    }

    ValueMapping valueMapping(int variable, const std::string& where) const {
        ValueMapping mapping;
        const std::vector<double> scale = numberAttribute(variable, "scale_factor");
        const std::vector<double> offset = numberAttribute(variable, "add_offset");
        const std::vector<double> fill = numberAttribute(variable, "_FillValue");
        mapping.missing = numberAttribute(variable, "missing_value");
        nc_type type = NC_NAT;
        check(nc_inq_vartype(id, variable, &type), where, "cannot read the type");
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

    // Reads the selection a z slice of the file at a time into `slice(z, values)`, values in the
    // grid's order (axes the file stores from their far end turned round), interleaved for
    // vectors.
    // `region` (of the grid's voxels; the whole grid by default) limits the read to its
    // hyperslab: the slices are then the region's, numbered from its first.
    void readSlices(const Selection& selection, std::int64_t timeStep,
                    const ProgressCallback& progress,
                    const std::function<void(std::int64_t, const std::vector<float>&)>& slice,
                    const std::optional<IndexBox>& region = std::nullopt) const {
        const std::size_t components = selection.ids.size();
        std::vector<ValueMapping> mappings;
        for (const int variable : selection.ids)
            mappings.push_back(valueMapping(variable, selection.where));
        const bool hasTime = selection.infos.front().dimensions.size() == 4;
        const glm::i64vec3 whole = selection.geometry.dims();
        const IndexBox box = region.value_or(IndexBox::of(selection.geometry));
        const glm::i64vec3 dims = box.dims();
        const glm::bvec3 reversed = selection.reversed;
        // The file's first index of the box along each axis (the far end of a reversed one).
        glm::i64vec3 fileFirst;
        for (int axis = 0; axis < 3; ++axis)
            fileFirst[axis] = reversed[axis] ? whole[axis] - box.hi[axis] : box.lo[axis];
        const std::size_t sliceVoxels = static_cast<std::size_t>(dims.x * dims.y);
        std::vector<double> raw(sliceVoxels);
        std::vector<float> values(sliceVoxels * components);
        reportProgress(progress, path, 0.0, selection.message);
        for (std::int64_t fileZ = 0; fileZ < dims.z; ++fileZ) {
            for (std::size_t component = 0; component < components; ++component) {
                // One z slice of the box: (time step,) z, its y, its x.
                std::size_t start[4] = {};
                std::size_t count[4] = {};
                const std::size_t zAxis = hasTime ? 1 : 0;
                if (hasTime) {
                    start[0] = static_cast<std::size_t>(timeStep);
                    count[0] = 1;
                }
                start[zAxis] = static_cast<std::size_t>(fileFirst.z + fileZ);
                start[zAxis + 1] = static_cast<std::size_t>(fileFirst.y);
                start[zAxis + 2] = static_cast<std::size_t>(fileFirst.x);
                count[zAxis] = 1;
                count[zAxis + 1] = static_cast<std::size_t>(dims.y);
                count[zAxis + 2] = static_cast<std::size_t>(dims.x);
                check(nc_get_vara_double(id, selection.ids[component], start, count, raw.data()),
                      selection.where,
                      "cannot read z slice " + std::to_string(fileFirst.z + fileZ));
                const ValueMapping& mapping = mappings[component];
                std::size_t n = 0;
                for (std::int64_t fileY = 0; fileY < dims.y; ++fileY) {
                    const std::int64_t y = reversed.y ? dims.y - 1 - fileY : fileY;
                    for (std::int64_t fileX = 0; fileX < dims.x; ++fileX, ++n) {
                        const std::int64_t x = reversed.x ? dims.x - 1 - fileX : fileX;
                        values[static_cast<std::size_t>(x + dims.x * y) * components +
                               component] = mapping(raw[n]);
                    }
                }
            }
            slice(reversed.z ? dims.z - 1 - fileZ : fileZ, values);
            reportProgress(progress, path, double(fileZ + 1) / double(dims.z), selection.message);
        }
    }
};

bool isNetCdfAvailable() { return true; }

NetCdfReader::NetCdfReader(const std::string& path) : mFile(std::make_unique<File>(path)) {}

NetCdfReader::~NetCdfReader() = default;

const std::vector<NetCdfVariableInfo>& NetCdfReader::variables() const {
    return mFile->variables;
}

std::pair<GridGeometry, int> NetCdfReader::geometry(const std::string& names,
                                                    std::int64_t timeStep) const {
    const Selection& selection = mFile->select(names, timeStep);
    return {selection.geometry, static_cast<int>(selection.ids.size())};
}

AnyGrid NetCdfReader::read(const std::string& names, std::int64_t timeStep,
                           const ProgressCallback& progress,
                           const std::optional<IndexBox>& region) const {
    const Selection& selection = mFile->select(names, timeStep);
    const int components = static_cast<int>(selection.ids.size());
    const IndexBox all = IndexBox::of(selection.geometry);
    if (region && (region->isEmpty() || region->intersection(all) != *region))
        throw DataError(selection.where + ": brick " + region->text() +
                        " is not a box of voxels of the grid's " + all.text());
    const GridGeometry geometry =
        region ? boxGeometry(selection.geometry, *region) : selection.geometry;
    detail::checkGridFitsInMemory(selection.where, geometry, components);
    mFile->checkStorage(selection);
    const glm::i64vec3 dims = geometry.dims();
    const auto sliceVoxels = static_cast<std::size_t>(dims.x * dims.y);
    // A brick's voxels are checked with the whole grid's, by the render that split it.
    const auto checkFinite = [&](const auto& grid) {
        if (!region)
            detail::checkFiniteVoxels(selection.where, grid->statistics());
    };
    if (components == 1) {
        auto grid = std::make_shared<DenseScalarGrid>(geometry);
        mFile->readSlices(
            selection, timeStep, progress,
            [&](std::int64_t z, const std::vector<float>& values) {
                std::copy(values.begin(), values.end(),
                          grid->values().begin() + static_cast<std::ptrdiff_t>(z * sliceVoxels));
            },
            region);
        checkFinite(grid);
        return grid;
    }
    auto grid = std::make_shared<DenseVectorGrid>(geometry);
    mFile->readSlices(
        selection, timeStep, progress,
        [&](std::int64_t z, const std::vector<float>& values) {
            glm::vec3* target =
                grid->values().data() + static_cast<std::ptrdiff_t>(z * sliceVoxels);
            for (std::size_t voxel = 0; voxel < sliceVoxels; ++voxel)
                target[voxel] =
                    glm::vec3(values[3 * voxel], values[3 * voxel + 1], values[3 * voxel + 2]);
        },
        region);
    checkFinite(grid);
    return grid;
}

void NetCdfReader::forEachSlice(
    const std::string& names, std::int64_t timeStep,
    const std::function<void(std::int64_t z, const std::vector<float>& values)>& slice) const {
    const Selection& selection = mFile->select(names, timeStep);
    mFile->checkStorage(selection);
    mFile->readSlices(selection, timeStep, {}, slice);
}

std::vector<NetCdfVariableInfo> listNetCdfVariables(const std::string& path) {
    return NetCdfReader(path).variables();
}

AnyGrid readNetCdfVariable(const std::string& path, const std::string& variable,
                           std::int64_t timeStep, const ProgressCallback& progress) {
    return NetCdfReader(path).read(variable, timeStep, progress);
}

#else

namespace {

[[noreturn]] void notBuiltIn(const std::string& path) {
    throw IoError(path + ": cannot read NetCDF files: texsplat was built without NetCDF "
                         "(TEXSPLAT_WITH_NETCDF=OFF)");
}

} // namespace

struct NetCdfReader::File {};

bool isNetCdfAvailable() { return false; }

NetCdfReader::NetCdfReader(const std::string& path) { notBuiltIn(path); }

NetCdfReader::~NetCdfReader() = default;

const std::vector<NetCdfVariableInfo>& NetCdfReader::variables() const {
    static const std::vector<NetCdfVariableInfo> kNone;
    return kNone;
}

std::pair<GridGeometry, int> NetCdfReader::geometry(const std::string&, std::int64_t) const {
    return {GridGeometry(glm::i64vec3(1)), 1};
}

AnyGrid NetCdfReader::read(const std::string&, std::int64_t, const ProgressCallback&,
                           const std::optional<IndexBox>&) const {
    return {};
}

void NetCdfReader::forEachSlice(
    const std::string&, std::int64_t,
    const std::function<void(std::int64_t, const std::vector<float>&)>&) const {}

std::vector<NetCdfVariableInfo> listNetCdfVariables(const std::string& path) { notBuiltIn(path); }

AnyGrid readNetCdfVariable(const std::string& path, const std::string&, std::int64_t,
                           const ProgressCallback&) {
    notBuiltIn(path);
}

#endif

} // namespace texsplat::volume
