#include "nodes/volume/VdbVolume.h"

#include "nodes/volume/SparseGrid.h"
#include "scenegraph/Error.h"
#include "scenegraph/Log.h"
#include "scenegraph/MemoryLimit.h"
#include "tests/scenegraph/TestFifo.h"

#include <gtest/gtest.h>

#ifdef TEXSPLAT_WITH_OPENVDB
#include "nodes/volume/detail/SourceSupport.h"
#include "nodes/volume/detail/VdbHeader.h"

#include <openvdb/openvdb.h>

#include <cmath>
#include <cstdint>
#include <iterator>
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
            (std::string("VdbVolumeTest_") + info->name() + "_" + name))
        .string();
}

openvdb::math::Transform::Ptr scaleTranslate(const openvdb::Vec3d& scale,
                                             const openvdb::Vec3d& translation) {
    openvdb::Mat4d matrix = openvdb::Mat4d::identity();
    matrix.preScale(scale);
    matrix.postTranslate(translation);
    return openvdb::math::Transform::createLinearTransform(matrix);
}

// A file written with OpenVDB's own API: the grids a reader meets in practice, and the ones it
// must refuse.
std::string writeTestFile() {
    openvdb::initialize();
    openvdb::GridPtrVec grids;

    auto density = openvdb::FloatGrid::create(0.0f);
    density->setName("density");
    density->setTransform(scaleTranslate({0.5, 1.0, 2.0}, {10.0, 20.0, 30.0}));
    auto densityAccessor = density->getAccessor();
    densityAccessor.setValue({-3, -2, -1}, 1.5f);
    densityAccessor.setValue({4, 5, 6}, 2.5f);
    densityAccessor.setValue({0, 0, 0}, std::numeric_limits<float>::quiet_NaN());
    densityAccessor.setValue({1, 1, 1}, std::numeric_limits<float>::infinity());
    grids.push_back(density);

    auto velocity = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
    velocity->setName("velocity");
    velocity->getAccessor().setValue({7, 8, 9}, openvdb::Vec3s(1.0f, 2.0f, 3.0f));
    velocity->getAccessor().setValue({8, 8, 9}, openvdb::Vec3s(-1.0f, 0.0f, 0.5f));
    grids.push_back(velocity);

    auto mask = openvdb::BoolGrid::create(false);
    mask->setName("mask");
    mask->getAccessor().setValue({0, 0, 0}, true);
    grids.push_back(mask);

    auto rotated = openvdb::FloatGrid::create(0.0f);
    rotated->setName("rotated");
    rotated->transform().postRotate(0.3, openvdb::math::Z_AXIS);
    rotated->getAccessor().setValue({0, 0, 0}, 1.0f);
    grids.push_back(rotated);

    auto empty = openvdb::FloatGrid::create(0.0f);
    empty->setName("empty");
    grids.push_back(empty);

    const std::string path = testPath("grids.vdb");
    openvdb::io::File(path).write(grids);
    return path;
}

template <typename Exception, typename Function>
std::string errorOf(Function function) {
    try {
        function();
    } catch (const Exception& error) {
        return error.what();
    }
    return "no such error";
}

TEST(VdbVolume, listsTheGridsOfAFile) {
    ASSERT_TRUE(isOpenVdbAvailable());
    const std::vector<VdbGridInfo> infos = listVdbGrids(writeTestFile());
    ASSERT_EQ(infos.size(), 5u); // OpenVDB lists them by name
    EXPECT_EQ(infos[0].name, "density");
    EXPECT_EQ(infos[0].valueType, "float");
    EXPECT_EQ(infos[2].name, "mask");
    EXPECT_EQ(infos[2].valueType, "bool");
    EXPECT_EQ(infos[4].name, "velocity");
    EXPECT_EQ(infos[4].valueType, "vec3s");
}

