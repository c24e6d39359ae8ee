#include "nodes/volume/RawHeader.h"

#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <utility>

namespace texsplat::volume {
namespace {

RawHeader parse(const std::string& text) {
    std::istringstream in(text);
    return RawHeader::parse(in, "grid.raw");
}

// The message of the ParseError or DataError that parsing `text` throws.
std::string errorOf(const std::string& text) {
    try {
        parse(text);
    } catch (const ParseError& error) {
        return std::string("ParseError: ") + error.what();
    } catch (const DataError& error) {
        return std::string("DataError: ") + error.what();
    }
    return "no error";
}

TEST(RawHeader, parsesEveryKeyAndStopsAfterTheDataLine) {
    std::istringstream in("texsplat-raw 1\n"
                          "# a comment, then a blank line\n"
                          "\n"
                          "dims 4 5 6\r\n"
                          "type uint16\n"
                          "  components   3\n"
                          "spacing 0.5 1 2\n"
                          "origin -1 0 1e3\n"
                          "endian big\n"
                          "data\n"
                          "BINARY");
    const RawHeader header = RawHeader::parse(in, "grid.raw");
    EXPECT_EQ(header.dims, glm::i64vec3(4, 5, 6));
    EXPECT_EQ(header.type, RawValueType::UInt16);
    EXPECT_EQ(header.components, 3);
    EXPECT_EQ(header.spacing, glm::dvec3(0.5, 1.0, 2.0));
    EXPECT_EQ(header.origin, glm::dvec3(-1.0, 0.0, 1000.0));
    EXPECT_EQ(header.endian, RawEndian::Big);
    EXPECT_EQ(header.bytesPerValue(), 2);
    EXPECT_EQ(header.dataBytes(), 4 * 5 * 6 * 3 * 2);
    std::string rest;
    in >> rest;
    EXPECT_EQ(rest, "BINARY");
}

TEST(RawHeader, defaultsAndFormatRoundTrip) {
    const RawHeader minimal = parse("texsplat-raw 1\ndims 2 3 4\ntype float32\ndata\n");
    EXPECT_EQ(minimal.components, 1);
    EXPECT_EQ(minimal.spacing, glm::dvec3(1.0));
    EXPECT_EQ(minimal.origin, glm::dvec3(0.0));
    EXPECT_EQ(minimal.endian, RawEndian::Little);

    RawHeader header;
    header.dims = {7, 1, 3};
    header.type = RawValueType::Float64;
    header.components = 3;
    header.spacing = {0.1, 0.2, 0.30000000000000004};
    header.origin = {-5.5, 1e-300, 3.0};
    header.endian = RawEndian::Big;
    const RawHeader back = parse(header.format());
    EXPECT_EQ(back.dims, header.dims);
    EXPECT_EQ(back.type, header.type);
    EXPECT_EQ(back.components, header.components);
    EXPECT_EQ(back.spacing, header.spacing);
    EXPECT_EQ(back.origin, header.origin);
    EXPECT_EQ(back.endian, header.endian);
}

// A headerless raw file read as texsplat-raw: the message names the format expected and says
// what to do, and never puts the file's bytes on the terminal.
TEST(RawHeader, binaryDataIsNamedNotPrinted) {
    EXPECT_EQ(errorOf(std::string("\x01\x02\xff\xfe\x00\x80 junk\n", 12)),
              "ParseError: grid.raw:1:1: expected 'texsplat-raw 1' on the first line, found "
              "binary data (a headerless raw file? give its layout: texsplat info FILE --dims "
              "X,Y,Z --type TYPE, or in a scene VolumeData source FILE_RAW_HEADERLESS)");
    EXPECT_EQ(errorOf(std::string(2000, '\x07')),
              "ParseError: grid.raw:1:1: header line longer than 1024 characters; is this a "
              "texsplat-raw file?");
    EXPECT_EQ(errorOf("texsplat-raw 1\ndims 4 \x9b\x01 4\n"),
              "ParseError: grid.raw:2:8: expected an integer for 'dims', found '\\x9b\\x01'");
    EXPECT_EQ(errorOf("texsplat-raw \xff\n"), "ParseError: grid.raw:1:14: unsupported "
                                              "texsplat-raw version '\\xff'; this reader reads "
                                              "version 1");
}

TEST(RawHeader, readsEveryValueType) {
    const std::pair<const char*, int> types[] = {{"uint8", 1},  {"int8", 1},  {"uint16", 2},
                                                 {"int16", 2},  {"uint32", 4}, {"int32", 4},
                                                 {"float32", 4}, {"float64", 8}};
    for (const auto& [name, bytes] : types) {
        const RawHeader header =
            parse(std::string("texsplat-raw 1\ndims 2 1 1\ntype ") + name + "\ndata\n");
        EXPECT_STREQ(toString(header.type), name);
        EXPECT_EQ(header.dataBytes(), 2 * bytes) << name;
    }
}

TEST(RawHeader, reportsGrammarErrorsWithLineAndColumn) {
    const std::string start = "texsplat-raw 1\n";
    EXPECT_EQ(errorOf(""), "ParseError: grid.raw:1:1: expected 'texsplat-raw 1' on the first line");
    EXPECT_EQ(errorOf("P6 64 64\n"),
              "ParseError: grid.raw:1:1: expected 'texsplat-raw 1' on the first line, found 'P6'");
    EXPECT_EQ(errorOf("texsplat-raw 2\n"), "ParseError: grid.raw:1:14: unsupported texsplat-raw "
                                            "version '2'; this reader reads version 1");
    EXPECT_EQ(errorOf(start + "dims 4 4\n"),
              "ParseError: grid.raw:2:1: 'dims' takes 3 values, found 2");
    EXPECT_EQ(errorOf(start + "dims 4 4 4 4\n"),
              "ParseError: grid.raw:2:12: 'dims' takes 3 values, found 4");
    EXPECT_EQ(errorOf(start + "dims 4 x4 4\n"),
              "ParseError: grid.raw:2:8: expected an integer for 'dims', found 'x4'");
    EXPECT_EQ(errorOf(start + "dims 4 4.5 4\n"),
              "ParseError: grid.raw:2:8: expected an integer for 'dims', found '4.5'");
    EXPECT_EQ(errorOf(start + "spacing 1 1 one\n"),
              "ParseError: grid.raw:2:13: expected a number for 'spacing', found 'one'");
    EXPECT_EQ(errorOf(start + "type int64\n"),
              "ParseError: grid.raw:2:6: unknown type 'int64'; expected uint8, int8, uint16, "
              "int16, uint32, int32, float32 or float64");
    EXPECT_EQ(errorOf(start + "components 2\n"),
              "ParseError: grid.raw:2:12: components must be 1 or 3, found 2");
    EXPECT_EQ(errorOf(start + "endian middle\n"),
              "ParseError: grid.raw:2:8: unknown endian 'middle'; expected little or big");
    EXPECT_EQ(errorOf(start + "size 4\n"),
              "ParseError: grid.raw:2:1: unknown header key 'size'; expected dims, type, "
              "components, spacing, origin, endian or data");
    EXPECT_EQ(errorOf(start + "type uint8\n\ntype uint8\n"),
              "ParseError: grid.raw:4:1: duplicate header key 'type' (first given on line 2)");
    EXPECT_EQ(errorOf(start + "type uint8\ndata\n"),
              "ParseError: grid.raw:3:1: header has no 'dims' line");
    EXPECT_EQ(errorOf(start + "dims 1 1 1\ndata\n"),
              "ParseError: grid.raw:3:1: header has no 'type' line");
    EXPECT_EQ(errorOf(start + "dims 1 1 1\ntype uint8\ndata now\n"),
              "ParseError: grid.raw:4:6: 'data' takes 0 values, found 1");
    EXPECT_EQ(errorOf(start + "dims 1 1 1\ntype uint8\n"),
              "ParseError: grid.raw:4:1: header ended before its 'data' line");
    EXPECT_EQ(errorOf(start + std::string(2000, 'x')),
              "ParseError: grid.raw:2:1: header line longer than 1024 characters; is this a "
              "texsplat-raw file?");
}

TEST(RawHeader, reportsUnusableGeometryAsDataErrors) {
    const std::string start = "texsplat-raw 1\n";
    EXPECT_EQ(errorOf(start + "dims 0 4 4\n"), "DataError: grid.raw:2:6: grid dimensions must be "
                                                "at least 1 voxel each, got 0 x 4 x 4");
    EXPECT_EQ(errorOf(start + "spacing 1 -1 1\n"),
              "DataError: grid.raw:2:9: grid spacing must be finite and positive, got 1 -1 1");
    EXPECT_EQ(errorOf(start + "origin nan 0 0\n"),
              "DataError: grid.raw:2:8: grid origin must be finite, got nan 0 0");
}

} // namespace
} // namespace texsplat::volume
