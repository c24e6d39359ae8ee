#include "nodes/volume/NrrdVolume.h"

#include "ExternalTool.h"
#include "SceneNodesTestSupport.h"
#include "nodes/NodeTypes.h"
#include "nodes/VolumeData.h"
#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/RawVolume.h"
#include "nodes/volume/VolumeFileInfo.h"
#include "nodes/volume/detail/SourceSupport.h"
#include "scenegraph/Error.h"
#include "scenegraph/MemoryLimit.h"
#include "scenegraph/io/SceneReader.h"
#include "tests/scenegraph/TestFifo.h"

#include <gtest/gtest.h>

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace texsplat::volume {
namespace {

using texsplat::nodes::test::errorOf;
using texsplat::nodes::test::findTool;
using texsplat::nodes::test::runTool;
using texsplat::nodes::test::shellQuoted;
using texsplat::nodes::test::testPath;

// teem's `unu` (Debian's teem-apps installs it as teem-unu).
const std::string& unu() {
    static const std::string tool = findTool({"unu", "teem-unu"});
    return tool;
}

#define REQUIRE_UNU()                                                                          \
    if (unu().empty())                                                                         \
    GTEST_SKIP() << "teem's unu is not installed (teem-apps); it writes the test's NRRD files"

// Runs `unu <arguments>` in `folder`; fails the test when unu does.
void runUnu(const std::string& arguments, const std::string& folder = ".") {
    ASSERT_TRUE(runTool("cd " + shellQuoted(folder) + " && " + unu() + " " + arguments))
        << "unu " << arguments;
}

// Values x + 10 y + 100 z of a 4 x 3 x 2 grid, as `Stored` in little-endian bytes, x fastest.
template <typename Stored> std::string rampBytes(int components = 1) {
    std::string bytes;
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 4; ++x)
                for (int c = 0; c < components; ++c) {
                    const auto value = static_cast<Stored>(x + 10 * y + 100 * z + 1000 * c / 10);
                    char word[sizeof(Stored)];
                    std::memcpy(word, &value, sizeof value);
                    if constexpr (__BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__)
                        std::reverse(word, word + sizeof word);
                    bytes.append(word, sizeof word);
                }
    return bytes;
}

std::string writeFile(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

template <typename T> void expectSameGrid(const Grid<T>& actual, const Grid<T>& expected) {
    ASSERT_EQ(actual.geometry(), expected.geometry());
    const glm::i64vec3 dims = expected.geometry().dims();
    for (std::int64_t z = 0; z < dims.z; ++z)
        for (std::int64_t y = 0; y < dims.y; ++y)
            for (std::int64_t x = 0; x < dims.x; ++x)
                ASSERT_EQ(actual.value({x, y, z}), expected.value({x, y, z}))
                    << x << " " << y << " " << z;
}

struct UnuType {
    const char* unuName;
    RawValueType type;
    std::string bytes;
};

// Every type, encoding and byte order as unu writes it reads as the same values read as raw.
TEST(NrrdVolume, readsEveryTypeEncodingAndByteOrderAsUnuWritesThem) {
    REQUIRE_UNU();
    const UnuType types[] = {{"uchar", RawValueType::UInt8, rampBytes<std::uint8_t>()},
                             {"\"signed char\"", RawValueType::Int8, rampBytes<std::int8_t>()},
                             {"ushort", RawValueType::UInt16, rampBytes<std::uint16_t>()},
                             {"short", RawValueType::Int16, rampBytes<std::int16_t>()},
                             {"uint", RawValueType::UInt32, rampBytes<std::uint32_t>()},
                             {"int", RawValueType::Int32, rampBytes<std::int32_t>()},
                             {"float", RawValueType::Float32, rampBytes<float>()},
                             {"double", RawValueType::Float64, rampBytes<double>()}};
    for (const UnuType& type : types) {
        const std::string raw = writeFile(testPath("ramp.raw"), type.bytes);
        RawHeader layout;
        layout.dims = {4, 3, 2};
        layout.type = type.type;
        const auto expected = std::get<ScalarGridPtr>(readHeaderlessRawVolume(raw, layout, 0));
        const std::string made = testPath("made.nrrd");
        runUnu("make -i " + shellQuoted(raw) + " -t " + type.unuName +
               " -s 4 3 2 -e raw -en little -o " + shellQuoted(made));
        for (const char* encoding : {"raw", "gzip"})
            for (const char* endian : {"little", "big"}) {
                const std::string path = testPath("saved.nrrd");
                runUnu(std::string("save -f nrrd -e ") + encoding + " -en " + endian + " -i " +
                       shellQuoted(made) + " -o " + shellQuoted(path));
                SCOPED_TRACE(std::string(type.unuName) + " " + encoding + " " + endian);
                expectSameGrid(*std::get<ScalarGridPtr>(readNrrdVolume(path)), *expected);
            }
    }
}

TEST(NrrdVolume, takesSpacingFromSpacingsOrSpaceDirectionsAndOrigin) {
    REQUIRE_UNU();
    const std::string raw = writeFile(testPath("ramp.raw"), rampBytes<float>());
    const std::string spacings = testPath("spacings.nrrd");
    runUnu("make -i " + shellQuoted(raw) + " -t float -s 4 3 2 -en little -sp 0.5 1 2 -o " +
           shellQuoted(spacings));
    EXPECT_EQ(std::get<ScalarGridPtr>(readNrrdVolume(spacings))->geometry(),
              GridGeometry({4, 3, 2}, glm::dvec3(0.0), {0.5, 1.0, 2.0}));
    const std::string directions = testPath("directions.nrrd");
    runUnu("make -i " + shellQuoted(raw) + " -t float -s 4 3 2 -en little -spc RAS " +
           "-orig '(1,-2,3.5)' -dirs '(0.5,0,0) (0,1,0) (0,0,2)' -o " + shellQuoted(directions));
    EXPECT_EQ(std::get<ScalarGridPtr>(readNrrdVolume(directions))->geometry(),
              GridGeometry({4, 3, 2}, {1.0, -2.0, 3.5}, {0.5, 1.0, 2.0}));
}

// Directions along the world axes but permuted and negative (as 3D Slicer writes LPS volumes):
// every sample lands where the header puts it.
TEST(NrrdVolume, placesEverySampleOfPermutedAndMirroredAxesWhereTheHeaderPutsIt) {
    REQUIRE_UNU();
    const std::string raw = writeFile(testPath("ramp.raw"), rampBytes<float>());
    const std::string path = testPath("reoriented.nrrd");
    runUnu("make -i " + shellQuoted(raw) + " -t float -s 4 3 2 -en little -spc LPS " +
           "-orig '(1,2,3)' -dirs '(0,-2,0) (0.5,0,0) (0,0,-1)' -o " + shellQuoted(path));
    const auto grid = std::get<ScalarGridPtr>(readNrrdVolume(path));
    EXPECT_EQ(grid->geometry(), GridGeometry({3, 4, 2}, {1.0, -4.0, 2.0}, {0.5, 2.0, 1.0}));
    // Sample (i, j, k) of the file holds i + 10 j + 100 k at (1 + 0.5 j, 2 - 2 i, 3 - k).
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 4; ++i) {
                const glm::dvec3 world(1.0 + 0.5 * j, 2.0 - 2.0 * i, 3.0 - k);
                const glm::dvec3 index = grid->geometry().worldToIndex(world);
                ASSERT_EQ(grid->value(glm::i64vec3(glm::round(index))),
                          float(i + 10 * j + 100 * k))
                    << i << " " << j << " " << k;
            }
}

TEST(NrrdVolume, refusesObliqueSpaceDirections) {
    REQUIRE_UNU();
    const std::string raw = writeFile(testPath("ramp.raw"), rampBytes<float>());
    const std::string path = testPath("oblique.nrrd");
    runUnu("make -i " + shellQuoted(raw) + " -t float -s 4 3 2 -en little -spc RAS " +
           "-orig '(0,0,0)' -dirs '(0.6,0.8,0) (-0.8,0.6,0) (0,0,1)' -o " + shellQuoted(path));
    const std::string error = errorOf<DataError>([&] { readNrrdVolume(path); });
    EXPECT_NE(error.find(": the direction of axis 0 is (0.6,0.8,0), not along one world axis; "
                         "oblique or rotated grids are not supported (resample the volume onto "
                         "an axis-aligned grid)"),
              std::string::npos)
        << error;
    EXPECT_EQ(error.rfind(path + ":", 0), 0u) << error;
}

TEST(NrrdVolume, readsAFourDimensionalArrayOfThreeVectorsAsAVectorGrid) {
    REQUIRE_UNU();
    const std::string raw = writeFile(testPath("vectors.raw"), rampBytes<float>(3));
    const std::string path = testPath("vectors.nrrd");
    runUnu("make -i " + shellQuoted(raw) +
           " -t float -s 3 4 3 2 -en little -k 3-vector space space space -sp nan 1 1 1 -e raw "
           "-o " + shellQuoted(path));
    const auto grid = std::get<VectorGridPtr>(readNrrdVolume(path));
    EXPECT_EQ(grid->geometry(), GridGeometry({4, 3, 2}));
    EXPECT_EQ(grid->value({3, 2, 1}), glm::vec3(123.0f, 223.0f, 323.0f));
}

TEST(NrrdVolume, readsADetachedHeaderWithLineAndByteSkip) {
    REQUIRE_UNU();
    const std::string data = writeFile(testPath("skip.raw"),
                                       "two lines\nof text\n12345" + rampBytes<std::int16_t>());
    // unu writes the data file's name as given, after "./": give it the name beside the header.
    const std::string folder = std::filesystem::path(data).parent_path().string();
    const std::string dataName = std::filesystem::path(data).filename().string();
    const std::string header = testPath("skip.nhdr");
    runUnu("make -h -i " + shellQuoted(dataName) +
           " -t short -s 4 3 2 -en little -ls 2 -bs 5 -o " + shellQuoted(header),
           folder);
    const auto grid = std::get<ScalarGridPtr>(readNrrdVolume(header));
    EXPECT_EQ(grid->value({3, 2, 1}), 123.0f);

    // byte skip -1: the data are the file's last bytes, after a header of unknown length.
    const std::string tail = writeFile(testPath("tail.raw"), "any binary header\x01\x02" +
                                                                 rampBytes<std::int16_t>());
    const std::string tailHeader = testPath("tail.nhdr");
    runUnu("make -h -i " + shellQuoted(std::filesystem::path(tail).filename().string()) +
               " -t short -s 4 3 2 -en little -bs -1 -o " + shellQuoted(tailHeader),
           folder);
    EXPECT_EQ(std::get<ScalarGridPtr>(readNrrdVolume(tailHeader))->value({3, 2, 1}), 123.0f);

    // The data file is found next to the header, whatever the working directory.
    const std::string gzipped = testPath("gz.nhdr");
    const std::string full = testPath("full.nrrd");
    runUnu("make -i " + shellQuoted(data) + " -t short -s 4 3 2 -en little -ls 2 -bs 5 -o " +
           shellQuoted(full));
    runUnu("save -f nrrd -e gzip -i " + shellQuoted(full) + " -o " + shellQuoted(gzipped));
    std::ifstream in(gzipped);
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(text.find("data file: ./"), std::string::npos) << text;
    EXPECT_EQ(std::get<ScalarGridPtr>(readNrrdVolume(gzipped))->value({3, 2, 1}), 123.0f);
}

TEST(NrrdVolume, refusesTruncatedData) {
    REQUIRE_UNU();
    const std::string raw = writeFile(testPath("ramp.raw"), rampBytes<float>());
    const std::string made = testPath("made.nrrd");
    runUnu("make -i " + shellQuoted(raw) + " -t float -s 4 3 2 -en little -o " +
           shellQuoted(made));
    const std::string gzipped = testPath("short-gzip.nrrd");
    runUnu("save -f nrrd -e gzip -i " + shellQuoted(made) + " -o " + shellQuoted(gzipped));

    std::filesystem::resize_file(made, std::filesystem::file_size(made) - 8);
    EXPECT_EQ(errorOf<DataError>([&] { readNrrdVolume(made); }),
              made + ": truncated data: the header's sizes 4 3 2 of type 'float' ask for 96 "
                     "bytes, but only 88 bytes follow the header");

    // A detached header whose data file is short; the message names the data file.
    const std::string shortData = writeFile(testPath("short.raw"), rampBytes<float>().substr(8));
    const std::string folder = std::filesystem::path(shortData).parent_path().string();
    const std::string detached = testPath("short.nhdr");
    runUnu("make -h -i " + shellQuoted(std::filesystem::path(shortData).filename().string()) +
               " -t float -s 4 3 2 -en little -o " + shellQuoted(detached),
           folder);
    EXPECT_EQ(errorOf<DataError>([&] { readNrrdVolume(detached); }),
              shortData + ": truncated data: the header's sizes 4 3 2 of type 'float' ask for 96 "
                          "bytes, but only 88 bytes follow the start of the file");

    // Complete gzip data of fewer values than the header asks for.
    const std::string longer = testPath("longer.nrrd");
    {
        std::ifstream in(gzipped, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), {});
        bytes.replace(bytes.find("sizes: 4 3 2"), 12, "sizes: 4 3 3");
        writeFile(longer, bytes);
    }
    EXPECT_EQ(errorOf<DataError>([&] { readNrrdVolume(longer); }),
              longer + ": truncated data: the gzip data holds only 96 bytes; the header's sizes "
                       "4 3 3 of type 'float' ask for 144 bytes");

    std::filesystem::resize_file(gzipped, std::filesystem::file_size(gzipped) - 12);
    const std::string error = errorOf<DataError>([&] { readNrrdVolume(gzipped); });
    EXPECT_EQ(error.rfind(gzipped + ": the gzip data ends early after ", 0), 0u) << error;
    EXPECT_NE(error.find(" bytes; the header's sizes 4 3 2 of type 'float' ask for 96 bytes"),
              std::string::npos)
        << error;
}

