#include "nodes/volume/RawVolume.h"

#include "nodes/volume/DenseGrid.h"
#include "scenegraph/Error.h"
#include "scenegraph/Log.h"
#include "tests/scenegraph/TestFifo.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace texsplat::volume {
namespace {

std::string testPath(const std::string& name) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return (std::filesystem::path(::testing::TempDir()) /
            (std::string("RawVolumeTest_") + info->name() + "_" + name))
        .string();
}

// Writes `header` followed by the bytes of `values` as they lie in memory, optionally reversed
// per value (to produce the other byte order).
template <typename Value>
std::string writeFile(const std::string& name, const std::string& header,
                      const std::vector<Value>& values, bool reverseBytes = false) {
    const std::string path = testPath(name);
    std::ofstream out(path, std::ios::binary);
    out << header;
    for (const Value& value : values) {
        char bytes[sizeof(Value)];
        std::memcpy(bytes, &value, sizeof(Value));
        if (reverseBytes)
            std::reverse(bytes, bytes + sizeof(Value));
        out.write(bytes, sizeof(Value));
    }
    return path;
}

std::string header(const std::string& dims, const std::string& type, int components = 1,
                   const std::string& endian = "little") {
    return "texsplat-raw 1\ndims " + dims + "\ntype " + type + "\ncomponents " +
           std::to_string(components) + "\nspacing 1 2 3\norigin 10 20 30\nendian " + endian +
           "\ndata\n";
}

ScalarGridPtr readScalar(const std::string& path) {
    return std::get<ScalarGridPtr>(readRawVolume(path));
}

template <typename Exception>
std::string errorOf(const std::string& path) {
    try {
        readRawVolume(path);
    } catch (const Exception& error) {
        return error.what();
    }
    return "no such error";
}

TEST(RawVolume, readsFloat32Scalars) {
    const std::vector<float> values = {0.5f, -1.0f, 2.0f, 3.0f, 4.0f, 5.0f};
    const ScalarGridPtr grid = readScalar(writeFile("f32.raw", header("3 2 1", "float32"), values));
    EXPECT_EQ(grid->geometry(), GridGeometry({3, 2, 1}, {10.0, 20.0, 30.0}, {1.0, 2.0, 3.0}));
    EXPECT_EQ(grid->value({0, 0, 0}), 0.5f);
    EXPECT_EQ(grid->value({1, 0, 0}), -1.0f);
    EXPECT_EQ(grid->value({2, 1, 0}), 5.0f);
}

TEST(RawVolume, readsFloat64BigEndian) {
    const std::vector<double> values = {1.25, -2.5, 1e-3, 6.0};
    const ScalarGridPtr grid =
        readScalar(writeFile("f64.raw", header("2 2 1", "float64", 1, "big"), values, true));
    EXPECT_EQ(grid->value({0, 0, 0}), 1.25f);
    EXPECT_EQ(grid->value({1, 0, 0}), -2.5f);
    EXPECT_EQ(grid->value({0, 1, 0}), 1e-3f);
    EXPECT_EQ(grid->value({1, 1, 0}), 6.0f);
}

TEST(RawVolume, readsUInt8AsIs) {
    const std::vector<std::uint8_t> values = {0, 1, 128, 255};
    const ScalarGridPtr grid = readScalar(writeFile("u8.raw", header("1 1 4", "uint8"), values));
    EXPECT_EQ(grid->value({0, 0, 0}), 0.0f);
    EXPECT_EQ(grid->value({0, 0, 2}), 128.0f);
    EXPECT_EQ(grid->value({0, 0, 3}), 255.0f);
}

TEST(RawVolume, readsUInt16BothEndians) {
    const std::vector<std::uint16_t> values = {1, 258, 65535, 4096};
    for (const bool big : {false, true}) {
        const ScalarGridPtr grid = readScalar(writeFile(
            big ? "u16be.raw" : "u16le.raw", header("4 1 1", "uint16", 1, big ? "big" : "little"),
            values, big));
        EXPECT_EQ(grid->value({1, 0, 0}), 258.0f) << (big ? "big" : "little");
        EXPECT_EQ(grid->value({2, 0, 0}), 65535.0f);
    }
}

TEST(RawVolume, readsThreeComponentsAsVectors) {
    const std::vector<float> values = {1, 2, 3, 4, 5, 6};
    const AnyGrid any = readRawVolume(writeFile("vec.raw", header("2 1 1", "float32", 3), values));
    const VectorGridPtr grid = std::get<VectorGridPtr>(any);
    EXPECT_EQ(grid->value({0, 0, 0}), glm::vec3(1, 2, 3));
    EXPECT_EQ(grid->value({1, 0, 0}), glm::vec3(4, 5, 6));
}

