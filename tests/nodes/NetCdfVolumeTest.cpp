#include "nodes/volume/NetCdfVolume.h"

#include "ExternalTool.h"
#include "SceneNodesTestSupport.h"
#include "nodes/NodeTypes.h"
#include "nodes/VolumeData.h"
#include "nodes/volume/VolumeFileInfo.h"
#include "scenegraph/Error.h"
#include "scenegraph/Log.h"
#include "scenegraph/MemoryLimit.h"
#include "scenegraph/WorkProgress.h"
#include "scenegraph/io/SceneReader.h"
#include "tests/scenegraph/TestFifo.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

namespace texsplat::volume {
namespace {

using texsplat::nodes::test::errorOf;
using texsplat::nodes::test::findTool;
using texsplat::nodes::test::runTool;
using texsplat::nodes::test::shellQuoted;
using texsplat::nodes::test::testPath;

#ifdef TEXSPLAT_WITH_NETCDF

const std::string& ncgen() {
    static const std::string tool = findTool({"ncgen"});
    return tool;
}

#define REQUIRE_NCGEN()                                                                        \
    if (ncgen().empty())                                                                       \
    GTEST_SKIP() << "NetCDF's ncgen is not installed (netcdf-bin); it writes the test's files"

// The NetCDF file ncgen writes from `cdl`, in the format `kind` ("classic", "nc4", ...).
std::string generate(const std::string& name, const std::string& cdl,
                     const std::string& kind = "classic") {
    const std::string source = testPath(name + ".cdl");
    std::ofstream(source) << cdl;
    const std::string path = testPath(name + ".nc");
    EXPECT_TRUE(runTool(ncgen() + " -k " + shellQuoted(kind) + " -o " + shellQuoted(path) + " " +
                        shellQuoted(source)))
        << cdl;
    return path;
}

// v[z][y][x] = x + 10 y + 100 z, with evenly spaced coordinates along x, y and z.
const char* const kRamp = R"(netcdf ramp {
dimensions:
    z = 2 ; y = 3 ; x = 4 ;
variables:
    double z(z) ; float y(y) ; float x(x) ;
    float v(z, y, x) ;
    float flat(y, x) ;
data:
    z = -5, -3 ;
    y = 0, 1, 2 ;
    x = 10, 10.5, 11, 11.5 ;
    v = 0, 1, 2, 3, 10, 11, 12, 13, 20, 21, 22, 23,
        100, 101, 102, 103, 110, 111, 112, 113, 120, 121, 122, 123 ;
    flat = 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11 ;
}
)";

TEST(NetCdfVolume, readsA3DVariableInCOrderWithItsCoordinatesAsNcgenWritesIt) {
    REQUIRE_NCGEN();
    for (const char* kind : {"classic", "64-bit offset", "cdf5", "nc4"}) {
        SCOPED_TRACE(kind);
        const std::string path = generate("ramp", kRamp, kind);
        const auto grid = std::get<ScalarGridPtr>(readNetCdfVariable(path, "v"));
        EXPECT_EQ(grid->geometry(), GridGeometry({4, 3, 2}, {10.0, 0.0, -5.0}, {0.5, 1.0, 2.0}));
        for (int z = 0; z < 2; ++z)
            for (int y = 0; y < 3; ++y)
                for (int x = 0; x < 4; ++x)
                    ASSERT_EQ(grid->value({x, y, z}), float(x + 10 * y + 100 * z));
    }
}

TEST(NetCdfVolume, appliesScaleAndOffsetAndMakesFillValuesEmpty) {
    REQUIRE_NCGEN();
    const std::string path = generate("packed", R"(netcdf packed {
dimensions:
    z = 2 ; y = 1 ; x = 2 ;
variables:
    short t(z, y, x) ;
        t:scale_factor = 0.5 ;
        t:add_offset = 10. ;
        t:_FillValue = -1s ;
    float u(z, y, x) ;
        u:missing_value = -999.f ;
data:
    t = 0, 4, _, 8 ;
    u = 1, -999, _, 4 ;
}
)");
    const auto grid = std::get<ScalarGridPtr>(readNetCdfVariable(path, "t"));
    EXPECT_EQ(grid->value({0, 0, 0}), 10.0f);
    EXPECT_EQ(grid->value({1, 0, 0}), 12.0f);
    EXPECT_FALSE(grid->isActive({0, 0, 1})) << "the fill value is an empty voxel";
    EXPECT_EQ(grid->value({1, 0, 1}), 14.0f);
    // missing_value, and the type's default fill where nothing was written (no _FillValue).
    const auto other = std::get<ScalarGridPtr>(readNetCdfVariable(path, "u"));
    EXPECT_EQ(other->value({0, 0, 0}), 1.0f);
    EXPECT_FALSE(other->isActive({1, 0, 0}));
    EXPECT_FALSE(other->isActive({0, 0, 1}));
    EXPECT_EQ(other->value({1, 0, 1}), 4.0f);
}