// zlib's compression of `bytes` zeros: what unu writes for an empty volume, a few bytes a MiB.
std::string compressedZeros(std::size_t bytes) {
    const std::string zeros(bytes, '\0');
    uLongf size = compressBound(static_cast<uLong>(bytes));
    std::string packed(size, '\0');
    EXPECT_EQ(compress2(reinterpret_cast<Bytef*>(packed.data()), &size,
                        reinterpret_cast<const Bytef*>(zeros.data()), static_cast<uLong>(bytes), 9),
                        Z_OK);
    packed.resize(size);
    return packed;
}

// A few bytes of gzip can declare any size. A 1 MB file declaring 3.8 GB was allocated (the
// machine had the memory) and inflated to its end; deflate expands a byte into at most 1032, so
// what the data can hold is checked before anything is allocated or decompressed.
TEST(NrrdVolume, refusesAGzipBombBeforeAllocatingForIt) {
    const std::string header = "NRRD0004\ntype: float\ndimension: 3\nsizes: 1000 1000 1000\n"
                               "endian: little\nencoding: gzip\n\n";
    const std::string data = compressedZeros(std::size_t{1} << 20);
    const std::string path = writeFile(testPath("bomb.nrrd"), header + data);
    EXPECT_EQ(errorOf<DataError>([&] { readNrrdVolume(path); }),
              path + ": truncated data: the header's sizes 1000 1000 1000 of type 'float' ask for "
                     "4000000000 bytes, but its " +
                  std::to_string(data.size()) + " bytes of gzip data hold at most " +
                  std::to_string(data.size() * 1032 + 258) +
                  " (deflate expands at most 1032 to 1)");
    // Data that could hold the grid: then the memory limit is asked, before allocating.
    const std::string fits = writeFile(testPath("fits.nrrd"),
                                       "NRRD0004\ntype: float\ndimension: 3\nsizes: 64 64 64\n"
                                       "endian: little\nencoding: gzip\n\n" +
                                           compressedZeros(std::size_t{1} << 20));
    const std::uint64_t previous = setMemoryLimit(std::uint64_t{512} << 10);
    const std::string error = errorOf<ResourceError>([&] { readNrrdVolume(fits); });
    setMemoryLimit(previous);
    EXPECT_EQ(error, fits + ": a grid of 64 x 64 x 64 voxels x 1 float would need " +
                         bytesText(std::uint64_t{1} << 20) + ", more than the memory limit of " +
                         bytesText(std::uint64_t{512} << 10) +
                         "; use a volume of lower resolution, or a larger --memory-limit");
    EXPECT_EQ(std::get<ScalarGridPtr>(readNrrdVolume(fits))->value({63, 63, 63}), 0.0f);
}