TEST(RawVolume, writeThenReadRoundTrips) {
    DenseVectorGrid vectors(GridGeometry({3, 2, 2}, {-1.0, 0.5, 2.0}, {0.1, 0.2, 0.3}));
    for (std::int64_t i = 0; i < 12; ++i)
        vectors.values()[static_cast<std::size_t>(i)] = glm::vec3(float(i), -float(i), 0.5f);
    const std::string path = testPath("roundtrip.raw");
    writeRawVolume(path, vectors);
    EXPECT_FALSE(std::filesystem::exists(path + ".partial"));
    const VectorGridPtr back = std::get<VectorGridPtr>(readRawVolume(path));
    EXPECT_EQ(back->geometry(), vectors.geometry());
    EXPECT_EQ(dynamic_cast<const DenseVectorGrid&>(*back).values(), vectors.values());
}

TEST(RawVolume, largeReadReportsProgressAndCanBeCancelled) {
    // 2^21 floats = 8 MiB: two 4 MiB chunks.
    const std::vector<float> values(std::size_t{1} << 21, 1.0f);
    const std::string path = writeFile("large.raw", header("128 128 128", "float32"), values);
    std::vector<double> fractions;
    readRawVolume(path, [&](double fraction, std::string_view message) {
        fractions.push_back(fraction);
        EXPECT_EQ(message, "reading");
        return true;
    });
    EXPECT_EQ(fractions, (std::vector<double>{0.0, 0.5, 1.0}));
    try {
        readRawVolume(path, [](double fraction, std::string_view) { return fraction < 0.5; });
        FAIL() << "not cancelled";
    } catch (const LoadCancelled& error) {
        EXPECT_EQ(std::string(error.what()), path + ": loading cancelled");
    }
    std::filesystem::remove(path);
}

TEST(RawVolume, nonFiniteVoxelsAreEmptyAndWarnedAboutOnce) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const std::string path =
        writeFile("nan.raw", header("5 1 1", "float32"), std::vector<float>{1, nan, inf, -inf, 2});
    std::vector<std::string> warnings;
    const LogSink previous = setLogSink([&](LogLevel level, std::string_view message) {
        if (level == LogLevel::Warning)
            warnings.emplace_back(message);
    });
    const ScalarGridPtr grid = readScalar(path);
    setLogSink(previous);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], path + ": 3 voxels are NaN or infinite; treated as empty");
    EXPECT_EQ(grid->statistics().nonFiniteCount, 3);
    EXPECT_EQ(grid->statistics().finiteCount, 2);
    EXPECT_FALSE(grid->isActive({1, 0, 0}));
    EXPECT_EQ(grid->value({2, 0, 0}), 0.0f);
}

TEST(RawVolume, refusesAGridWithNoFiniteVoxel) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const std::string scalars =
        writeFile("nan.raw", header("2 2 1", "float32"), std::vector<float>{nan, inf, -inf, nan});
    EXPECT_EQ(errorOf<DataError>(scalars),
              scalars + ": all 4 voxels are NaN or infinite; nothing to draw");
    // A vector is empty when any of its components is not finite.
    const std::string vectors = writeFile("nanvec.raw", header("2 1 1", "float64", 3),
                                          std::vector<double>{1, 2, nan, inf, 0, 0});
    EXPECT_EQ(errorOf<DataError>(vectors),
              vectors + ": all 2 voxels are NaN or infinite; nothing to draw");
    // float64 beyond the float range becomes infinite, hence empty.
    const std::string one = writeFile("huge.raw", header("1 1 1", "float64"),
                                      std::vector<double>{1e300});
    EXPECT_EQ(errorOf<DataError>(one),
              one + ": its only voxel is NaN or infinite; nothing to draw");
}

TEST(RawVolume, reportsMissingFolderTruncatedAndOversizedFiles) {
    const std::string missing = testPath("missing.raw");
    EXPECT_EQ(errorOf<IoError>(missing),
              missing + ": cannot open file (No such file or directory)");
    const std::string folder = ::testing::TempDir();
    EXPECT_EQ(errorOf<IoError>(folder), folder + ": cannot open file (it is a folder)");

    const std::string truncated =
        writeFile("short.raw", header("4 4 4", "float32"), std::vector<float>(25, 1.0f));
    EXPECT_EQ(errorOf<DataError>(truncated),
              truncated + ": truncated data: the header asks for 4 x 4 x 4 voxels x 1 component "
                          "x 4 bytes (float32) = 256 bytes, but only 100 bytes follow it");
    const std::string oversized =
        writeFile("long.raw", header("2 2 2", "uint16", 3), std::vector<std::uint16_t>(25, 1));
    EXPECT_EQ(errorOf<DataError>(oversized),
              oversized + ": data size mismatch: the header asks for 2 x 2 x 2 voxels x 3 "
                          "components x 2 bytes (uint16) = 48 bytes, but 50 bytes follow it");
}

TEST(RawVolume, refusesFifosAndDevicesBeforeOpeningThem) {
    EXPECT_EQ(errorOf<IoError>("/dev/zero"),
              "/dev/zero: cannot read file: it is a character device, not a regular file");
    const texsplat::test::TestFifo pipe(testPath("data.raw"));
    const std::string& fifo = pipe.path();
    EXPECT_EQ(errorOf<IoError>(fifo),
              fifo + ": cannot read file: it is a FIFO, not a regular file");
    RawHeader layout;
    layout.dims = {4, 4, 4};
    try {
        readHeaderlessRawVolume(fifo, layout, 0);
        ADD_FAILURE() << "no error";
    } catch (const IoError& error) {
        EXPECT_EQ(std::string(error.what()),
                  fifo + ": cannot read file: it is a FIFO, not a regular file");
    }
}

