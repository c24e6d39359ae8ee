#include "nodes/volume/VolumeFileInfo.h"

#include "nodes/volume/NetCdfVolume.h"
#include "nodes/volume/NpyHeader.h"
#include "nodes/volume/NpyVolume.h"
#include "nodes/volume/NrrdHeader.h"
#include "nodes/volume/NrrdVolume.h"
#include "nodes/volume/RawHeader.h"
#include "nodes/volume/RawVolume.h"
#include "nodes/volume/ValueHistogram.h"
#include "nodes/volume/VdbVolume.h"
#include "nodes/volume/detail/RawData.h"
#include "nodes/volume/detail/SourceSupport.h"
#include "scenegraph/Error.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <optional>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace texsplat::volume {
namespace {

constexpr int kBarWidth = 40;

// Six significant digits: what a user reads off to write a scene.
std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

// The shortest text that reads back as the same float: voxel values exactly as stored.
std::string floatNumber(double value) {
    char text[32];
    for (int precision = 6; precision <= 9; ++precision) {
        std::snprintf(text, sizeof text, "%.*g", precision, value);
        if (static_cast<float>(std::strtod(text, nullptr)) == static_cast<float>(value))
            break;
    }
    return text;
}

std::string padRight(const std::string& text, std::size_t width) {
    return text.size() >= width ? text : text + std::string(width - text.size(), ' ');
}

std::string padLeft(const std::string& text, std::size_t width) {
    return text.size() >= width ? text : std::string(width - text.size(), ' ') + text;
}

std::string triple(const glm::dvec3& v, const char* separator) {
    return number(v.x) + separator + number(v.y) + separator + number(v.z);
}

// One pass over a grid's values: `chunk(values, voxels)` with `components` floats a voxel, until
// every voxel was given once.
using VoxelChunk = std::function<void(const float* values, std::int64_t voxels)>;
using ValuePass = std::function<void(const VoxelChunk& chunk)>;

// What `info` prints of a grid's values.
struct ValueSummary {
    GridStatistics statistics;
    std::vector<std::uint64_t> histogram; // over statistics.minimum .. maximum
};

double scalarOf(const float* voxel, int components) {
    return components == 1 ? double(*voxel)
                           : glm::length(glm::dvec3(voxel[0], voxel[1], voxel[2]));
}

bool isFiniteVoxel(const float* voxel, int components) {
    for (int c = 0; c < components; ++c)
        if (!std::isfinite(voxel[c]))
            return false;
    return true;
}

// The values of `pass` in two passes: their range, then the histogram over it.
ValueSummary summarize(const ValuePass& pass, int components, int bins) {
    ValueSummary summary;
    GridStatistics& statistics = summary.statistics;
    double lowest = std::numeric_limits<double>::infinity();
    double highest = -std::numeric_limits<double>::infinity();
    pass([&](const float* values, std::int64_t voxels) {
        for (std::int64_t i = 0; i < voxels; ++i, values += components) {
            if (!isFiniteVoxel(values, components)) {
                ++statistics.nonFiniteCount;
                continue;
            }
            ++statistics.finiteCount;
            const double value = scalarOf(values, components);
            lowest = std::min(lowest, value);
            highest = std::max(highest, value);
        }
    });
    summary.histogram.assign(static_cast<std::size_t>(bins), 0);
    if (statistics.finiteCount == 0)
        return summary;
    statistics.minimum = lowest;
    statistics.maximum = highest;
    if (!(highest > lowest)) {
        summary.histogram[0] = static_cast<std::uint64_t>(statistics.finiteCount);
        return summary;
    }
    // As valueHistogram() bins them.
    const double span = highest - lowest;
    pass([&](const float* values, std::int64_t voxels) {
        for (std::int64_t i = 0; i < voxels; ++i, values += components) {
            if (!isFiniteVoxel(values, components))
                continue;
            const double bin = (scalarOf(values, components) - lowest) / span * double(bins);
            summary.histogram[std::min(std::size_t(bins) - 1,
                                       static_cast<std::size_t>(std::max(0.0, bin)))] += 1;
        }
    });
    return summary;
}

// The summary of a grid held in memory.
template <typename T>
ValueSummary summarize(const Grid<T>& grid, int bins) {
    ValueSummary summary;
    summary.statistics = grid.statistics();
    const GridStatistics& statistics = summary.statistics;
    summary.histogram.assign(static_cast<std::size_t>(bins), 0);
    if (statistics.maximum > statistics.minimum)
        summary.histogram = valueHistogram(grid, statistics.minimum, statistics.maximum,
                                           static_cast<std::size_t>(bins));
    else if (statistics.finiteCount > 0)
        summary.histogram[0] = static_cast<std::uint64_t>(statistics.finiteCount);
    return summary;
}

std::string describeGrid(const GridGeometry& geometry, int components,
                         const ValueSummary& summary) {
    const GridStatistics& statistics = summary.statistics;
    const glm::i64vec3 dims = geometry.dims();
    std::string text;
    const auto row = [&text](const std::string& key, const std::string& value) {
        text += "  " + padRight(key, 14) + value + "\n";
    };
    row("values", components == 1 ? "scalar" : "vector (3 components)");
    row("dimensions", std::to_string(dims.x) + " x " + std::to_string(dims.y) + " x " +
                          std::to_string(dims.z) + " voxels (x, y, z)");
    row("voxel size", triple(geometry.spacing(), " x "));
    row("bounding box", "(" + triple(geometry.boundsMin(), ", ") + ") .. (" +
                            triple(geometry.boundsMax(), ", ") + ")");
    row("active voxels", std::to_string(statistics.finiteCount) + " of " +
                             std::to_string(geometry.voxelCount()) +
                             (statistics.nonFiniteCount > 0
                                  ? " (" + std::to_string(statistics.nonFiniteCount) +
                                        " more are NaN or infinite)"
                                  : std::string()));
    if (statistics.finiteCount == 0)
        return text;
    row(components == 1 ? "value range" : "length range",
        floatNumber(statistics.minimum) + " .. " + floatNumber(statistics.maximum));
    const std::size_t bins = summary.histogram.size();
    const double low = statistics.minimum;
    const double width = (statistics.maximum - low) / double(bins);
    const std::uint64_t most =
        std::max<std::uint64_t>(1, *std::max_element(summary.histogram.begin(),
                                                     summary.histogram.end()));
    text += "  histogram (" + std::to_string(bins) + " bins)\n";
    for (std::size_t bin = 0; bin < bins; ++bin) {
        const std::uint64_t count = summary.histogram[bin];
        const auto bar = static_cast<int>((count * kBarWidth + most - 1) / most);
        text += "    " + padLeft(number(low + double(bin) * width), 12) + " .. " +
                padRight(number(low + double(bin + 1) * width), 12) + " " +
                padLeft(std::to_string(count), 10) +
                (bar > 0 ? " " + std::string(static_cast<std::size_t>(bar), '#') : std::string()) +
                "\n";
    }
    return text;
}

std::string describe(const AnyGrid& grid, int bins) {
    return std::visit(
        [bins](const auto& g) {
            using T = typename std::decay_t<decltype(*g)>::ValueType;
            return describeGrid(g->geometry(), std::is_same_v<T, float> ? 1 : 3,
                                summarize(*g, bins));
        },
        grid);
}

// The description of the raw values of `layout`, stored in `order`, that `use` hands a decoder:
// streamed, unless they are vectors in Fortran order, whose components lie apart (read whole).
std::string describeRaw(const RawHeader& layout, detail::RawOrder order,
                        const std::function<void(const detail::RawDataDecoder&)>& use, int bins) {
    const int components = layout.components;
    if (order == detail::RawOrder::ZFastest && components != 1)
        return describe(detail::readRawGrid(use, {}), bins);
    const ValuePass pass = [&](const VoxelChunk& chunk) {
        use([&](const detail::RawDataView& data) {
            detail::readRawValues(data, {},
                                  [&](std::int64_t, const float* values, std::int64_t count) {
                                      chunk(values, count / components);
                                  });
        });
    };
    return describeGrid(GridGeometry(layout.dims, layout.origin, layout.spacing), components,
                        summarize(pass, components, bins));
}

std::string snippet(const std::string& source, const std::string& path,
                    const std::string& gridName = {}) {
    return "  scene         VolumeData { source " + source + " fileName \"" + path + "\"" +
           (gridName.empty() ? std::string() : " gridName \"" + gridName + "\"") + " }\n";
}

std::string upperCase(std::string text) {
    for (char& c : text)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

// VolumeData's fields for a headerless raw file.
std::string headerlessFields(const HeaderlessRawLayout& headerless) {
    const RawHeader& layout = headerless.layout;
    return "source FILE_RAW_HEADERLESS fileName \"{path}\" dimensions " +
           std::to_string(layout.dims.x) + " " + std::to_string(layout.dims.y) + " " +
           std::to_string(layout.dims.z) + " dataType " + upperCase(toString(layout.type)) +
           (layout.endian == RawEndian::Big ? " byteOrder BIG" : "") +
           (headerless.headerBytes != 0
                ? " headerBytes " + std::to_string(headerless.headerBytes)
                : std::string()) +
           (layout.components != 1 ? " components " + std::to_string(layout.components)
                                   : std::string());
}

std::string replacedPath(std::string text, const std::string& path) {
    text.replace(text.find("{path}"), 6, path);
    return text;
}

// Three volume variables `u…`, `v…`, `w…` of the same dimensions: the vectors they make.
std::string netCdfVectors(const std::vector<NetCdfVariableInfo>& variables,
                          const std::string& path) {
    const auto volume = [&](const std::string& name) -> const NetCdfVariableInfo* {
        for (const NetCdfVariableInfo& info : variables)
            if (info.name == name && info.isVolume())
                return &info;
        return nullptr;
    };
    std::string text;
    for (const NetCdfVariableInfo& u : variables) {
        if (!u.isVolume() || (u.name[0] != 'u' && u.name[0] != 'U'))
            continue;
        const bool upper = u.name[0] == 'U';
        const std::string rest = u.name.substr(1);
        const NetCdfVariableInfo* v = volume((upper ? "V" : "v") + rest);
        const NetCdfVariableInfo* w = volume((upper ? "W" : "w") + rest);
        if (v == nullptr || w == nullptr || v->dimensions != u.dimensions ||
            w->dimensions != u.dimensions)
            continue;
        const std::string names = u.name + " " + v->name + " " + w->name;
        text += "vectors '" + names + "' (x, y, z: three variables of the same dimensions)\n" +
                snippet("FILE_NETCDF", path, names);
    }
    return text;
}

} // namespace

VolumeFileFormat detectVolumeFileFormat(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        return VolumeFileFormat::Unknown;
    std::ifstream in(path, std::ios::binary);
    char start[12] = {};
    in.read(start, sizeof start);
    const std::string_view head(start, static_cast<std::size_t>(in.gcount()));
    if (head.substr(0, 12) == "texsplat-raw")
        return VolumeFileFormat::TexsplatRaw;
    if (head.substr(0, 6) == "\x93NUMPY")
        return VolumeFileFormat::Npy;
    if (head.substr(0, 4) == "NRRD")
        return VolumeFileFormat::Nrrd;
    // NetCDF classic ("CDF\1"), 64-bit offset ("CDF\2"), CDF-5 ("CDF\5"); NetCDF-4 is HDF5.
    if (head.substr(0, 3) == "CDF" || head.substr(0, 8) == "\x89HDF\r\n\x1a\n")
        return VolumeFileFormat::NetCdf;
    // OpenVDB's magic number 0x56444220 ("VDB "), written little endian.
    if (head.substr(0, 4) == std::string_view(" BDV", 4))
        return VolumeFileFormat::Vdb;
    // A .raw without the header is most likely headerless raw: the texsplat-raw reader's message
    // then says how to describe it in a scene.
    const std::string extension = std::filesystem::path(path).extension().string();
    if (extension == ".raw")
        return VolumeFileFormat::TexsplatRaw;
    if (extension == ".npy")
        return VolumeFileFormat::Npy;
    if (extension == ".nrrd" || extension == ".nhdr")
        return VolumeFileFormat::Nrrd;
    if (extension == ".nc" || extension == ".nc4")
        return VolumeFileFormat::NetCdf;
    if (extension == ".vdb")
        return VolumeFileFormat::Vdb;
    return VolumeFileFormat::Unknown;
}

std::string describeVolumeFile(const std::string& path, int histogramBins,
                               const std::optional<HeaderlessRawLayout>& headerless,
                               const sg::DataRoots* roots) {
    const int bins = std::max(1, histogramBins);
    if (headerless) {
        const RawHeader& layout = headerless->layout;
        std::string text = path + ": headerless raw, " + toString(layout.type) + ", " +
                           (layout.endian == RawEndian::Little ? "little" : "big") + " endian" +
                           (headerless->headerBytes != 0
                                ? ", after " + std::to_string(headerless->headerBytes) +
                                      " header bytes"
                                : std::string()) +
                           "\n";
        text += describeRaw(
            layout, detail::RawOrder::XFastest,
            [&](const detail::RawDataDecoder& use) {
                detail::withHeaderlessRawData(path, layout, headerless->headerBytes, use);
            },
            bins);
        return text + "  scene         VolumeData { " +
               replacedPath(headerlessFields(*headerless), path) + " }\n";
    }
    switch (detectVolumeFileFormat(path)) {
    case VolumeFileFormat::TexsplatRaw: {
        std::ifstream in = detail::openForReading(path);
        const RawHeader header = RawHeader::parse(in, path);
        std::string text = path + ": texsplat-raw, " + toString(header.type) + ", " +
                           (header.endian == RawEndian::Little ? "little" : "big") +
                           " endian\n";
        text += describeRaw(
            header, detail::RawOrder::XFastest,
            [&](const detail::RawDataDecoder& use) { detail::withRawVolumeData(path, use); },
            bins);
        return text + snippet("FILE_RAW", path);
    }
    case VolumeFileFormat::Npy: {
        std::ifstream in = detail::openForReading(path);
        const NpyHeader header = NpyHeader::parse(in, path);
        std::string text = path + ": NumPy .npy, dtype '" + header.descr + "' (" +
                           toString(header.layout.type) + "), shape " + header.shapeText() +
                           ", " + (header.fortranOrder ? "Fortran" : "C") + " order\n";
        text += describeRaw(
            header.layout,
            header.fortranOrder ? detail::RawOrder::ZFastest : detail::RawOrder::XFastest,
            [&](const detail::RawDataDecoder& use) { detail::withNpyData(path, use); }, bins);
        return text + snippet("FILE_NPY", path);
    }
    case VolumeFileFormat::Nrrd: {
        std::ifstream in = detail::openForReading(path);
        const NrrdHeader header = NrrdHeader::parse(in, path);
        std::string text = path + ": NRRD, type '" + header.typeName + "' (" +
                           toString(header.layout.type) + "), sizes " + header.sizesText() +
                           ", " + header.encodingName() + " encoding, " +
                           (header.layout.endian == RawEndian::Little ? "little" : "big") +
                           " endian" +
                           (header.dataFile.empty() ? std::string()
                                                    : ", data file '" + header.dataFile + "'") +
                           "\n";
        text += describeRaw(
            header.layout, detail::RawOrder::XFastest,
            [&](const detail::RawDataDecoder& use) { detail::withNrrdData(path, use, roots); },
            bins);
        return text + snippet("FILE_NRRD", path);
    }
    case VolumeFileFormat::NetCdf: {
        // One reader for every variable: a file of 10 000 variables was opened (and its variables
        // listed) once per variable.
        const NetCdfReader reader(path);
        const std::vector<NetCdfVariableInfo>& variables = reader.variables();
        std::string text = path + ": NetCDF, " + std::to_string(variables.size()) +
                           (variables.size() == 1 ? " variable\n" : " variables\n");
        const auto volumes = std::count_if(variables.begin(), variables.end(),
                                           [](const auto& info) { return info.isVolume(); });
        for (const NetCdfVariableInfo& info : variables) {
            text += "variable " + info.declaration() + "\n";
            if (info.isCoordinate) {
                text += "  coordinate of dimension '" + info.name + "'\n";
                continue;
            }
            if (!info.isVolume()) {
                text += "  not readable: texsplat reads 3-D (z, y, x) and 4-D (time, z, y, x) "
                        "variables of numbers\n";
                continue;
            }
            if (info.dimensions.size() == 4)
                text += "  time steps    " + std::to_string(info.dimensions[0].length) +
                        " along '" + info.dimensions[0].name +
                        "' (VolumeData timeStep 0 to " +
                        std::to_string(info.dimensions[0].length - 1) + "; step 0 below)\n";
            const GridGeometry geometry = reader.geometry(info.name).first;
            const ValuePass pass = [&](const VoxelChunk& chunk) {
                reader.forEachSlice(info.name, 0,
                                    [&](std::int64_t, const std::vector<float>& values) {
                                        chunk(values.data(),
                                              static_cast<std::int64_t>(values.size()));
                                    });
            };
            text += describeGrid(geometry, 1, summarize(pass, 1, bins));
            text += snippet("FILE_NETCDF", path, volumes == 1 ? std::string() : info.name);
        }
        return text + netCdfVectors(variables, path);
    }
    case VolumeFileFormat::Vdb: {
        const std::vector<VdbGridInfo> grids = listVdbGrids(path);
        std::string text = path + ": OpenVDB, " + std::to_string(grids.size()) +
                           (grids.size() == 1 ? " grid\n" : " grids\n");
        for (const VdbGridInfo& info : grids) {
            text += "grid '" + info.name + "' (" + info.valueType + ")\n";
            if (info.valueType != "float" && info.valueType != "vec3s") {
                text += "  not readable: texsplat reads float and vec3s grids\n";
                continue;
            }
            text += describe(readVdbGrid(path, info.name), bins);
            text += snippet("FILE_VDB", path, grids.size() == 1 ? std::string() : info.name);
        }
        return text;
    }
    case VolumeFileFormat::Unknown: break;
    }
    throw IoError(path + ": not a data file texsplat reads whole; expected texsplat-raw, NumPy "
                         ".npy, NRRD, NetCDF or OpenVDB .vdb");
}

std::string quickLookScene(const std::string& path,
                           const std::optional<HeaderlessRawLayout>& headerless) {
    std::string fields;
    std::string note;
    const std::string quoted = "\"" + path + "\"";
    if (headerless) {
        fields = replacedPath(headerlessFields(*headerless), path);
    } else {
        switch (detectVolumeFileFormat(path)) {
        case VolumeFileFormat::TexsplatRaw:
            fields = "source FILE_RAW fileName " + quoted;
            break;
        case VolumeFileFormat::Npy:
            fields = "source FILE_NPY fileName " + quoted;
            break;
        case VolumeFileFormat::Nrrd:
            fields = "source FILE_NRRD fileName " + quoted;
            break;
        case VolumeFileFormat::NetCdf: {
            const std::vector<NetCdfVariableInfo> variables = NetCdfReader(path).variables();
            const auto first = std::find_if(variables.begin(), variables.end(),
                                            [](const auto& info) { return info.isVolume(); });
            if (first == variables.end())
                throw DataError(path + ": no 3-D or 4-D variable to draw; the file has " +
                                std::to_string(variables.size()) + " variables");
            fields = "source FILE_NETCDF fileName " + quoted + " gridName \"" + first->name +
                     "\"";
            note = "# the file's first 3-D or 4-D variable; `texsplat info " + path +
                   "` lists the others\n";
            break;
        }
        case VolumeFileFormat::Vdb: {
            const std::vector<VdbGridInfo> grids = listVdbGrids(path);
            const auto first = std::find_if(grids.begin(), grids.end(), [](const auto& info) {
                return info.valueType == "float" || info.valueType == "vec3s";
            });
            if (first == grids.end())
                throw DataError(path + ": no float or vec3s grid to draw; the file has " +
                                std::to_string(grids.size()) + " grids");
            fields = "source FILE_VDB fileName " + quoted + " gridName \"" + first->name + "\"";
            note = "# the file's first float or vec3s grid; `texsplat info " + path +
                   "` lists the others\n";
            break;
        }
        case VolumeFileFormat::Unknown:
            throw IoError(path + ": not a data file texsplat reads whole; expected texsplat-raw, "
                                 "NumPy .npy, NRRD, NetCDF or OpenVDB .vdb");
        }
    }
    return "#Inventor V2.1 ascii\n"
           "# A first look at " + path + ": `texsplat info " + path +
           " --scene` prints this scene\n"
           "# and `texsplat render " + path + " -o look.png` draws it. Save it to edit it:\n"
           "#   texsplat info " + path +
           " --scene > look.iv && texsplat render look.iv -o look.png\n"
           "Separator {\n" + note +
           "    VolumeData { " + fields + " }\n"
           "    # The 1st to 99th percentile of the values, opacity rising with them, per voxel.\n"
           "    TransferFunction {\n"
           "        preset        VIRIDIS\n"
           "        rangeMode     PERCENTILE\n"
           "        opacityValues [ 0, 1 ]\n"
           "        opacities     [ 0, 0.2 ]\n"
           "        unitDistance  0\n"
           "    }\n"
           "    TextureSplat { }\n"
           "}\n";
}

} // namespace texsplat::volume