TEST(NrrdVolume, aFileThatIsNotNrrdGetsTheFormatNamed) {
    const std::string path = writeFile(testPath("not.nrrd"), std::string("\x00\x01\xfe\xff", 4));
    EXPECT_EQ(errorOf<ParseError>([&] { readNrrdVolume(path); }),
              path + ": not a NRRD file: expected it to start with 'NRRD0001' to 'NRRD0005'");
}

TEST(NrrdVolume, refusesATypeItDoesNotRead) {
    const std::string path = writeFile(testPath("long.nrrd"),
                                       "NRRD0004\ntype: int64\ndimension: 3\nsizes: 1 1 1\n"
                                       "endian: little\nencoding: raw\n\n" +
                                           std::string(8, '\0'));
    EXPECT_EQ(errorOf<DataError>([&] { readNrrdVolume(path); }),
              path + ":2:7: type 'int64' is not supported; texsplat reads int8, uint8, int16, "
                     "uint16, int32, uint32, float and double");
}

TEST(NrrdVolume, refusesAFifoBeforeOpeningIt) {
    const texsplat::test::TestFifo pipe(testPath("data.nrrd"));
    EXPECT_EQ(errorOf<IoError>([&] { readNrrdVolume(pipe.path()); }),
              pipe.path() + ": cannot read file: it is a FIFO, not a regular file");
}