const char* const kSeries = R"(netcdf series {
dimensions:
    time = UNLIMITED ; z = 1 ; y = 1 ; x = 2 ;
variables:
    double time(time) ;
    int w(time, z, y, x) ;
    float flat(y, x) ;
data:
    time = 0, 6 ;
    w = 1, 2, 3, 4 ;
    flat = 1, 2 ;
}
)";

TEST(NetCdfVolume, readsATimeStepOfA4DVariable) {
    REQUIRE_NCGEN();
    const std::string path = generate("series", kSeries);
    const auto second = std::get<ScalarGridPtr>(readNetCdfVariable(path, "w", 1));
    EXPECT_EQ(second->value({0, 0, 0}), 3.0f);
    EXPECT_EQ(second->value({1, 0, 0}), 4.0f);
    // No name: the file's only 3-D or 4-D variable.
    EXPECT_EQ(std::get<ScalarGridPtr>(readNetCdfVariable(path, ""))->value({1, 0, 0}), 2.0f);
    EXPECT_EQ(errorOf<DataError>([&] { readNetCdfVariable(path, "w", 2); }),
              path + ": variable 'w': timeStep 2 is outside its 2 steps along 'time' (0 to 1)");
    const std::string ramp = generate("ramp", kRamp);
    EXPECT_EQ(errorOf<DataError>([&] { readNetCdfVariable(ramp, "v", 1); }),
              ramp + ": variable 'v': timeStep 1 asks for a time step of a variable without a "
                     "time dimension");
}

TEST(NetCdfVolume, aMissingOrWrongVariableGetsTheVariablesListed) {
    REQUIRE_NCGEN();
    const std::string path = generate("ramp", kRamp);
    EXPECT_EQ(errorOf<DataError>([&] { readNetCdfVariable(path, "temperature"); }),
              path + ": no variable named 'temperature'; the file has: float v(z=2, y=3, x=4), "
                     "float flat(y=3, x=4)");
    EXPECT_EQ(errorOf<DataError>([&] { readNetCdfVariable(path, "flat"); }),
              path + ": variable 'flat' has 2 dimensions (float flat(y=3, x=4)); texsplat reads "
                     "3-D variables (z, y, x) and 4-D ones (time, z, y, x)");
    const std::string two = generate("two", R"(netcdf two {
dimensions:
    z = 1 ; y = 1 ; x = 1 ;
variables:
    float a(z, y, x) ;
    byte b(z, y, x) ;
}
)");
    EXPECT_EQ(errorOf<DataError>([&] { readNetCdfVariable(two, ""); }),
              two + ": no variable named, and the file has 2 3-D or 4-D variables; name one "
                    "(VolumeData's gridName) of: float a(z=1, y=1, x=1), byte b(z=1, y=1, x=1)");
    const std::string flat = generate("flat", R"(netcdf flat {
dimensions:
    y = 1 ; x = 2 ;
variables:
    float x(x) ;
    float sst(y, x) ;
}
)");
    EXPECT_EQ(errorOf<DataError>([&] { readNetCdfVariable(flat, ""); }),
              flat + ": no 3-D or 4-D variable to read; the file has: float sst(y=1, x=2)");
}

