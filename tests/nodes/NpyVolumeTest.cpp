#include "nodes/volume/NpyVolume.h"

#include "SceneNodesTestSupport.h"
#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/RawVolume.h"
#include "scenegraph/Error.h"
#include "tests/scenegraph/TestFifo.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace texsplat::volume {
namespace {

using texsplat::nodes::test::testPath;

// The Python that has numpy: the one on PATH, else the system's (a Python of a version manager
// may come first on PATH without it); empty when none has.
const std::string& numpyPython() {
    static const std::string python = [] {
        for (const char* candidate : {"python3", "/usr/bin/python3"}) {
            const std::string check = std::string(candidate) + " -c 'import numpy' >/dev/null 2>&1";
            if (std::system(check.c_str()) == 0)
                return std::string(candidate);
        }
        return std::string();
    }();
    return python;
}

bool hasNumpy() { return !numpyPython().empty(); }

// Runs Python `code` with numpy imported as np and `path` bound to `path`; false on failure.
bool runNumpy(const std::string& code, const std::string& path) {
    const std::string command = numpyPython() + " -c \"import numpy as np; path = '" + path +
                                "'; " + code + "\"";
    return std::system(command.c_str()) == 0;
}

template <typename T>
void expectSameGrid(const Grid<T>& actual, const Grid<T>& expected) {
    ASSERT_EQ(actual.geometry(), expected.geometry());
    const glm::i64vec3 dims = expected.geometry().dims();
    for (std::int64_t z = 0; z < dims.z; ++z)
        for (std::int64_t y = 0; y < dims.y; ++y)
            for (std::int64_t x = 0; x < dims.x; ++x)
                ASSERT_EQ(actual.value({x, y, z}), expected.value({x, y, z}))
                    << x << " " << y << " " << z;
}

#define REQUIRE_NUMPY()                                                                        \
    if (!hasNumpy())                                                                           \
    GTEST_SKIP() << "numpy is not installed (python3-numpy); it writes the test's .npy files"

// Each array as numpy writes it equals the same values as texsplat-raw; a[z, y, x] is voxel
// (x, y, z), whatever the order and byte order in the file.
TEST(NpyVolume, readsScalarsAsNumpyWritesThemInEveryOrderAndType) {
    REQUIRE_NUMPY();
    // Value a[z, y, x] = x + 10 y + 100 z: every voxel tells where it came from.
    DenseScalarGrid expected(GridGeometry({4, 3, 2}));
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 4; ++x)
                expected.setValue({x, y, z}, float(x + 10 * y + 100 * z));
    const std::string raw = testPath("same.raw");
    writeRawVolume(raw, expected);
    ASSERT_NO_THROW(expectSameGrid(*std::get<ScalarGridPtr>(readRawVolume(raw)), expected));
    const char* const dtypes[] = {"<f4", ">f4", "<f8", ">f8", "|u1", "<u2", ">u2",
                                  "<i2", ">i2", "<i4", ">i4", "<u4", "|i1"};
    for (const char* dtype : dtypes) {
        for (const char* order : {"C", "F"}) {
            const std::string path = testPath(std::string(order) + ".npy");
            ASSERT_TRUE(runNumpy(std::string("z, y, x = np.mgrid[0:2, 0:3, 0:4]; ") +
                                     "a = np.array(x + 10 * y + 100 * z, dtype='" + dtype +
                                     "', order='" + order + "'); np.save(path, a)",
                                 path));
            const ScalarGridPtr grid = std::get<ScalarGridPtr>(readNpyVolume(path));
            SCOPED_TRACE(std::string(dtype) + " order " + order);
            expectSameGrid(*grid, expected);
        }
    }
}

TEST(NpyVolume, readsVectorsOfShapeZYX3) {
    REQUIRE_NUMPY();
    DenseVectorGrid expected(GridGeometry({3, 2, 2}));
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x)
                expected.setValue({x, y, z}, glm::vec3(x, 10 + y, 20 + z));
    for (const char* order : {"C", "F"}) {
        const std::string path = testPath(std::string(order) + ".npy");
        ASSERT_TRUE(runNumpy(std::string("z, y, x = np.mgrid[0:2, 0:2, 0:3]; ") +
                                 "a = np.stack([x, 10 + y, 20 + z], axis=-1).astype('<f4'); "
                                 "np.save(path, np.asarray(a, order='" + order + "'))",
                             path));
        SCOPED_TRACE(order);
        expectSameGrid(*std::get<VectorGridPtr>(readNpyVolume(path)), expected);
    }
}

TEST(NpyVolume, refusesDataOfTheWrongSize) {
    REQUIRE_NUMPY();
    const std::string path = testPath("short.npy");
    ASSERT_TRUE(runNumpy("np.save(path, np.zeros((2, 3, 4), dtype='<f4'))", path));
    std::filesystem::resize_file(path, std::filesystem::file_size(path) - 8);
    try {
        readNpyVolume(path);
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_EQ(std::string(error.what()),
                  path + ": truncated data: the header's shape (2, 3, 4) of '<f4' asks for 96 "
                         "bytes, but only 88 bytes follow it");
    }
    std::filesystem::resize_file(path, std::filesystem::file_size(path) + 9);
    try {
        readNpyVolume(path);
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_EQ(std::string(error.what()),
                  path + ": data size mismatch: the header's shape (2, 3, 4) of '<f4' asks for 96 "
                         "bytes, but 97 bytes follow it");
    }
}

TEST(NpyVolume, aFileThatIsNotNpyGetsTheFormatNamed) {
    const std::string path = testPath("not.npy");
    std::ofstream(path, std::ios::binary) << std::string("\x00\x01\xfe\xff binary", 11);
    try {
        readNpyVolume(path);
        FAIL() << "no error";
    } catch (const ParseError& error) {
        EXPECT_EQ(std::string(error.what()),
                  path + ": not a NumPy .npy file: expected it to start with the bytes \\x93NUMPY "
                         "and a format version");
    }
}

TEST(NpyVolume, refusesAFifoBeforeOpeningIt) {
    const texsplat::test::TestFifo pipe(testPath("data.npy"));
    const std::string& fifo = pipe.path();
    try {
        readNpyVolume(fifo);
        ADD_FAILURE() << "no error";
    } catch (const IoError& error) {
        EXPECT_EQ(std::string(error.what()),
                  fifo + ": cannot read file: it is a FIFO, not a regular file");
    }
}

} // namespace
} // namespace texsplat::volume