TEST(VdbVolume, readsAFloatGridByNameWithItsTransform) {
    const std::string path = writeTestFile();
    std::vector<std::string> warnings;
    const LogSink previous = setLogSink([&](LogLevel level, std::string_view message) {
        if (level == LogLevel::Warning)
            warnings.emplace_back(message);
    });
    const ScalarGridPtr grid = std::get<ScalarGridPtr>(readVdbGrid(path, "density"));
    setLogSink(previous);

    // Active bounding box (-3,-2,-1)..(4,5,6): voxel (0,0,0) is OpenVDB's (-3,-2,-1).
    EXPECT_EQ(grid->geometry(), GridGeometry({8, 8, 8}, {8.5, 18.0, 28.0}, {0.5, 1.0, 2.0}));
    EXPECT_EQ(grid->value({0, 0, 0}), 1.5f);
    EXPECT_EQ(grid->value({7, 7, 7}), 2.5f);
    EXPECT_EQ(grid->value({1, 1, 1}), 0.0f);
    EXPECT_FALSE(grid->isActive({3, 2, 1})) << "NaN is empty";
    // The voxels lie in two OpenVDB leaves, (-8,-8,-8) and (0,0,0): two blocks, not more.
    EXPECT_EQ(dynamic_cast<const SparseScalarGrid&>(*grid).blockCount(), 2u);
    const GridStatistics statistics = grid->statistics();
    EXPECT_EQ(statistics.finiteCount, 2);
    EXPECT_EQ(statistics.nonFiniteCount, 2);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], path + ": grid 'density': 2 voxels are NaN or infinite; treated as "
                                  "empty");
}