TEST(NetCdfVolume, aFileThatIsNotNetCdfGetsTheFormatNamed) {
    const std::string path = testPath("not.nc");
    std::ofstream(path, std::ios::binary) << std::string("\x00\x01\xfe\xff binary", 11);
    EXPECT_EQ(errorOf<ParseError>([&] { readNetCdfVariable(path, "v"); }),
              path + ": not a NetCDF file: expected NetCDF classic, 64-bit offset, CDF-5 or "
                     "NetCDF-4 (NetCDF: Unknown file format)");
    const texsplat::test::TestFifo pipe(testPath("data.nc"));
    EXPECT_EQ(errorOf<IoError>([&] { listNetCdfVariables(pipe.path()); }),
              pipe.path() + ": cannot read file: it is a FIFO, not a regular file");
}

TEST(NetCdfVolume, sizesInAClassicHeaderAreCheckedAgainstTheFileBeforeLibNetCdfAllocates) {
    // Found by fuzz_netcdf_reader: a name's length of 0xe2e2e2e2 made libnetcdf allocate 3.8 GB
    // for a file of 24 bytes.
    const std::string path = testPath("name.nc");
    const std::string header("CDF\x01"
                             "\0\0\0\0"           // no records
                             "\0\0\0\x0a\0\0\0\x01" // one dimension
                             "\xe2\xe2\xe2\xe2zzzz",  // its name's length, 4 bytes of name
                             24);
    std::ofstream(path, std::ios::binary) << header;
    EXPECT_EQ(errorOf<IoError>([&] { listNetCdfVariables(path); }),
              path + ": truncated or corrupt NetCDF file: a name at byte 20 needs 3806520034 "
                     "bytes, but the file ends at byte 24");
    // A count of attributes beyond the file (CDF-5: 8-byte counts), checked before the items.
    const std::string counts("CDF\x05"
                             "\0\0\0\0\0\0\0\0"             // no records
                             "\0\0\0\0\0\0\0\0\0\0\0\0"     // no dimensions
                             "\0\0\0\x0c\x7f\xff\xff\xff\xff\xff\xff\xff", // attributes
                             36);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << counts;
    EXPECT_EQ(errorOf<IoError>([&] { readNetCdfVariable(path, "v"); }),
              path + ": truncated or corrupt NetCDF file: the global attributes at byte 36 "
                     "declares 9223372036854775807 items of at least 4 bytes, but the file ends "
                     "at byte 36");
}

// The 80-byte header of a classic NetCDF file with one dimension x of `length` and one
// variable v(x) of NetCDF type `type` whose values take `size` bytes from byte 80 (the
// header's end, so the file holds none of them).
std::string oneVariableHeader(std::uint32_t length, std::uint32_t type, std::uint32_t size) {
    std::string header("CDF\x01", 4);
    const auto word = [&header](std::uint32_t value) {
        for (int shift = 24; shift >= 0; shift -= 8) {
            header.push_back(static_cast<char>((value >> shift) & 0xff));
        }
    };
    const auto name = [&](char letter) {
        word(1);
        header.push_back(letter);
        header.append(3, '\0'); // padded to 4 bytes
    };
    word(0);                 // no records
    word(10);                // NC_DIMENSION
    word(1);                 // one dimension:
    name('x');               // x,
    word(length);            // of `length`
    word(0);                 // no global attributes
    word(0);                 //
    word(11);                // NC_VARIABLE
    word(1);                 // one variable:
    name('v');               // v,
    word(1);                 // of one dimension,
    word(0);                 // x
    word(0);                 // no attributes
    word(0);                 //
    word(type);              // its type,
    word(size);              // the bytes of its values
    word(80);                // and where they start
    return header;
}

TEST(NetCdfVolume, aVariableOfAnUnknownTypeIsRefusedBeforeLibNetCdfDividesByItsSize) {
    // Found by fuzz_netcdf_reader (scripts/fuzz-long.sh, seed 7): a variable of type 12 in a
    // classic file stopped the process with SIGFPE inside libnetcdf (NC_check_vlen).
    const std::string path = testPath("type.nc");
    std::ofstream(path, std::ios::binary) << oneVariableHeader(3, 12, 12);
    EXPECT_EQ(errorOf<IoError>([&] { listNetCdfVariables(path); }),
              path + ": truncated or corrupt NetCDF file: a variable's type is 12, expected 1 "
                     "to 6");
}

