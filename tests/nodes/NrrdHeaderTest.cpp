#include "nodes/volume/NrrdHeader.h"

#include "SceneNodesTestSupport.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace texsplat::volume {
namespace {

using texsplat::nodes::test::errorOf;

NrrdHeader parse(const std::string& text) {
    std::istringstream in(text);
    return NrrdHeader::parse(in, "h.nrrd");
}

// A valid header of a 4 x 3 x 2 float grid, with `extra` lines before its blank line.
std::string header(const std::string& extra = {}) {
    return "NRRD0004\n# a comment\ntype: float\ndimension: 3\nsizes: 4 3 2\nendian: big\n"
           "encoding: gzip\n" +
           extra + "\n";
}

TEST(NrrdHeader, readsTheLayoutAndWhereTheDataStarts) {
    const std::string text = header("spacings: 0.5 1 2\ncontent: ramp\nunit:=mm\n");
    const NrrdHeader parsed = parse(text + "DATA");
    EXPECT_EQ(parsed.layout.dims, glm::i64vec3(4, 3, 2));
    EXPECT_EQ(parsed.layout.type, RawValueType::Float32);
    EXPECT_EQ(parsed.layout.endian, RawEndian::Big);
    EXPECT_EQ(parsed.layout.spacing, glm::dvec3(0.5, 1.0, 2.0));
    EXPECT_EQ(parsed.encoding, NrrdEncoding::Gzip);
    EXPECT_EQ(parsed.typeName, "float");
    EXPECT_EQ(parsed.dataOffset, static_cast<std::int64_t>(text.size()));
    EXPECT_TRUE(parsed.dataFile.empty());
}

TEST(NrrdHeader, readsSpaceDirectionsOriginAndADataFile) {
    const NrrdHeader parsed =
        parse("NRRD0005\ntype: unsigned short int\ndimension: 4\nsizes: 3 4 3 2\n"
              "endian: little\nencoding: raw\nspace: left-posterior-superior\n"
              "space directions: none (0.5,0,0) (0, 1, 0) (0,0,2)\nspace origin: (1,2,3)\n"
              "byte skip: -1\nline skip: 2\ndata file: vectors.raw\n");
    EXPECT_EQ(parsed.layout.type, RawValueType::UInt16);
    EXPECT_EQ(parsed.layout.components, 3);
    EXPECT_EQ(parsed.layout.dims, glm::i64vec3(4, 3, 2));
    EXPECT_EQ(parsed.layout.spacing, glm::dvec3(0.5, 1.0, 2.0));
    EXPECT_EQ(parsed.layout.origin, glm::dvec3(1.0, 2.0, 3.0));
    EXPECT_EQ(parsed.byteSkip, -1);
    EXPECT_EQ(parsed.lineSkip, 2);
    EXPECT_EQ(parsed.dataFile, "vectors.raw");
}

// Axis-aligned directions in any order and sign: each file axis lands on its world axis, the
// grid keeps positive spacings, and its voxel (0,0,0) is the sample nearest the low corner.
TEST(NrrdHeader, readsPermutedAndNegativeDirections) {
    const NrrdHeader parsed = parse(
        header("space directions: (0,-2,0) (0.5,0,0) (0,0,-1)\nspace origin: (1,2,3)\n"));
    EXPECT_EQ(parsed.gridAxis, glm::ivec3(1, 0, 2));
    EXPECT_EQ(parsed.reversed, glm::bvec3(true, false, true));
    EXPECT_EQ(parsed.layout.dims, glm::i64vec3(3, 4, 2));
    EXPECT_EQ(parsed.layout.spacing, glm::dvec3(0.5, 2.0, 1.0));
    EXPECT_EQ(parsed.layout.origin, glm::dvec3(1.0, 2.0 - 3 * 2.0, 3.0 - 1.0));
    // A 2-D image in the y-z plane: its missing third axis becomes x.
    const NrrdHeader plane = parse("NRRD0004\ntype: uchar\ndimension: 2\nsizes: 5 7\n"
                                   "encoding: raw\nspace directions: (0,1,0) (0,0,1)\n\n");
    EXPECT_EQ(plane.gridAxis, glm::ivec3(1, 2, 0));
    EXPECT_EQ(plane.layout.dims, glm::i64vec3(1, 5, 7));
}

TEST(NrrdHeader, namesWhatIsWrongAndWhere) {
    const auto errorOfHeader = [](const std::string& text) {
        try {
            parse(text);
        } catch (const Error& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(errorOfHeader("\x89PNG\r\n\x1a\n"),
              "h.nrrd: not a NRRD file: expected it to start with 'NRRD0001' to 'NRRD0005'");
    EXPECT_EQ(errorOfHeader("NRRD0009\n"),
              "h.nrrd: unsupported NRRD version 'NRRD0009'; this reader reads NRRD0001 to "
              "NRRD0005");
    EXPECT_EQ(errorOfHeader(header("colour: red\n")), "h.nrrd:8:1: unknown field 'colour'");
    EXPECT_EQ(errorOfHeader(header("encoding: raw\n")),
              "h.nrrd:8:1: duplicate field 'encoding' (first given on line 7)");
    EXPECT_EQ(errorOfHeader("NRRD0004\ntype: float\ndimension: 3\nsizes: 4 3 2\n"
                            "encoding: raw\n\n"),
              "h.nrrd:2:1: type 'float' has several bytes, but the header has no 'endian' field");
    EXPECT_EQ(errorOfHeader("NRRD0004\ntype: float\nsizes: 4 3 2\n"),
              "h.nrrd:3:8: 'sizes' comes before 'dimension'");
    EXPECT_EQ(errorOfHeader("NRRD0004\ndimension: 3\nsizes: 4 3\n"),
              "h.nrrd:3:11: 'sizes' needs 3 values (one per axis), found 2");
    EXPECT_EQ(errorOfHeader("NRRD0004\ndimension: 3\nsizes: 4 x 2\n"),
              "h.nrrd:3:10: expected a size in 'sizes', found 'x'");
    EXPECT_EQ(errorOfHeader("NRRD0004\ntype: float\ndimension: 3\nsizes: 4 0 2\n"
                            "endian: little\nencoding: raw\n\n"),
              "h.nrrd:4:1: grid dimensions must be at least 1 voxel each, got 4 x 0 x 2");
    EXPECT_EQ(errorOfHeader(header().replace(header().find("gzip"), 4, "bzip2")),
              "h.nrrd:7:11: encoding 'bzip2' is not supported; texsplat reads raw and gzip "
              "(convert with: unu save -f nrrd -e gzip -i IN -o OUT.nrrd)");
    EXPECT_EQ(errorOfHeader(header("space directions: (1,0,0) (0,0.6,0.8) (0,0,1)\n")),
              "h.nrrd:8:1: the direction of axis 1 is (0,0.6,0.8), not along one world axis; "
              "oblique or rotated grids are not supported (resample the volume onto an "
              "axis-aligned grid)");
    EXPECT_EQ(errorOfHeader(header("space directions: (1,0,0) (0,0,1) (0,0,-2)\n")),
              "h.nrrd:8:1: two axes lie along world axis z (the direction of axis 2 is "
              "(0,0,-2))");
    EXPECT_EQ(errorOfHeader(header("spacings: 1 1 1\nspace directions: (1,0,0) (0,1,0) "
                                   "(0,0,1)\n")),
              "h.nrrd:8:1: a header gives either 'spacings' or 'space directions', not both");
    EXPECT_EQ(errorOfHeader(header("spacings: 1 -1 1\n")),
              "h.nrrd:8:1: the spacing of axis 1 must be a finite number above 0, found -1");
    EXPECT_EQ(errorOfHeader("NRRD0004\ntype: float\ndimension: 4\nsizes: 2 4 3 2\n"
                            "endian: little\nencoding: raw\n\n"),
              "h.nrrd:4:1: a 4-D array must hold 3-vectors along its first axis (sizes 3 X Y Z), "
              "found sizes 2 4 3 2");
    EXPECT_EQ(errorOfHeader("NRRD0004\ntype: float\ndimension: 3\nsizes: 4 3 2\n"
                            "endian: little\nencoding: raw\n"),
              "h.nrrd:7:1: the header ends without the blank line before its data and names no "
              "'data file'");
    EXPECT_EQ(errorOfHeader(header("data file: \x1b[2Jdata.raw\n")),
              "h.nrrd:8:12: 'data file' is not printable text: '\\x1b[2Jdata.raw'");
    EXPECT_EQ(errorOfHeader(header("data file: LIST\n")),
              "h.nrrd:8:12: several data files are not supported; join them into one (unu join)");
    EXPECT_EQ(errorOfHeader(header("byte skip: -1\n")),
              "h.nrrd:8:1: 'byte skip: -1' works with raw encoding only");
}

} // namespace
} // namespace texsplat::volume
