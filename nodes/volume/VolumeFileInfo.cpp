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
#include "nodes/volume/detail/SourceSupport.h"
#include "scenegraph/Error.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
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

template <typename T>
std::string describeGrid(const Grid<T>& grid, int bins) {
    const GridGeometry& geometry = grid.geometry();
    const GridStatistics statistics = grid.statistics();
    const glm::i64vec3 dims = geometry.dims();
    std::string text;
    const auto row = [&text](const std::string& key, const std::string& value) {
        text += "  " + padRight(key, 14) + value + "\n";
    };
    row("values", std::is_same_v<T, float> ? "scalar" : "vector (3 components)");
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
    row(std::is_same_v<T, float> ? "value range" : "length range",
        floatNumber(statistics.minimum) + " .. " + floatNumber(statistics.maximum));

    const double low = statistics.minimum;
    const double width = (statistics.maximum - low) / bins;
    std::vector<std::uint64_t> counts(static_cast<std::size_t>(bins), 0);
    if (width > 0.0) {
        counts = valueHistogram(grid, low, statistics.maximum, static_cast<std::size_t>(bins));
    } else {
        counts[0] = static_cast<std::uint64_t>(statistics.finiteCount);
    }
    const std::uint64_t most = *std::max_element(counts.begin(), counts.end());
    text += "  histogram (" + std::to_string(bins) + " bins)\n";
    for (int bin = 0; bin < bins; ++bin) {
        const std::uint64_t count = counts[static_cast<std::size_t>(bin)];
        const auto bar = static_cast<int>((count * kBarWidth + most - 1) / most);
        text += "    " + padLeft(number(low + bin * width), 12) + " .. " +
                padRight(number(low + (bin + 1) * width), 12) + " " +
                padLeft(std::to_string(count), 10) +
                (bar > 0 ? " " + std::string(static_cast<std::size_t>(bar), '#') : std::string()) +
                "\n";
    }
    return text;
}

std::string describe(const AnyGrid& grid, int bins) {
    return std::visit([bins](const auto& g) { return describeGrid(*g, bins); }, grid);
}

std::string snippet(const std::string& source, const std::string& path,
                    const std::string& gridName = {}) {
    return "  scene         VolumeData { source " + source + " fileName \"" + path + "\"" +
           (gridName.empty() ? std::string() : " gridName \"" + gridName + "\"") + " }\n";
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

std::string describeVolumeFile(const std::string& path, int histogramBins) {
    histogramBins = std::max(1, histogramBins);
    switch (detectVolumeFileFormat(path)) {
    case VolumeFileFormat::TexsplatRaw: {
        std::ifstream in = detail::openForReading(path);
        const RawHeader header = RawHeader::parse(in, path);
        std::string text = path + ": texsplat-raw, " + toString(header.type) + ", " +
                           (header.endian == RawEndian::Little ? "little" : "big") +
                           " endian\n";
        text += describe(readRawVolume(path), histogramBins);
        return text + snippet("FILE_RAW", path);
    }
    case VolumeFileFormat::Npy: {
        std::ifstream in = detail::openForReading(path);
        const NpyHeader header = NpyHeader::parse(in, path);
        std::string text = path + ": NumPy .npy, dtype '" + header.descr + "' (" +
                           toString(header.layout.type) + "), shape " + header.shapeText() +
                           ", " + (header.fortranOrder ? "Fortran" : "C") + " order\n";
        text += describe(readNpyVolume(path), histogramBins);
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
        text += describe(readNrrdVolume(path), histogramBins);
        return text + snippet("FILE_NRRD", path);
    }
    case VolumeFileFormat::NetCdf: {
        const std::vector<NetCdfVariableInfo> variables = listNetCdfVariables(path);
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
            text += describe(readNetCdfVariable(path, info.name), histogramBins);
            text += snippet("FILE_NETCDF", path, volumes == 1 ? std::string() : info.name);
        }
        return text;
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
            text += describe(readVdbGrid(path, info.name), histogramBins);
            text += snippet("FILE_VDB", path, grids.size() == 1 ? std::string() : info.name);
        }
        return text;
    }
    case VolumeFileFormat::Unknown: break;
    }
    throw IoError(path + ": not a data file texsplat reads whole; expected texsplat-raw, NumPy "
                         ".npy, NRRD, NetCDF or OpenVDB .vdb");
}

} // namespace texsplat::volume