TEST(NetCdfVolume, valuesDeclaredBeyondTheEndOfAClassicFileAreRefused) {
    // Found by fuzz_netcdf_reader (scripts/fuzz-long.sh, seed 1126): a header of 404 bytes
    // declared a variable of 100 MB, which libnetcdf read as fill values and texsplat converted
    // for longer than the fuzzer's 10 s.
    const std::string path = testPath("beyond.nc");
    std::ofstream(path, std::ios::binary) << oneVariableHeader(100000000, 5, 400000000);
    EXPECT_EQ(errorOf<IoError>([&] { listNetCdfVariables(path); }),
              path + ": truncated or corrupt NetCDF file: variable 'v' declares 400000000 bytes "
                     "of values from byte 80, but the file ends at byte 80");
}

TEST(NetCdfVolume, chunksLargerThanTheMemoryLimitAreRefusedBeforeHdf5ReadsOne) {
    // A NetCDF-4 file declares its chunks' size, up to 4 GiB each along an unlimited dimension
    // whatever the variable holds; HDF5 allocated and filled one (80 MB here) to read 8 values.
    REQUIRE_NCGEN();
    const std::string path = generate("chunks", R"(netcdf chunks {
dimensions:
    time = UNLIMITED ; z = 2 ; y = 2 ; x = 2 ;
variables:
    float v(time, z, y, x) ;
        v:_ChunkSizes = 2500000, 2, 2, 2 ;
data:
    v = 1, 2, 3, 4, 5, 6, 7, 8 ;
}
)", "nc4");
    const std::uint64_t limit = std::uint64_t{16} << 20;
    const std::uint64_t previous = setMemoryLimit(limit);
    const std::string error = errorOf<ResourceError>([&] { readNetCdfVariable(path, "v"); });
    setMemoryLimit(previous);
    EXPECT_EQ(error, path + ": variable 'v': its chunks of 2500000 x 2 x 2 x 2 values of 4 bytes "
                            "(HDF5 reads a chunk whole) would need " +
                         bytesText(80000000) + ", more than the memory limit of " +
                         bytesText(limit) +
                         "; use a volume of lower resolution, or a larger --memory-limit");
    EXPECT_NO_THROW(readNetCdfVariable(path, "v")); // under the limit of this machine
}

TEST(NetCdfVolume, aGlobalHeapThatHdf5WouldReadForeverIsRefused) {
    // Found by fuzz_netcdf_reader (scripts/fuzz-long.sh, seed 20261127): HDF5 1.10 walks a global
    // heap collection object by object, stepping over the free space by its size; a free-space
    // object of 0 bytes kept `texsplat info` on a 7 KB file busy for good. ncgen writes the
    // coordinate variables' dimension scales' references into such a collection.
    REQUIRE_NCGEN();
    const std::string written = generate("heap", kRamp, "nc4");
    std::ifstream in(written, std::ios::binary);
    std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_NO_THROW(readNetCdfVariable(written, "v"));
    const std::size_t collection = bytes.find("GCOL");
    ASSERT_NE(collection, std::string::npos);
    // Objects (lengths of 8 bytes): an index of 2 bytes, a count of 2, 4 reserved, a size of 8,
    // then the data padded to 8; the free space is the object of index 0.
    const auto field = [&](std::size_t at, int count) {
        std::uint64_t value = 0;
        for (int i = count - 1; i >= 0; --i)
            value = (value << 8U) | static_cast<unsigned char>(bytes[at + std::size_t(i)]);
        return value;
    };
    std::size_t object = collection + 16;
    while (field(object, 2) != 0) {
        object += 16 + (field(object + 8, 8) + 7) / 8 * 8;
        ASSERT_LT(object + 16, collection + field(collection + 8, 8)) << "no free space";
    }
    bytes.replace(object + 8, 8, std::string(8, '\0'));
    const std::string damaged = testPath("heap-damaged.nc");
    std::ofstream(damaged, std::ios::binary) << bytes;
    EXPECT_EQ(errorOf<IoError>([&] { listNetCdfVariables(damaged); }),
              damaged + ": truncated or corrupt NetCDF file: the HDF5 global heap at byte " +
                  std::to_string(collection) + " has a free-space object of 0 bytes at byte " +
                  std::to_string(object) + ", which HDF5 1.10 reads forever");
}

