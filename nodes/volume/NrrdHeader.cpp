#include "nodes/volume/NrrdHeader.h"

#include "nodes/volume/GridGeometry.h"
#include "nodes/volume/detail/Format.h"
#include "nodes/volume/detail/NrrdHeaderText.h"
#include "nodes/volume/detail/Printable.h"
#include "scenegraph/Error.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <string_view>

namespace texsplat::volume {
namespace {

using detail::formatNumber;
using detail::NrrdLineReader;
using detail::NrrdPlace;
using detail::NrrdValueScanner;
using detail::printable;

constexpr int kMaxDimension = 4;
constexpr int kSpaceDimension = 3;

struct NamedType {
    const char* name;
    RawValueType type;
};

// teem's spellings of the types we read (nrrdType airEnum).
constexpr NamedType kTypes[] = {
    {"signed char", RawValueType::Int8},        {"int8", RawValueType::Int8},
    {"int8_t", RawValueType::Int8},             {"uchar", RawValueType::UInt8},
    {"unsigned char", RawValueType::UInt8},     {"uint8", RawValueType::UInt8},
    {"uint8_t", RawValueType::UInt8},           {"short", RawValueType::Int16},
    {"short int", RawValueType::Int16},         {"signed short", RawValueType::Int16},
    {"signed short int", RawValueType::Int16},  {"int16", RawValueType::Int16},
    {"int16_t", RawValueType::Int16},           {"ushort", RawValueType::UInt16},
    {"unsigned short", RawValueType::UInt16},   {"unsigned short int", RawValueType::UInt16},
    {"uint16", RawValueType::UInt16},           {"uint16_t", RawValueType::UInt16},
    {"int", RawValueType::Int32},               {"signed int", RawValueType::Int32},
    {"int32", RawValueType::Int32},             {"int32_t", RawValueType::Int32},
    {"uint", RawValueType::UInt32},             {"unsigned int", RawValueType::UInt32},
    {"uint32", RawValueType::UInt32},           {"uint32_t", RawValueType::UInt32},
    {"float", RawValueType::Float32},           {"double", RawValueType::Float64}};

constexpr const char* kUnsupportedTypes[] = {
    "longlong", "long long", "long long int", "signed long long", "signed long long int",
    "int64", "int64_t", "ulonglong", "unsigned long long", "unsigned long long int", "uint64",
    "uint64_t", "block"};

constexpr const char* kIgnoredFields[] = {
    "content", "number", "kinds", "centers", "centerings", "labels", "units", "thicknesses",
    "axis mins", "axismins", "axis maxs", "axismaxs", "min", "max", "old min", "oldmin",
    "old max", "oldmax", "measurement frame", "space units", "sample units", "sampleunits"};

// Old spellings of fields, by their current names.
const std::map<std::string, std::string> kFieldAliases{
    {"byteskip", "byte skip"}, {"lineskip", "line skip"}, {"datafile", "data file"}};

// Named spaces and their dimension (nrrdSpace airEnum).
const std::map<std::string, int> kSpaces{
    {"right-anterior-superior", 3}, {"ras", 3}, {"left-anterior-superior", 3}, {"las", 3},
    {"left-posterior-superior", 3}, {"lps", 3}, {"scanner-xyz", 3}, {"3d-right-handed", 3},
    {"3d-left-handed", 3}, {"right-anterior-superior-time", 4}, {"rast", 4},
    {"left-anterior-superior-time", 4}, {"last", 4}, {"left-posterior-superior-time", 4},
    {"lpst", 4}, {"scanner-xyz-time", 4}, {"3d-right-handed-time", 4},
    {"3d-left-handed-time", 4}};

std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

// "(0.6,0.8,0)": a direction as a message quotes it.
std::string vectorText(const std::vector<double>& values) {
    std::string text = "(";
    for (std::size_t i = 0; i < values.size(); ++i)
        text += (i == 0 ? "" : ",") + formatNumber(values[i]);
    return text + ")";
}

// The fields read so far, before they are checked against each other.
struct Fields {
    std::map<std::string, NrrdPlace> seen;
    int dimension = 0;
    std::optional<std::vector<double>> spacings;
    std::vector<std::optional<std::vector<double>>> directions;
    std::optional<std::vector<double>> origin;
    int spaceDimension = 0;
    bool hasEndian = false;
};

void readMagic(std::istream& in, const std::string& source, NrrdLineReader& reader) {
    char start[8] = {};
    in.read(start, sizeof start);
    const std::string_view magic(start, static_cast<std::size_t>(in.gcount()));
    reader.countMagic(in.gcount());
    if (magic.size() < 8 || magic.substr(0, 4) != "NRRD")
        throw ParseError(source + ": not a NRRD file: expected it to start with 'NRRD0001' to "
                                  "'NRRD0005'");
    if (magic.substr(4, 3) != "000" || magic[7] < '1' || magic[7] > '5')
        throw ParseError(source + ": unsupported NRRD version '" + printable(magic) +
                         "'; this reader reads NRRD0001 to NRRD0005");
    std::string rest;
    reader.next(rest);
    if (!rest.empty())
        throw ParseError(reader.where({1, 9}) + "expected the end of the line after '" +
                         std::string(magic) + "', found '" + printable(rest) + "'");
}

RawValueType parseType(const std::string& name, const NrrdLineReader& reader, NrrdPlace at) {
    const std::string key = lowercase(name);
    for (const NamedType& known : kTypes)
        if (key == known.name)
            return known.type;
    const std::string expected = "; texsplat reads int8, uint8, int16, uint16, int32, uint32, "
                                 "float and double";
    for (const char* unsupported : kUnsupportedTypes)
        if (key == unsupported)
            throw DataError(reader.where(at) + "type '" + printable(name) + "' is not supported" +
                            expected);
    throw ParseError(reader.where(at) + "unknown type '" + printable(name) + "'" + expected);
}

NrrdEncoding parseEncoding(const std::string& name, const NrrdLineReader& reader, NrrdPlace at) {
    const std::string key = lowercase(name);
    if (key == "raw")
        return NrrdEncoding::Raw;
    if (key == "gzip" || key == "gz")
        return NrrdEncoding::Gzip;
    const std::string expected = "; texsplat reads raw and gzip (convert with: unu save -f nrrd "
                                 "-e gzip -i IN -o OUT.nrrd)";
    for (const char* other : {"ascii", "text", "txt", "hex", "bzip2", "bz2", "zrl"})
        if (key == other)
            throw DataError(reader.where(at) + "encoding '" + printable(name) +
                            "' is not supported" + expected);
    throw ParseError(reader.where(at) + "unknown encoding '" + printable(name) + "'" + expected);
}

// Reads the value of one field into `header` and `fields`.
void readField(const std::string& field, NrrdValueScanner& value, const NrrdLineReader& reader,
               NrrdHeader& header, Fields& fields) {
    const NrrdPlace at = value.place();
    const auto requireDimension = [&] {
        if (fields.dimension == 0)
            value.fail(at, "'" + field + "' comes before 'dimension'");
    };
    const auto perAxis = [&](auto read) {
        requireDimension();
        for (int axis = 0; axis < fields.dimension; ++axis) {
            if (value.atEnd())
                value.fail(value.place(), "'" + field + "' needs " +
                                              std::to_string(fields.dimension) +
                                              " values (one per axis), found " +
                                              std::to_string(axis));
            read();
        }
    };
    if (field == "dimension") {
        fields.dimension = value.number<int>(field, "a whole number");
        if (fields.dimension < 1 || fields.dimension > kMaxDimension)
            throw DataError(reader.where(at) + "dimension " + std::to_string(fields.dimension) +
                            " is not supported; texsplat reads 1- to 3-D scalars and 4-D "
                            "arrays of 3-vectors (sizes 3 X Y Z)");
    } else if (field == "type") {
        header.typeName = value.words(); // "unsigned short int" is one type
        header.layout.type = parseType(header.typeName, reader, at);
    } else if (field == "sizes") {
        perAxis([&] { header.sizes.push_back(value.number<std::int64_t>(field, "a size")); });
    } else if (field == "endian") {
        const std::string name = lowercase(value.word());
        if (name != "little" && name != "big")
            value.fail(at, "unknown endian '" + printable(name) + "'; expected little or big");
        header.layout.endian = name == "little" ? RawEndian::Little : RawEndian::Big;
        fields.hasEndian = true;
    } else if (field == "encoding") {
        header.encoding = parseEncoding(value.word(), reader, at);
    } else if (field == "spacings") {
        fields.spacings.emplace();
        perAxis([&] { fields.spacings->push_back(value.number<double>(field, "a number")); });
    } else if (field == "space directions") {
        perAxis([&] { fields.directions.push_back(value.vector(field)); });
    } else if (field == "space origin") {
        fields.origin = value.vector(field);
        if (!fields.origin)
            value.fail(at, "'space origin' must be a vector '(x,y,z)'");
    } else if (field == "space") {
        const std::string name = value.word();
        const auto known = kSpaces.find(lowercase(name));
        if (known == kSpaces.end())
            value.fail(at, "unknown space '" + printable(name) + "'");
        fields.spaceDimension = known->second;
    } else if (field == "space dimension") {
        fields.spaceDimension = value.number<int>(field, "a whole number");
        if (fields.spaceDimension < 1)
            value.fail(at, "'space dimension' must be 1 or more, found " +
                               std::to_string(fields.spaceDimension));
    } else if (field == "byte skip") {
        header.byteSkip = value.number<std::int64_t>(field, "a whole number");
        if (header.byteSkip < -1)
            value.fail(at, "'byte skip' must be -1 or more, found " +
                               std::to_string(header.byteSkip));
    } else if (field == "line skip") {
        header.lineSkip = value.number<std::int64_t>(field, "a whole number");
        if (header.lineSkip < 0)
            value.fail(at, "'line skip' must be 0 or more, found " +
                               std::to_string(header.lineSkip));
    } else if (field == "data file") {
        const std::string name = value.words();
        if (name.empty())
            value.fail(at, "'data file' names no file");
        if (!detail::isText(name)) // it is printed in messages and by `texsplat info`
            value.fail(at, "'data file' is not printable text: '" + printable(name) + "'");
        if (name.rfind("LIST", 0) == 0 ||
            (name.find('%') != std::string::npos && name.find(' ') != std::string::npos))
            throw DataError(reader.where(at) + "several data files are not supported; join "
                                               "them into one (unu join)");
        header.dataFile = name;
    } else {
        value.fail({at.line, 1}, "unknown field '" + printable(field) + "'");
    }
    if (!value.atEnd())
        value.fail(value.place(), "unexpected '" + printable(value.word()) + "' after the " +
                                      "value of '" + field + "'");
}

// "axis 2" in messages counts from 0, as teem does.
std::string axisName(int axis) { return "axis " + std::to_string(axis); }

// Spacing and origin from `spacings` or `space directions` and `space origin`.
void readGeometry(const Fields& fields, const NrrdLineReader& reader, int firstSpatialAxis,
                  NrrdHeader& header) {
    const auto placeOf = [&](const char* field) { return reader.where(fields.seen.at(field)); };
    const bool hasDirections = fields.seen.count("space directions") != 0;
    if (fields.spacings && hasDirections)
        throw ParseError(placeOf("spacings") + "a header gives either 'spacings' or 'space "
                                               "directions', not both");
    const int spaceDimension = fields.spaceDimension != 0 ? fields.spaceDimension : kSpaceDimension;
    if ((hasDirections || fields.origin) && spaceDimension != kSpaceDimension)
        throw DataError(placeOf(fields.seen.count("space") ? "space" : "space dimension") +
                        "space dimension " + std::to_string(spaceDimension) +
                        " is not supported; expected 3");
    const int spatialAxes = fields.dimension - firstSpatialAxis;
    std::array<bool, kSpaceDimension> used{};
    for (int axis = 0; axis < fields.dimension; ++axis) {
        const bool spatial = axis >= firstSpatialAxis;
        const int fileAxis = axis - firstSpatialAxis;
        if (fields.spacings) {
            const double spacing = (*fields.spacings)[static_cast<std::size_t>(axis)];
            if (!spatial)
                continue; // teem writes nan for the vector axis
            if (!(std::isfinite(spacing) && spacing > 0.0))
                throw DataError(placeOf("spacings") + "the spacing of " + axisName(axis) +
                                " must be a finite number above 0, found " +
                                formatNumber(spacing));
            header.layout.spacing[fileAxis] = spacing;
        }
        if (hasDirections) {
            const auto& direction = fields.directions[static_cast<std::size_t>(axis)];
            if (!spatial) {
                if (direction)
                    throw DataError(placeOf("space directions") + axisName(axis) +
                                    " holds the 3 vector components; its direction must be "
                                    "'none', found " + vectorText(*direction));
                continue;
            }
            if (!direction)
                throw DataError(placeOf("space directions") + "the direction of " +
                                axisName(axis) + " is 'none'; a spatial axis needs a vector");
            if (direction->size() != kSpaceDimension)
                throw ParseError(placeOf("space directions") + "the direction of " +
                                 axisName(axis) + " has " + std::to_string(direction->size()) +
                                 " components; the space has 3");
            const auto along = std::count_if(direction->begin(), direction->end(),
                                             [](double component) { return component != 0.0; });
            const auto world = static_cast<int>(
                std::find_if(direction->begin(), direction->end(),
                             [](double component) { return component != 0.0; }) -
                direction->begin());
            if (along != 1 || !std::isfinite((*direction)[std::size_t(world)]))
                throw DataError(placeOf("space directions") + "the direction of " +
                                axisName(axis) + " is " + vectorText(*direction) +
                                ", not along one world axis; oblique or rotated grids are not "
                                "supported (resample the volume onto an axis-aligned grid)");
            if (used[std::size_t(world)])
                throw DataError(placeOf("space directions") + "two axes lie along world axis " +
                                "xyz"[world] + " (the direction of " + axisName(axis) + " is " +
                                vectorText(*direction) + ")");
            used[std::size_t(world)] = true;
            const double length = (*direction)[std::size_t(world)];
            header.gridAxis[fileAxis] = world;
            header.reversed[fileAxis] = length < 0.0;
            header.layout.spacing[world] = std::abs(length);
        }
    }
    // The file's missing axes (of a 1-D or 2-D array) take the grid axes left, in order.
    for (int fileAxis = spatialAxes, world = 0; hasDirections && fileAxis < kSpaceDimension;
         ++fileAxis) {
        while (used[std::size_t(world)])
            ++world;
        header.gridAxis[fileAxis] = world;
        used[std::size_t(world)] = true;
    }
    if (fields.origin) {
        if (fields.origin->size() != kSpaceDimension)
            throw ParseError(placeOf("space origin") + "'space origin' has " +
                             std::to_string(fields.origin->size()) +
                             " components; the space has 3");
        for (int world = 0; world < kSpaceDimension; ++world)
            header.layout.origin[world] = (*fields.origin)[static_cast<std::size_t>(world)];
    }
    // `space origin` is the file's first sample; a reversed axis starts the grid at its last.
    for (int fileAxis = 0; fileAxis < spatialAxes; ++fileAxis)
        if (header.reversed[fileAxis]) {
            const int world = header.gridAxis[fileAxis];
            const auto last = header.sizes[std::size_t(firstSpatialAxis + fileAxis)] - 1;
            header.layout.origin[world] -= double(last) * header.layout.spacing[world];
        }
}

// Checks the fields against each other and completes the layout.
void finish(const Fields& fields, const NrrdLineReader& reader, NrrdHeader& header) {
    for (const char* required : {"dimension", "type", "sizes", "encoding"})
        if (fields.seen.count(required) == 0)
            throw ParseError(reader.where({reader.line(), 1}) + "the header has no '" +
                             required + "' field");
    const NrrdPlace sizesAt = fields.seen.at("sizes");
    const bool vectors = fields.dimension == kMaxDimension;
    if (vectors && header.sizes[0] != 3)
        throw DataError(reader.where(sizesAt) + "a 4-D array must hold 3-vectors along its "
                                                "first axis (sizes 3 X Y Z), found sizes " +
                        header.sizesText());
    const int firstSpatialAxis = vectors ? 1 : 0;
    header.layout.components = vectors ? 3 : 1;
    if (!fields.hasEndian && header.layout.bytesPerValue() > 1)
        throw ParseError(reader.where(fields.seen.at("type")) + "type '" +
                         printable(header.typeName) +
                         "' has several bytes, but the header has no 'endian' field");
    if (header.byteSkip == -1 && header.encoding != NrrdEncoding::Raw)
        throw DataError(reader.where(fields.seen.at("byte skip")) +
                        "'byte skip: -1' works with raw encoding only");
    readGeometry(fields, reader, firstSpatialAxis, header);
    glm::i64vec3 dims(1);
    for (int axis = firstSpatialAxis; axis < fields.dimension; ++axis)
        dims[header.gridAxis[axis - firstSpatialAxis]] =
            header.sizes[static_cast<std::size_t>(axis)];
    try {
        static_cast<void>(GridGeometry(dims, header.layout.origin, header.layout.spacing));
        header.layout.dims = dims;
        static_cast<void>(header.layout.dataBytes());
    } catch (const DataError& error) {
        throw DataError(reader.where(sizesAt) + error.what());
    }
}

} // namespace

const char* NrrdHeader::encodingName() const {
    return encoding == NrrdEncoding::Raw ? "raw" : "gzip";
}

std::string NrrdHeader::sizesText() const {
    std::string text;
    for (const std::int64_t size : sizes)
        text += (text.empty() ? "" : " ") + std::to_string(size);
    return text;
}

NrrdHeader NrrdHeader::parse(std::istream& in, const std::string& source) {
    NrrdLineReader reader(in, source);
    readMagic(in, source, reader);
    NrrdHeader header;
    Fields fields;
    std::string line;
    bool blankLine = false;
    while (reader.next(line)) {
        if (line.empty()) {
            blankLine = true;
            break;
        }
        if (line[0] == '#')
            continue;
        const std::size_t separator = line.find(": ");
        const std::size_t keyValue = line.find(":=");
        if (keyValue != std::string::npos && keyValue < separator)
            continue; // key/value pairs describe, they do not lay out the data
        if (separator == std::string::npos)
            throw ParseError(reader.where({reader.line(), 1}) +
                             "expected 'field: value' or 'key:=value', found '" +
                             printable(line) + "'");
        std::string field = lowercase(line.substr(0, separator));
        const auto alias = kFieldAliases.find(field);
        if (alias != kFieldAliases.end())
            field = alias->second;
        const NrrdPlace at{reader.line(), 1};
        if (std::find(std::begin(kIgnoredFields), std::end(kIgnoredFields), field) !=
            std::end(kIgnoredFields))
            continue;
        const auto [previous, isNew] = fields.seen.emplace(field, at);
        if (!isNew)
            throw ParseError(reader.where(at) + "duplicate field '" + printable(field) +
                             "' (first given on line " + std::to_string(previous->second.line) +
                             ")");
        NrrdValueScanner value(std::string_view(line).substr(separator + 2),
                           static_cast<int>(separator) + 3, reader, reader.line());
        readField(field, value, reader, header, fields);
    }
    if (!blankLine && header.dataFile.empty())
        throw ParseError(reader.where({reader.line() + 1, 1}) +
                         "the header ends without the blank line before its data and names "
                         "no 'data file'");
    finish(fields, reader, header);
    header.dataOffset = reader.consumed();
    return header;
}

} // namespace texsplat::volume
