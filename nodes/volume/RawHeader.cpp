#include "nodes/volume/RawHeader.h"

#include "nodes/volume/GridGeometry.h"
#include "nodes/volume/detail/Printable.h"
#include "scenegraph/Error.h"

#include <charconv>
#include <limits>
#include <map>
#include <sstream>
#include <string_view>
#include <vector>

namespace texsplat::volume {
namespace {

using detail::isText;
using detail::printable;

constexpr std::string_view kMagic = "texsplat-raw";
constexpr std::size_t kMaxLineLength = 1024;

struct Token {
    std::string text;
    int column; // 1-based
};

// One header line split at blanks, each word remembering where it started for messages.
struct Line {
    int number = 0;
    std::vector<Token> tokens;
};

class HeaderReader {
public:
    HeaderReader(std::istream& in, const std::string& source) : mIn(in), mSource(source) {}

    // False at end of input. Throws on over-long lines (binary data read as text).
    bool next(Line& line) {
        std::string text;
        char c = 0;
        bool any = false;
        while (mIn.get(c)) {
            any = true;
            if (c == '\n')
                break;
            if (text.size() == kMaxLineLength)
                throw ParseError(where(mLineNumber + 1, 1) + "header line longer than " +
                                 std::to_string(kMaxLineLength) +
                                 " characters; is this a texsplat-raw file?");
            text += c;
        }
        if (!any)
            return false;
        if (!text.empty() && text.back() == '\r')
            text.pop_back();
        line.number = ++mLineNumber;
        line.tokens.clear();
        std::size_t position = 0;
        while (position < text.size()) {
            const std::size_t start = text.find_first_not_of(" \t", position);
            if (start == std::string::npos)
                break;
            const std::size_t end = std::min(text.find_first_of(" \t", start), text.size());
            line.tokens.push_back({text.substr(start, end - start), static_cast<int>(start) + 1});
            position = end;
        }
        return true;
    }