// Winds and clouds of one climate file: u, v and w on pressure levels (decreasing) and latitudes
// from north to south (decreasing), as ERA5 and most reanalyses store them.
const char* const kClimate = R"(netcdf climate {
dimensions:
    level = 3 ; latitude = 2 ; longitude = 4 ;
variables:
    float level(level) ;
    float latitude(latitude) ;
    float longitude(longitude) ;
    float u(level, latitude, longitude) ;
    float v(level, latitude, longitude) ;
    float w(level, latitude, longitude) ;
    float cc(level, latitude, longitude) ;
    float flat(latitude, longitude) ;
data:
    level = 1000, 850, 700 ;
    latitude = 60, 50 ;
    longitude = -120, -119.5, -119, -118.5 ;
    u = 0, 1, 2, 3, 10, 11, 12, 13, 100, 101, 102, 103, 110, 111, 112, 113,
        200, 201, 202, 203, 210, 211, 212, 213 ;
    v = 0, -1, -2, -3, -10, -11, -12, -13, -100, -101, -102, -103, -110, -111, -112, -113,
        -200, -201, -202, -203, -210, -211, -212, -213 ;
    w = 1, 1, 1, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2, 2, 2, 3, 3, 3, 3, 3, 3, 3, 3 ;
    cc = 0, 1, 2, 3, 10, 11, 12, 13, 100, 101, 102, 103, 110, 111, 112, 113,
         200, 201, 202, 203, 210, 211, 212, 213 ;
    flat = 1, 2, 3, 4, 5, 6, 7, 8 ;
}
)";

// The value the file stores at (longitude, latitude, level) index (i, j, k) of u and cc.
float climateValue(int i, int j, int k) { return float(i + 10 * j + 100 * k); }

// The decreasing levels and latitudes run from their other end: voxel (0, 0, 0) is the file's
// last latitude and last level, the smallest coordinates. It was indexed 0, 1, 2 with a warning
// ("not evenly spaced and increasing"): winds and clouds lost their place in the world.
TEST(NetCdfVolume, decreasingEvenlySpacedCoordinatesRunTheirAxisFromTheOtherEnd) {
    REQUIRE_NCGEN();
    const std::string path = generate("climate", kClimate);
    std::vector<std::string> logged;
    const LogSink previous = setLogSink(
        [&](LogLevel, std::string_view message) { logged.emplace_back(message); });
    const auto clouds = std::get<ScalarGridPtr>(readNetCdfVariable(path, "cc"));
    setLogSink(previous);
    EXPECT_TRUE(logged.empty()) << logged.front();
    EXPECT_EQ(clouds->geometry(),
              GridGeometry({4, 2, 3}, {-120.0, 50.0, 700.0}, {0.5, 10.0, 150.0}));
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 4; ++i)
                ASSERT_EQ(clouds->value({i, j, k}), climateValue(i, 1 - j, 2 - k))
                    << i << " " << j << " " << k;
}

// Uneven levels index their axis, with one warning, also when info streams the variable twice.
TEST(NetCdfVolume, anUnevenCoordinateIndexesItsAxisWithOneWarning) {
    REQUIRE_NCGEN();
    const std::string path = generate("uneven", R"(netcdf uneven {
dimensions:
    level = 3 ; y = 1 ; x = 2 ;
variables:
    float level(level) ;
    float t(level, y, x) ;
data:
    level = 1000, 850, 500 ;
    t = 1, 2, 3, 4, 5, 6 ;
}
)");
    std::vector<std::string> logged;
    const LogSink previous = setLogSink(
        [&](LogLevel, std::string_view message) { logged.emplace_back(message); });
    const std::string info = describeVolumeFile(path);
    setLogSink(previous);
    EXPECT_EQ(logged, std::vector<std::string>{path + ": variable 't': coordinate 'level' is not "
                                                      "evenly spaced; its axis (z) is indexed 0, "
                                                      "1, 2, ..."});
    EXPECT_NE(info.find("  voxel size    1 x 1 x 1\n"), std::string::npos) << info;
}