TEST(NrrdVolume, isASourceOfVolumeDataAndOfInfo) {
    REQUIRE_UNU();
    const std::string raw = writeFile(testPath("ramp.raw"), rampBytes<std::uint8_t>());
    const std::string path = testPath("ramp.nrrd");
    runUnu("make -i " + shellQuoted(raw) + " -t uchar -s 4 3 2 -sp 1 1 2 -e raw -o " +
           shellQuoted(path));
    nodes::registerNodeTypes();
    const sg::Node::Ptr root = sg::SceneReader::readString(
        "#Inventor V2.1 ascii\nVolumeData { source FILE_NRRD fileName \"" + path + "\" }\n");
    const auto& volume = static_cast<const nodes::VolumeData&>(*root);
    EXPECT_EQ(volume.scalarGrid()->value({1, 2, 1}), 121.0f);

    const std::string info = describeVolumeFile(path, 2);
    EXPECT_EQ(info.substr(0, info.find('\n') + 1),
              path + ": NRRD, type 'unsigned char' (uint8), sizes 4 3 2, raw encoding, little "
                     "endian\n");
    EXPECT_NE(info.find("  dimensions    4 x 3 x 2 voxels (x, y, z)\n"
                        "  voxel size    1 x 1 x 2\n"),
              std::string::npos)
        << info;
    EXPECT_NE(info.find("  value range   0 .. 123\n"), std::string::npos) << info;
    EXPECT_NE(info.find("VolumeData { source FILE_NRRD fileName \"" + path + "\" }"),
              std::string::npos)
        << info;
}

} // namespace
} // namespace texsplat::volume