TEST(RawVolume, reportsBadHeadersAndZeroSizeGrids) {
    const std::string bad =
        writeFile("bad.raw", "texsplat-raw 1\ndims 4 4\n", std::vector<float>{});
    EXPECT_EQ(errorOf<ParseError>(bad), bad + ":2:1: 'dims' takes 3 values, found 2");
    const std::string empty =
        writeFile("empty.raw", header("8 0 8", "float32"), std::vector<float>{});
    EXPECT_EQ(errorOf<DataError>(empty),
              empty + ":2:6: grid dimensions must be at least 1 voxel each, got 8 x 0 x 8");
}

RawHeader headerlessLayout(glm::i64vec3 dims, RawValueType type, int components = 1,
                           RawEndian endian = RawEndian::Little) {
    RawHeader layout;
    layout.dims = dims;
    layout.type = type;
    layout.components = components;
    layout.endian = endian;
    return layout;
}

TEST(RawVolume, readsHeaderlessFilesOfEveryTypeAndByteOrder) {
    const std::string skipped = "sixteen bytes...";
    const auto check = [&](auto values, RawValueType type, RawEndian endian) {
        const bool swap = endian == RawEndian::Big;
        const std::string path = writeFile(std::string(toString(type)) + (swap ? "be" : "le"),
                                           skipped, values, swap);
        const ScalarGridPtr grid = std::get<ScalarGridPtr>(
            readHeaderlessRawVolume(path, headerlessLayout({2, 1, 2}, type, 1, endian), 16));
        EXPECT_EQ(grid->geometry(), GridGeometry({2, 1, 2})) << toString(type);
        for (int k = 0; k < 2; ++k)
            for (int i = 0; i < 2; ++i)
                EXPECT_EQ(grid->value({i, 0, k}), float(values[std::size_t(i + 2 * k)]))
                    << toString(type) << " " << i << " " << k;
    };
    for (RawEndian endian : {RawEndian::Little, RawEndian::Big}) {
        check(std::vector<std::uint8_t>{0, 1, 200, 255}, RawValueType::UInt8, endian);
        check(std::vector<std::int8_t>{-128, -1, 0, 127}, RawValueType::Int8, endian);
        check(std::vector<std::uint16_t>{0, 1, 300, 65535}, RawValueType::UInt16, endian);
        check(std::vector<std::int16_t>{-32768, -2, 300, 32767}, RawValueType::Int16, endian);
        check(std::vector<std::uint32_t>{0, 7, 70000, 16777216}, RawValueType::UInt32, endian);
        check(std::vector<std::int32_t>{-16777216, -3, 70000, 5}, RawValueType::Int32, endian);
        check(std::vector<float>{-1.5f, 0.25f, 3e10f, 7.0f}, RawValueType::Float32, endian);
        check(std::vector<double>{-1.5, 0.25, 1e-3, 7.0}, RawValueType::Float64, endian);
    }
}

TEST(RawVolume, readsHeaderlessVectors) {
    const std::vector<float> values = {1, 2, 3, 4, 5, 6};
    const std::string path = writeFile("vectors.raw", "", values);
    const VectorGridPtr grid = std::get<VectorGridPtr>(
        readHeaderlessRawVolume(path, headerlessLayout({2, 1, 1}, RawValueType::Float32, 3), 0));
    EXPECT_EQ(grid->value({0, 0, 0}), glm::vec3(1, 2, 3));
    EXPECT_EQ(grid->value({1, 0, 0}), glm::vec3(4, 5, 6));
}

TEST(RawVolume, headerlessSizeMismatchNamesBothByteCounts) {
    const std::string path = writeFile("short.raw", "", std::vector<float>(60, 1.0f));
    const auto errorOfHeaderless = [&](const RawHeader& layout, std::int64_t headerBytes) {
        try {
            readHeaderlessRawVolume(path, layout, headerBytes);
        } catch (const DataError& error) {
            return std::string(error.what());
        }
        return std::string("no such error");
    };
    EXPECT_EQ(errorOfHeaderless(headerlessLayout({4, 4, 4}, RawValueType::Float32), 0),
              path + ": file size mismatch: the scene describes 4 x 4 x 4 voxels x 1 component x 4 "
                     "bytes (float32) = 256 bytes, plus 0 header bytes = 256 bytes, but the file "
                     "has 240 bytes");
    EXPECT_EQ(errorOfHeaderless(headerlessLayout({4, 4, 2}, RawValueType::UInt16, 3), 16),
              path + ": file size mismatch: the scene describes 4 x 4 x 2 voxels x 3 components x "
                     "2 bytes (uint16) = 192 bytes, plus 16 header bytes = 208 bytes, but the file "
                     "has 240 bytes");
    EXPECT_EQ(errorOfHeaderless(headerlessLayout({4, 4, 2}, RawValueType::UInt16, 3), -1),
              path + ": headerBytes must be 0 or more, got -1");
}

} // namespace
} // namespace texsplat::volume