    std::string where(int line, int column) const {
        return mSource + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
    }
    int lineNumber() const { return mLineNumber; }

private:
    std::istream& mIn;
    const std::string& mSource;
    int mLineNumber = 0;
};

void expectValueCount(const HeaderReader& reader, const Line& line, std::size_t count) {
    const std::size_t found = line.tokens.size() - 1;
    if (found == count)
        return;
    const int column = found > count ? line.tokens[count + 1].column : line.tokens[0].column;
    throw ParseError(reader.where(line.number, column) + "'" + printable(line.tokens[0].text) +
                     "' takes " +
                     std::to_string(count) + " value" + (count == 1 ? "" : "s") + ", found " +
                     std::to_string(found));
}

template <typename Number>
Number parseNumber(const HeaderReader& reader, const Line& line, std::size_t index,
                   const char* kind) {
    const Token& token = line.tokens[index];
    Number value{};
    const char* first = token.text.data();
    const char* last = first + token.text.size();
    const auto [end, error] = std::from_chars(first, last, value);
    if (error != std::errc() || end != last)
        throw ParseError(reader.where(line.number, token.column) + "expected " + kind + " for '" +
                         printable(line.tokens[0].text) + "', found '" + printable(token.text) +
                         "'");
    return value;
}

// The geometry checks live in GridGeometry; here they only gain the header's location.
void checkGeometry(const HeaderReader& reader, const Line& line, const glm::i64vec3& dims,
                   const glm::dvec3& origin, const glm::dvec3& spacing) {
    try {
        static_cast<void>(GridGeometry(dims, origin, spacing));
    } catch (const DataError& error) {
        throw DataError(reader.where(line.number, line.tokens[1].column) + error.what());
    }
}

RawValueType parseType(const HeaderReader& reader, const Line& line) {
    const std::string& name = line.tokens[1].text;
    for (RawValueType type : {RawValueType::UInt8, RawValueType::Int8, RawValueType::UInt16,
                              RawValueType::Int16, RawValueType::UInt32, RawValueType::Int32,
                              RawValueType::Float32, RawValueType::Float64})
        if (name == toString(type))
            return type;
    throw ParseError(reader.where(line.number, line.tokens[1].column) + "unknown type '" +
                     printable(name) +
                     "'; expected uint8, int8, uint16, int16, uint32, int32, float32 or float64");
}

} // namespace

const char* toString(RawValueType type) {
    switch (type) {
    case RawValueType::Float32: return "float32";
    case RawValueType::Float64: return "float64";
    case RawValueType::UInt8: return "uint8";
    case RawValueType::UInt16: return "uint16";
    case RawValueType::Int8: return "int8";
    case RawValueType::Int16: return "int16";
    case RawValueType::UInt32: return "uint32";
    case RawValueType::Int32: return "int32";
    }
    return "unknown";
}

int bytesPerValue(RawValueType type) {
    switch (type) {
    case RawValueType::UInt8:
    case RawValueType::Int8: return 1;
    case RawValueType::UInt16:
    case RawValueType::Int16: return 2;
    case RawValueType::Float32:
    case RawValueType::UInt32:
    case RawValueType::Int32: return 4;
    case RawValueType::Float64: return 8;
    }
    return 0;
}

int RawHeader::bytesPerValue() const { return volume::bytesPerValue(type); }

std::int64_t RawHeader::dataBytes() const {
    const std::int64_t valueBytes = std::int64_t{bytesPerValue()} * components;
    const std::int64_t voxels = GridGeometry(dims).voxelCount();
    if (voxels > std::numeric_limits<std::int64_t>::max() / valueBytes)
        throw DataError("grid of " + std::to_string(voxels) + " voxels of " +
                        std::to_string(valueBytes) + " bytes each exceeds 2^63 bytes");
    return voxels * valueBytes;
}

RawHeader RawHeader::parse(std::istream& in, const std::string& source) {
    HeaderReader reader(in, source);
    Line line;
    const bool hasFirstLine = reader.next(line);
    if (!hasFirstLine || line.tokens.size() != 2 || line.tokens[0].text != kMagic) {
        const std::string found = line.tokens.empty() ? "" : line.tokens[0].text;
        std::string what = "expected 'texsplat-raw 1' on the first line";
        if (hasFirstLine && !found.empty())
            what += isText(found) ? ", found '" + printable(found) + "'"
                                  : std::string(", found binary data (a headerless raw file? "
                                                "give its layout: texsplat info FILE --dims "
                                                "X,Y,Z --type TYPE, or in a scene VolumeData "
                                                "source FILE_RAW_HEADERLESS)");
        throw ParseError(reader.where(1, 1) + what);
    }
    if (line.tokens[1].text != "1")
        throw ParseError(reader.where(1, line.tokens[1].column) +
                         "unsupported texsplat-raw version '" + printable(line.tokens[1].text) +
                         "'; this reader reads version 1");

    RawHeader header;
    std::map<std::string, int> seen; // key -> line it was given on
    while (reader.next(line)) {
        if (line.tokens.empty() || line.tokens[0].text[0] == '#')
            continue;
        const std::string& key = line.tokens[0].text;
        const auto [previous, isNew] = seen.emplace(key, line.number);
        if (!isNew)
            throw ParseError(reader.where(line.number, 1) + "duplicate header key '" +
                             printable(key) +
                             "' (first given on line " + std::to_string(previous->second) + ")");
        if (key == "dims") {
            expectValueCount(reader, line, 3);
            for (int axis = 0; axis < 3; ++axis)
                header.dims[axis] = parseNumber<std::int64_t>(reader, line, axis + 1, "an integer");
            checkGeometry(reader, line, header.dims, glm::dvec3(0.0), glm::dvec3(1.0));
        } else if (key == "type") {
            expectValueCount(reader, line, 1);
            header.type = parseType(reader, line);
        } else if (key == "components") {
            expectValueCount(reader, line, 1);
            header.components = parseNumber<int>(reader, line, 1, "an integer");
            if (header.components != 1 && header.components != 3)
                throw ParseError(reader.where(line.number, line.tokens[1].column) +
                                 "components must be 1 or 3, found " +
                                 printable(line.tokens[1].text));
        } else if (key == "spacing" || key == "origin") {
            expectValueCount(reader, line, 3);
            glm::dvec3& target = key == "spacing" ? header.spacing : header.origin;
            for (int axis = 0; axis < 3; ++axis)
                target[axis] = parseNumber<double>(reader, line, axis + 1, "a number");
            checkGeometry(reader, line, glm::i64vec3(1), header.origin, header.spacing);
        } else if (key == "endian") {
            expectValueCount(reader, line, 1);
            const std::string& name = line.tokens[1].text;
            if (name != "little" && name != "big")
                throw ParseError(reader.where(line.number, line.tokens[1].column) +
                                 "unknown endian '" + printable(name) +
                                 "'; expected little or big");
            header.endian = name == "little" ? RawEndian::Little : RawEndian::Big;
        } else if (key == "data") {
            expectValueCount(reader, line, 0);
            for (const char* required : {"dims", "type"})
                if (seen.count(required) == 0)
                    throw ParseError(reader.where(line.number, 1) + "header has no '" +
                                     required + "' line");
            return header;
        } else {
            throw ParseError(reader.where(line.number, 1) + "unknown header key '" +
                             printable(key) +
                             "'; expected dims, type, components, spacing, origin, endian or data");
        }
    }
    throw ParseError(reader.where(reader.lineNumber() + 1, 1) +
                     "header ended before its 'data' line");
}

std::string RawHeader::format() const {
    std::ostringstream out;
    out.precision(17);
    out << kMagic << " 1\n"
        << "dims " << dims.x << ' ' << dims.y << ' ' << dims.z << '\n'
        << "type " << toString(type) << '\n'
        << "components " << components << '\n'
        << "spacing " << spacing.x << ' ' << spacing.y << ' ' << spacing.z << '\n'
        << "origin " << origin.x << ' ' << origin.y << ' ' << origin.z << '\n'
        << "endian " << (endian == RawEndian::Little ? "little" : "big") << '\n'
        << "data\n";
    return out.str();
}

} // namespace texsplat::volume
