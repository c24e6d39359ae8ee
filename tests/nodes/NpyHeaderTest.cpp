#include "nodes/volume/NpyHeader.h"

#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace texsplat::volume {
namespace {

// The bytes of an .npy file of format `major`.0 whose header is `dict` (padded with blanks and a
// newline to a multiple of 64 bytes, as numpy does).
std::string npy(const std::string& dict, int major = 1) {
    const std::size_t prefix = major == 1 ? 10 : 12;
    std::string header = dict;
    while ((prefix + header.size() + 1) % 64 != 0)
        header += ' ';
    header += '\n';
    std::string bytes = std::string("\x93NUMPY", 6) + char(major) + '\0';
    const std::size_t length = header.size();
    bytes += char(length & 0xff);
    bytes += char((length >> 8) & 0xff);
    if (major != 1)
        bytes += std::string(2, '\0');
    return bytes + header;
}

NpyHeader parse(const std::string& bytes) {
    std::istringstream in(bytes);
    return NpyHeader::parse(in, "a.npy");
}

std::string errorOf(const std::string& bytes) {
    try {
        parse(bytes);
    } catch (const ParseError& error) {
        return std::string("ParseError: ") + error.what();
    } catch (const DataError& error) {
        return std::string("DataError: ") + error.what();
    }
    return "no error";
}

TEST(NpyHeader, readsWhatNumpyWrites) {
    const NpyHeader header =
        parse(npy("{'descr': '<f4', 'fortran_order': False, 'shape': (4, 3, 2), }"));
    EXPECT_EQ(header.majorVersion, 1);
    EXPECT_EQ(header.descr, "<f4");
    EXPECT_FALSE(header.fortranOrder);
    EXPECT_EQ(header.shapeText(), "(4, 3, 2)");
    EXPECT_EQ(header.layout.dims, glm::i64vec3(2, 3, 4));
    EXPECT_EQ(header.layout.type, RawValueType::Float32);
    EXPECT_EQ(header.layout.endian, RawEndian::Little);
    EXPECT_EQ(header.layout.components, 1);
    EXPECT_EQ(header.dataOffset, 128);
}

TEST(NpyHeader, readsEveryTypeOrderAndShape) {
    NpyHeader header = parse(npy("{\"shape\": (5, 6, 7, 3), \"fortran_order\": True, "
                                 "\"descr\": \">u2\"}",
                                 2));
    EXPECT_EQ(header.majorVersion, 2);
    EXPECT_TRUE(header.fortranOrder);
    EXPECT_EQ(header.layout.dims, glm::i64vec3(7, 6, 5));
    EXPECT_EQ(header.layout.components, 3);
    EXPECT_EQ(header.layout.type, RawValueType::UInt16);
    EXPECT_EQ(header.layout.endian, RawEndian::Big);
    EXPECT_EQ(header.dataOffset, 128);

    header = parse(npy("{'descr': '|u1', 'fortran_order': False, 'shape': (9,), }"));
    EXPECT_EQ(header.layout.dims, glm::i64vec3(9, 1, 1));
    EXPECT_EQ(header.shapeText(), "(9,)");
    header = parse(npy("{'descr': '<i4', 'fortran_order': False, 'shape': (3L, 8L), }"));
    EXPECT_EQ(header.layout.dims, glm::i64vec3(8, 3, 1));
    EXPECT_EQ(header.layout.type, RawValueType::Int32);

    const std::pair<const char*, RawValueType> types[] = {
        {"<f8", RawValueType::Float64}, {"|i1", RawValueType::Int8},
        {"<i2", RawValueType::Int16},   {">u4", RawValueType::UInt32},
        {">f4", RawValueType::Float32}};
    for (const auto& [descr, type] : types) {
        header = parse(npy(std::string("{'descr': '") + descr +
                           "', 'fortran_order': False, 'shape': (1, 1, 1), }"));
        EXPECT_EQ(header.layout.type, type) << descr;
    }
}

TEST(NpyHeader, reportsWhatIsWrongWithoutQuotingBinaryBytes) {
    const std::string ok = "'fortran_order': False, 'shape': (2, 2, 2)";
    EXPECT_EQ(errorOf("texsplat-raw 1\n"),
              "ParseError: a.npy: not a NumPy .npy file: expected it to start with the bytes "
              "\\x93NUMPY and a format version");
    EXPECT_EQ(errorOf(std::string("\x93NUMPY\x09\x00", 8)),
              "ParseError: a.npy: unsupported .npy format version 9.0; this reader reads versions "
              "1, 2 and 3");
    EXPECT_EQ(errorOf(npy("{'descr': '<f4', " + ok + "}").substr(0, 40)),
              "ParseError: a.npy: .npy file ends inside its header: the header is 118 bytes "
              "long, but only 30 follow");
    EXPECT_EQ(errorOf(std::string("\x93NUMPY\x02\x00\xff\xff\xff\x00", 12)),
              "ParseError: a.npy: .npy header length 16777215 is more than 65536 bytes; is this "
              "a NumPy .npy file?");
    EXPECT_EQ(errorOf(npy("\x01\xff{}")),
              "ParseError: a.npy: .npy header, character 1: expected '{' starting the header's "
              "dict, found '\\x01'");
    EXPECT_EQ(errorOf(npy("{'descr': '<f4', " + ok + ", 'extra': 1}")),
              "ParseError: a.npy: .npy header, character 62: unknown key 'extra'; expected "
              "'descr', 'fortran_order' and 'shape'");
    EXPECT_EQ(errorOf(npy("{'descr': '<f4', 'descr': '<f4', " + ok + "}")),
              "ParseError: a.npy: .npy header, character 18: duplicate key 'descr'");
    EXPECT_EQ(errorOf(npy("{" + ok + "}")), "ParseError: a.npy: .npy header has no 'descr'");
    EXPECT_EQ(errorOf(npy("{'descr': '<f4', 'fortran_order': 0, 'shape': (2,)}")),
              "ParseError: a.npy: .npy header, character 35: expected a string, True, False or a "
              "tuple, found '0'");
    EXPECT_EQ(errorOf(npy("{'descr': '<f4', 'fortran_order': 'no', 'shape': (2,)}")),
              "ParseError: a.npy: .npy header, character 35: 'fortran_order' must be True or "
              "False");
    EXPECT_EQ(errorOf(npy("{'descr': '<f4', 'fortran_order': False, 'shape': (2, x)}")),
              "ParseError: a.npy: .npy header, character 55: expected an axis length (a whole "
              "number), found 'x'");
    EXPECT_EQ(errorOf(npy("{'descr': [('a', '<f4')], " + ok + "}")),
              "ParseError: a.npy: .npy header, character 11: expected a string, True, False or a "
              "tuple, found '['");
    EXPECT_EQ(errorOf(npy("{'descr': '<f4', " + ok + "} x")),
              "ParseError: a.npy: .npy header, character 62: expected the end of the header "
              "after '}', found 'x'");
    EXPECT_EQ(errorOf(npy("{'descr': '<i8', " + ok + "}")),
              "DataError: a.npy: data type '<i8' is not supported; expected <f4, <f8, |u1, |i1, "
              "<u2, <i2, <u4 or <i4 (or > for big endian)");
    EXPECT_EQ(errorOf(npy("{'descr': '|f4', " + ok + "}")),
              "DataError: a.npy: data type '|f4' is not supported; expected <f4, <f8, |u1, |i1, "
              "<u2, <i2, <u4 or <i4 (or > for big endian)");
    EXPECT_EQ(errorOf(npy("{'descr': '<f4', 'fortran_order': False, 'shape': (2, 2, 2, 2)}")),
              "DataError: a.npy: array of shape (2, 2, 2, 2) is not supported; expected (x), "
              "(y, x), (z, y, x) or (z, y, x, 3)");
    EXPECT_EQ(errorOf(npy("{'descr': '<f4', 'fortran_order': False, 'shape': ()}")),
              "DataError: a.npy: array of shape () is not supported; expected (x), (y, x), "
              "(z, y, x) or (z, y, x, 3)");
    EXPECT_EQ(errorOf(npy("{'descr': '<f4', 'fortran_order': False, 'shape': (4, 0, 4)}")),
              "DataError: a.npy: array of shape (4, 0, 4): grid dimensions must be at least 1 "
              "voxel each, got 4 x 0 x 4");
}

} // namespace
} // namespace texsplat::volume