TEST(VdbVolume, readsAVectorGrid) {
    const VectorGridPtr grid = std::get<VectorGridPtr>(readVdbGrid(writeTestFile(), "velocity"));
    EXPECT_EQ(grid->geometry(), GridGeometry({2, 1, 1}, {7.0, 8.0, 9.0}));
    EXPECT_EQ(grid->value({0, 0, 0}), glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(grid->value({1, 0, 0}), glm::vec3(-1.0f, 0.0f, 0.5f));
}

TEST(VdbVolume, sparseGridsStaySparseInMemory) {
    openvdb::initialize();
    auto grid = openvdb::FloatGrid::create(0.0f);
    grid->setName("sparse");
    auto accessor = grid->getAccessor();
    for (int i = 0; i < 1000; ++i) // a diagonal through a 1000^3 box: 4 GB if it were dense
        accessor.setValue({i, i, i}, float(i));
    // An active tile: one value for a whole 8^3 leaf, expanded into 512 voxels.
    grid->tree().addTile(1, openvdb::Coord(64, 0, 0), 7.0f, true);
    const std::string path = testPath("sparse.vdb");
    openvdb::io::File(path).write({grid});

    std::vector<double> fractions;
    std::vector<std::string> messages;
    const AnyGrid any = readVdbGrid(path, "sparse", [&](double fraction, std::string_view text) {
        fractions.push_back(fraction);
        if (messages.empty() || messages.back() != text)
            messages.emplace_back(text);
        return true;
    });
    const auto& sparse = dynamic_cast<const SparseScalarGrid&>(*std::get<ScalarGridPtr>(any));
    EXPECT_EQ(sparse.geometry().dims(), glm::i64vec3(1000, 1000, 1000));
    EXPECT_EQ(sparse.activeVoxelCount(), 1000 + 512);
    EXPECT_EQ(sparse.blockCount(), 125u + 1u) << "one block per OpenVDB leaf";
    EXPECT_LT(sparse.memoryBytes(), std::size_t{1} << 20);
    EXPECT_EQ(sparse.value({999, 999, 999}), 999.0f);
    EXPECT_EQ(sparse.value({70, 7, 7}), 7.0f);
    EXPECT_EQ(sparse.value({70, 8, 7}), 0.0f);
    EXPECT_EQ(fractions.front(), 0.0);
    EXPECT_EQ(fractions.back(), 1.0);
    // OpenVDB's own read of the grid comes first, then the copy into blocks.
    EXPECT_EQ(messages,
              (std::vector<std::string>{"reading grid 'sparse'", "copying grid 'sparse'"}));

    EXPECT_EQ(errorOf<LoadCancelled>([&] {
                  readVdbGrid(path, "sparse", [](double, std::string_view) { return false; });
              }),
              path + ": loading cancelled");
}

// Leaves are copied a block at a time (OpenVDB orders a leaf z fastest, a block x fastest), with
// the active bounding box not on a leaf boundary: every active voxel, and only those, at its
// place, compared with OpenVDB's own iteration.
TEST(VdbVolume, copiesEveryActiveVoxelOfItsLeavesInPlace) {
    openvdb::initialize();
    auto source = openvdb::FloatGrid::create(-1.0f);
    source->setName("scattered");
    auto accessor = source->getAccessor();
    const auto valueAt = [](const openvdb::Coord& c) {
        return static_cast<float>(c.x() + 64 * c.y() + 4096 * c.z());
    };
    for (int i = 0; i < 3000; ++i) { // a fixed scatter, 3 to 43 along x, 2 to 40 along y, z
        const openvdb::Coord c(3 + (i * 7) % 41, 2 + (i * 13) % 39, -5 + (i * 29) % 45);
        accessor.setValue(c, valueAt(c));
    }
    accessor.setValueOff(openvdb::Coord(3 + 7 % 41, 2 + 13 % 39, -5 + 29 % 45)); // stored, off
    const std::string path = testPath("scattered.vdb");
    openvdb::io::File(path).write({source});

    const auto grid = std::get<ScalarGridPtr>(readVdbGrid(path, "scattered"));
    const openvdb::CoordBBox box = source->evalActiveVoxelBoundingBox();
    const glm::i64vec3 low(box.min().x(), box.min().y(), box.min().z());
    std::int64_t active = 0;
    std::int64_t misplaced = 0;
    for (auto on = source->tree().cbeginValueOn(); on; ++on) {
        const openvdb::Coord c = on.getCoord();
        const glm::i64vec3 index = glm::i64vec3(c.x(), c.y(), c.z()) - low;
        ++active;
        misplaced += grid->isActive(index) && grid->value(index) == *on ? 0 : 1;
    }
    EXPECT_GT(active, 1500);
    EXPECT_EQ(misplaced, 0);
    EXPECT_EQ(grid->statistics().finiteCount, active) << "no voxel active that OpenVDB's is not";
}

TEST(VdbVolume, aTileOfManyBlocksBecomesThoseBlocks) {
    openvdb::initialize();
    auto source = openvdb::FloatGrid::create(0.0f);
    source->setName("tiled");
    source->tree().addTile(2, openvdb::Coord(128, 0, -128), 3.0f, true); // 128^3 voxels
    source->tree().setValue(openvdb::Coord(100, 5, 7), 2.0f);            // and one leaf's voxel
    const std::string path = testPath("tiled.vdb");
    openvdb::io::File(path).write({source});

    const auto grid = std::get<ScalarGridPtr>(readVdbGrid(path, "tiled"));
    const auto& sparse = dynamic_cast<const SparseScalarGrid&>(*grid);
    EXPECT_EQ(sparse.activeVoxelCount(), 128 * 128 * 128 + 1);
    EXPECT_EQ(sparse.blockCount(), 16u * 16u * 16u + 1u);
    // Voxel (0, 0, 0) is OpenVDB's (100, 0, -128).
    const glm::i64vec3 low(100, 0, -128);
    for (const glm::i64vec3 corner : {glm::i64vec3(128, 0, -128), glm::i64vec3(255, 127, -1),
                                      glm::i64vec3(200, 64, -64)}) {
        EXPECT_TRUE(grid->isActive(corner - low));
        EXPECT_EQ(grid->value(corner - low), 3.0f);
    }
    EXPECT_FALSE(grid->isActive(glm::i64vec3(127, 0, -128) - low));
    EXPECT_EQ(grid->value(glm::i64vec3(100, 5, 7) - low), 2.0f);
}

TEST(VdbVolume, reportsWrongNamesTypesAndTransforms) {
    const std::string path = writeTestFile();
    EXPECT_EQ(errorOf<DataError>([&] { readVdbGrid(path, "pressure"); }),
              path + ": no grid named 'pressure'; the file has: density (float), empty "
                     "(float), mask (bool), rotated (float), velocity (vec3s)");
    EXPECT_EQ(errorOf<DataError>([&] { readVdbGrid(path, "mask"); }),
              path + ": grid 'mask' holds bool values; expected float or vec3s");
    EXPECT_EQ(errorOf<DataError>([&] { readVdbGrid(path, "rotated"); }),
              path + ": grid 'rotated' has a rotated, sheared, mirrored or non-linear "
                     "transform; only axis-aligned scale and translation are supported");
    EXPECT_EQ(errorOf<DataError>([&] { readVdbGrid(path, "empty"); }),
              path + ": grid 'empty' has no active voxels");
}

TEST(VdbVolume, refusesAGridWhoseActiveVoxelsAreAllNanOrInfinite) {
    openvdb::initialize();
    auto fog = openvdb::FloatGrid::create(0.0f);
    fog->setName("fog");
    fog->getAccessor().setValue({0, 0, 0}, std::numeric_limits<float>::quiet_NaN());
    fog->getAccessor().setValue({100, 0, 0}, -std::numeric_limits<float>::infinity());
    // An active tile of NaN: 512 more voxels, none finite.
    fog->tree().addTile(1, openvdb::Coord(64, 0, 0), std::numeric_limits<float>::quiet_NaN(),
                        true);
    auto wind = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
    wind->setName("wind");
    wind->getAccessor().setValue({1, 2, 3}, openvdb::Vec3s(1.0f, std::nanf(""), 0.0f));
    const std::string path = testPath("nan.vdb");
    openvdb::io::File(path).write({fog, wind});
    EXPECT_EQ(errorOf<DataError>([&] { readVdbGrid(path, "fog"); }),
              path + ": grid 'fog': all 514 voxels are NaN or infinite; nothing to draw");
    EXPECT_EQ(errorOf<DataError>([&] { readVdbGrid(path, "wind"); }),
              path + ": grid 'wind': its only voxel is NaN or infinite; nothing to draw");
}

TEST(VdbVolume, reportsMissingAndForeignFiles) {
    const std::string missing = testPath("missing.vdb");
    EXPECT_EQ(errorOf<IoError>([&] { readVdbGrid(missing, "density"); }),
              missing + ": cannot open file (No such file or directory)");
    const std::string foreign = testPath("foreign.vdb");
    std::ofstream(foreign) << "texsplat-raw 1\n";
    EXPECT_EQ(errorOf<IoError>([&] { listVdbGrids(foreign); }),
              foreign + ": cannot read OpenVDB file (IoError: not a VDB file)");
}

TEST(VdbVolume, refusesATileTooLargeForMemoryBeforeCopyingIt) {
    // One active root tile: 4096^3 voxels in a file of a few hundred bytes.
    openvdb::initialize();
    auto bomb = openvdb::FloatGrid::create(0.0f);
    bomb->setName("density");
    bomb->tree().addTile(3, openvdb::Coord(0), 1.0f, true);
    const std::string path = testPath("bomb.vdb");
    openvdb::io::File(path).write({bomb});
    ASSERT_LT(std::filesystem::file_size(path), 1000u);
    const std::uint64_t voxels = std::uint64_t{1} << 36;
    // OpenVDB's tree (its root's one tile) is held while the voxels are copied.
    const std::uint64_t bytes = SparseGrid<float>::memoryBytesForBlocks(voxels / 512) +
                                detail::checkVdbDeclaredSizes(path).find("density")->bytes;
    ASSERT_GT(bytes, memoryLimit()) << "this machine could copy the tile";
    EXPECT_EQ(errorOf<ResourceError>([&] { readVdbGrid(path, "density"); }),
              path + ": grid 'density': copying its 68719476736 active voxels (tiles included) "
                     "would need " + bytesText(bytes) + ", more than the memory limit of " +
                  bytesText(memoryLimit()) +
                  "; use a volume of lower resolution, or a larger --memory-limit");
}

TEST(VdbVolume, wrapsWhatOpenVdbThrowsForATruncatedFileWithTheFileName) {
    const std::string valid = writeTestFile();
    const auto size = std::filesystem::file_size(valid);
    std::ifstream in(valid, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const std::string path = testPath("truncated.vdb");
    const auto cut = [&](std::size_t length) {
        std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes.substr(0, length);
        return errorOf<IoError>([&] {
            for (const VdbGridInfo& info : listVdbGrids(path))
                readVdbGrid(path, info.name);
        });
    };
    // Cut in the last grid's transform: OpenVDB read a map type name from bytes that were not
    // there, "internal error: KeyError ...", naming no file. The walk of the file before OpenVDB
    // opens it finds that the grid ends beyond the file.
    const std::string transform = cut(size - 50);
    EXPECT_EQ(transform.rfind(path + ": truncated or corrupt VDB file: grid 'empty': its "
                                     "descriptor places it from byte ", 0),
              0u)
        << transform;
    EXPECT_NE(transform.find(", but the file ends at byte " + std::to_string(size - 50)),
              std::string::npos)
        << transform;
    // Cut in the middle: OpenVDB quoted kilobytes of what it took for a grid type ("Cannot read
    // grid. Grid type ..."); the walk stops at the grid that the cut falls in.
    const std::string middle = cut(size / 2);
    EXPECT_EQ(middle.rfind(path + ": truncated or corrupt VDB file: grid '", 0), 0u) << middle;
    EXPECT_LT(middle.size(), path.size() + 200) << middle;
}

TEST(VdbVolume, sizesInTheHeaderAreCheckedAgainstTheFileBeforeOpenVdbAllocates) {
    // Found by fuzz_vdb_reader: a damaged string length made OpenVDB allocate and fill 2.7 GB
    // while opening a 10 KB file.
    const std::string valid = writeTestFile();
    std::ifstream in(valid, std::ios::binary);
    std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    // The header (magic 8, version 4, library version 8, offsets flag 1, UUID 36), no file
    // metadata (4), the grid count (4), then the first grid's name: its length, then "density".
    ASSERT_EQ(bytes.substr(65, 11), std::string("\x07\0\0\0density", 11));
    bytes.replace(65, 4, "\xe2\xe2\xe2\xe2");
    const std::string path = testPath("damaged.vdb");
    std::ofstream(path, std::ios::binary) << bytes;
    EXPECT_EQ(errorOf<IoError>([&] { listVdbGrids(path); }),
              path + ": truncated or corrupt VDB file: a grid's name at byte 69 needs 3806520034 "
                     "bytes, but the file ends at byte " + std::to_string(bytes.size()));
    EXPECT_EQ(errorOf<IoError>([&] { readVdbGrid(path, "density"); }),
              path + ": truncated or corrupt VDB file: a grid's name at byte 69 needs 3806520034 "
                     "bytes, but the file ends at byte " + std::to_string(bytes.size()));
}

// A float grid of `count`^3 voxels with values that do not compress, so that the file holds
// about 4 count^3 bytes of it.
openvdb::FloatGrid::Ptr incompressible(int count) {
    auto grid = openvdb::FloatGrid::create(0.0f);
    auto accessor = grid->getAccessor();
    std::uint32_t random = 1;
    for (int z = 0; z < count; ++z)
        for (int y = 0; y < count; ++y)
            for (int x = 0; x < count; ++x) {
                random = random * 1664525u + 1013904223u;
                accessor.setValue({x, y, z}, static_cast<float>(random >> 8) + 1.0f);
            }
    return grid;
}

TEST(VdbVolume, reportsTheBytesOpenVdbReadsAndStopsItWhenCancelled) {
    openvdb::initialize();
    auto density = incompressible(96); // about 3.4 MiB
    density->setName("density");
    const std::string path = testPath("big.vdb");
    openvdb::io::File(path).write({density});
    std::vector<double> fractions;
    readVdbGrid(path, "density", [&fractions](double fraction, std::string_view message) {
        if (message == "reading grid 'density'")
            fractions.push_back(fraction);
        return true;
    });
    // 0, once per MiB read, then 1.
    ASSERT_EQ(fractions.size(), 5u);
    EXPECT_EQ(fractions.front(), 0.0);
    EXPECT_EQ(fractions.back(), 1.0);
    for (std::size_t i = 1; i < fractions.size(); ++i)
        EXPECT_GT(fractions[i], fractions[i - 1]) << i;

    // Cancelled from inside OpenVDB's read: the exception leaves it (ASan: nothing leaks).
    EXPECT_EQ(errorOf<LoadCancelled>([&] {
                  readVdbGrid(path, "density", [&](double fraction, std::string_view message) {
                      return message != "reading grid 'density'" || fraction < 0.3;
                  });
              }),
              path + ": loading cancelled");
    const ScalarGridPtr grid = std::get<ScalarGridPtr>(readVdbGrid(path, "density"));
    EXPECT_EQ(grid->statistics().finiteCount, 96 * 96 * 96);
}

TEST(VdbVolume, readsTheGridOfARepeatedNameThatOpenVdbWouldRead) {
    openvdb::initialize();
    auto first = openvdb::FloatGrid::create(0.0f);
    first->setName("density");
    first->getAccessor().setValue({0, 0, 0}, 1.0f);
    auto second = openvdb::FloatGrid::create(0.0f);
    second->setName("density");
    second->getAccessor().setValue({0, 0, 0}, 2.0f);
    const std::string path = testPath("twice.vdb");
    openvdb::io::File(path).write({first, second});
    EXPECT_EQ(std::get<ScalarGridPtr>(readVdbGrid(path, "density"))->value({0, 0, 0}), 1.0f);
    EXPECT_EQ(std::get<ScalarGridPtr>(readVdbGrid(path, "density[1]"))->value({0, 0, 0}), 2.0f);
}

TEST(VdbVolume, refusesAFifoBeforeOpeningIt) {
    const texsplat::test::TestFifo pipe(testPath("grids.vdb"));
    const std::string& fifo = pipe.path();
    EXPECT_EQ(errorOf<IoError>([&] { listVdbGrids(fifo); }),
              fifo + ": cannot read file: it is a FIFO, not a regular file");
}

} // namespace
} // namespace texsplat::volume
#endif