// `gridName "u v w"`: vectors from three variables, in the clouds' place (the docs' climate example
// needed a Python conversion to a vector .npy, which lost the coordinates).
TEST(NetCdfVolume, threeVariablesNamedTogetherAreTheComponentsOfVectors) {
    REQUIRE_NCGEN();
    const std::string path = generate("climate", kClimate);
    const auto winds = std::get<VectorGridPtr>(readNetCdfVariable(path, "u v w"));
    const auto clouds = std::get<ScalarGridPtr>(readNetCdfVariable(path, "cc"));
    EXPECT_EQ(winds->geometry(), clouds->geometry());
    EXPECT_EQ(winds->value({3, 0, 0}), glm::vec3(213.0f, -213.0f, 3.0f));
    EXPECT_EQ(winds->value({1, 1, 2}), glm::vec3(1.0f, -1.0f, 1.0f));

    nodes::registerNodeTypes();
    const sg::Node::Ptr root = sg::SceneReader::readString(
        "#Inventor V2.1 ascii\nVolumeData { source FILE_NETCDF fileName \"" + path +
        "\" gridName \"u v w\" }\n");
    const auto& volume = static_cast<const nodes::VolumeData&>(*root);
    ASSERT_NE(volume.vectorGrid(), nullptr);
    EXPECT_EQ(volume.vectorGrid()->value({3, 0, 0}), glm::vec3(213.0f, -213.0f, 3.0f));

    EXPECT_EQ(errorOf<DataError>([&] { readNetCdfVariable(path, "u v"); }),
              path + ": 'u v' names 2 variables; vectors take three, their x, y and z "
                     "components ('u v w')");
    EXPECT_EQ(errorOf<DataError>([&] { readNetCdfVariable(path, "u v q"); }),
              path + ": no variable named 'q' (of the vector 'u v q'); the file has: float "
                     "u(level=3, latitude=2, longitude=4), float v(level=3, latitude=2, "
                     "longitude=4), float w(level=3, latitude=2, longitude=4), float cc(level=3, "
                     "latitude=2, longitude=4), float flat(latitude=2, longitude=4)");
    EXPECT_EQ(errorOf<DataError>([&] { readNetCdfVariable(path, "u v flat"); }),
              path + ": variable 'flat' has 2 dimensions (float flat(latitude=2, longitude=4)); "
                     "texsplat reads 3-D variables (z, y, x) and 4-D ones (time, z, y, x)");
}

TEST(NetCdfVolume, theComponentsOfVectorsMustHaveTheSameDimensions) {
    REQUIRE_NCGEN();
    const std::string path = generate("mismatch", R"(netcdf mismatch {
dimensions:
    z = 1 ; y = 1 ; x = 2 ; x2 = 2 ;
variables:
    float u(z, y, x) ; float v(z, y, x) ; float w(z, y, x2) ;
}
)");
    EXPECT_EQ(errorOf<DataError>([&] { readNetCdfVariable(path, "u v w"); }),
              path + ": variables 'u', 'v', 'w': the components of vectors must have the same "
                     "dimensions, but float u(z=1, y=1, x=2) and float w(z=1, y=1, x2=2) differ");
}

// A NetCDF-4 file of 8 KB declares a variable of 4 GB in chunks never written: HDF5 reads them
// as fill values, which `texsplat info` allocated and converted (25.7 s, 3.97 GB) before "all
// voxels are NaN". What the file can hold is checked first.
TEST(NetCdfVolume, aNetCdf4VariableLargerThanItsFileCouldHoldIsRefusedBeforeReading) {
    REQUIRE_NCGEN();
    const std::string path = generate("fill", R"(netcdf fill {
dimensions:
    z = 1000 ; y = 1000 ; x = 1000 ;
variables:
    float v(z, y, x) ;
        v:_ChunkSizes = 100, 100, 100 ;
}
)", "nc4");
    const auto bytes = std::filesystem::file_size(path);
    ASSERT_LT(bytes, 100000u);
    const std::string expected =
        path + ": variable 'v': a step of 1000 x 1000 x 1000 values of 4 bytes (4000000000 "
               "bytes) cannot come from a file of " +
        std::to_string(bytes) + " bytes, which uncompressed holds at most " +
        std::to_string(bytes) +
        " bytes of values: the rest would be fill values, never written (empty voxels)";
    const std::uint64_t previous = setMemoryLimit(std::uint64_t{64} << 30);
    EXPECT_EQ(errorOf<DataError>([&] { readNetCdfVariable(path, "v"); }), expected);
    // info streams the values and needs no memory for the grid, but asks the same.
    EXPECT_EQ(errorOf<DataError>([&] { describeVolumeFile(path); }), expected);
    setMemoryLimit(previous);
}

TEST(NetCdfVolume, isASourceOfVolumeDataAndOfInfo) {
    REQUIRE_NCGEN();
    const std::string path = generate("series", kSeries);
    nodes::registerNodeTypes();
    const sg::Node::Ptr root = sg::SceneReader::readString(
        "#Inventor V2.1 ascii\nVolumeData { source FILE_NETCDF fileName \"" + path +
        "\" gridName \"w\" timeStep 1 }\n");
    const auto& volume = static_cast<const nodes::VolumeData&>(*root);
    EXPECT_EQ(volume.scalarGrid()->value({1, 0, 0}), 4.0f);

    const std::string info = describeVolumeFile(path, 2);
    EXPECT_EQ(info.substr(0, info.find("  values")),
              path + ": NetCDF, 3 variables\n"
                     "variable double time(time=2)\n"
                     "  coordinate of dimension 'time'\n"
                     "variable int w(time=2, z=1, y=1, x=2)\n"
                     "  time steps    2 along 'time' (VolumeData timeStep 0 to 1; step 0 below)\n");
    EXPECT_NE(info.find("  dimensions    2 x 1 x 1 voxels (x, y, z)\n"), std::string::npos)
        << info;
    EXPECT_NE(info.find("  value range   1 .. 2\n"), std::string::npos) << info;
    EXPECT_NE(info.find("  scene         VolumeData { source FILE_NETCDF fileName \"" + path +
                        "\" }\n"
                        "variable float flat(y=1, x=2)\n"
                        "  not readable: texsplat reads 3-D (z, y, x) and 4-D (time, z, y, x) "
                        "variables of numbers\n"),
              std::string::npos)
        << info;
}

TEST(NetCdfVolume, tellsTheActionsWorkProgressOfEachZSliceReadWhichMayCancel) {
    REQUIRE_NCGEN();
    const std::string path = generate("slices", R"(netcdf slices {
dimensions:
    z = 10 ; y = 1 ; x = 2 ;
variables:
    float v(z, y, x) ;
data:
    v = 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19 ;
}
)");
    const std::string step =
        "reading variable 'v' from " + std::filesystem::path(path).filename().string();
    const auto volume = nodes::VolumeData::create();
    volume->source.setValue(nodes::VolumeSource::FileNetCdf);
    volume->fileName = path;
    std::vector<double> fractions;
    const auto recording = [&](double cancelAt) {
        return [&fractions, &step, cancelAt](std::string_view told, double fraction) {
            EXPECT_EQ(told, step);
            fractions.push_back(fraction);
            return fraction < cancelAt;
        };
    };
    EXPECT_EQ(errorOf<sg::Cancelled>([&] { volume->load(recording(0.3)); }),
              "VolumeData: " + step + ": cancelled");
    EXPECT_EQ(fractions.size(), 4u); // 0, then after each of the slices 0, 1 and 2
    EXPECT_FALSE(volume->isLoaded());

    fractions.clear();
    volume->load(recording(2.0));
    ASSERT_EQ(fractions.size(), 11u);
    for (std::size_t slices = 0; slices <= 10; ++slices)
        EXPECT_DOUBLE_EQ(fractions[slices], double(slices) / 10.0);
    EXPECT_EQ(volume->scalarGrid()->value({1, 0, 9}), 19.0f);
}

#else

TEST(NetCdfVolume, saysWhenItIsNotBuiltIn) {
    EXPECT_FALSE(isNetCdfAvailable());
    EXPECT_EQ(errorOf<IoError>([] { readNetCdfVariable("a.nc", "v"); }),
              "a.nc: cannot read NetCDF files: texsplat was built without NetCDF "
              "(TEXSPLAT_WITH_NETCDF=OFF)");
}

#endif

} // namespace
} // namespace texsplat::volume
