// The walk of an OpenVDB file's trees before OpenVDB reads them (nodes/volume/detail/VdbTree.h,
// VdbHeader.h), through the reader that runs it: every valid kind of file passes, and a damaged
// count or size is refused, located, before OpenVDB allocates or loops for it.

#include "nodes/volume/VdbVolume.h"

#include "SceneNodesTestSupport.h"
#include "nodes/volume/SparseGrid.h"
#include "scenegraph/Error.h"
#include "scenegraph/MemoryLimit.h"
#include "tests/scenegraph/ScopedMemoryLimit.h"

#include <gtest/gtest.h>

#ifdef TEXSPLAT_WITH_OPENVDB
#include "nodes/volume/detail/VdbHeader.h"

#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

namespace texsplat::volume {
namespace {

using nodes::test::errorOf;
using nodes::test::testPath;
using test::ScopedMemoryLimit;

std::string contents(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string save(const std::string& name, const std::string& bytes) {
    const std::string path = testPath(name);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    return path;
}

std::int64_t int64At(const std::string& bytes, std::size_t offset) {
    std::int64_t value;
    std::memcpy(&value, bytes.data() + offset, sizeof value);
    return value;
}

void setInt64At(std::string& bytes, std::size_t offset, std::int64_t value) {
    std::memcpy(bytes.data() + offset, &value, sizeof value);
}

// A float grid named "density" of one leaf, all of whose 512 voxels are active and differ, so
// that zip and blosc compress its block; the file ends with that block.
openvdb::FloatGrid::Ptr denseLeaf(float background = 0.0f) {
    openvdb::initialize();
    auto grid = openvdb::FloatGrid::create(background);
    grid->setName("density");
    auto accessor = grid->getAccessor();
    for (int i = 0; i < 512; ++i)
        accessor.setValue({i / 64, i / 8 % 8, i % 8}, 1.0f + float(i % 7) * 0.25f);
    return grid;
}

std::string writeFile(const std::string& name, const openvdb::GridPtrVec& grids,
                      std::uint32_t compression) {
    const std::string path = testPath(name);
    openvdb::io::File file(path);
    file.setCompression(compression);
    file.write(grids);
    return path;
}

// Where the size of the file's last block is: the 8 bytes after which the block fills the file.
std::size_t lastBlockSizeAt(const std::string& bytes) {
    for (std::size_t at = bytes.size() - 8; at > 0; --at)
        if (int64At(bytes, at) == std::int64_t(bytes.size() - at - 8))
            return at;
    ADD_FAILURE() << "no block fills the end of the file";
    return 0;
}

template <typename Function> std::string ioErrorOf(Function function) {
    try {
        function();
    } catch (const IoError& error) {
        return error.what();
    }
    return "no IoError";
}

std::string readEveryGrid(const std::string& path) {
    return ioErrorOf([&] {
        for (const VdbGridInfo& info : listVdbGrids(path))
            readVdbGrid(path, info.name);
    });
}

TEST(VdbTree, everyKindOfValidFileIsReadAfterItsTreeIsWalked) {
    openvdb::initialize();
    // Values of every kind of node: root tiles, internal node tiles, leaves with one, two or
    // more inactive values (each a different flag before the node's values), negative
    // backgrounds; every value type OpenVDB stores as values, in full and as half floats.
    auto sparse = openvdb::FloatGrid::create(-2.0f);
    sparse->setName("sparse");
    sparse->tree().addTile(3, openvdb::Coord(4096), 1.0f, false);
    sparse->tree().addTile(2, openvdb::Coord(-4096), 2.0f, true);
    sparse->tree().addTile(1, openvdb::Coord(64, 0, 0), 3.0f, false);
    auto& tree = sparse->tree();
    tree.setValue({1, 2, 3}, 4.0f);
    tree.setValueOff({1, 2, 4}, 2.0f); // -background and +background: a selection mask
    tree.setValue({200, 2, 3}, 5.0f);
    tree.setValueOff({200, 2, 4}, 7.0f); // one other inactive value
    tree.setValue({300, 2, 3}, 5.0f);
    tree.setValueOff({300, 2, 4}, 7.0f); // two other inactive values
    tree.setValueOff({300, 2, 5}, 8.0f);
    tree.setValueOff({300, 2, 6}, 9.0f); // three: every value stored
    auto half = denseLeaf();
    half->setName("half");
    half->setSaveFloatAsHalf(true);
    auto velocity = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
    velocity->setName("velocity");
    velocity->tree().setValue({7, 8, 9}, openvdb::Vec3s(1.0f, 2.0f, 3.0f));
    auto halfVelocity = velocity->deepCopy();
    halfVelocity->setName("halfVelocity");
    halfVelocity->setSaveFloatAsHalf(true);
    auto shared = sparse->copyGrid(); // an instance: it shares the tree of "sparse"
    shared->setName("shared");
    auto wide = openvdb::DoubleGrid::create(0.0);
    wide->tree().setValue({1, 1, 1}, 2.0);
    auto counts = openvdb::Int32Grid::create(0);
    counts->tree().setValue({1, 1, 1}, 3);
    auto big = openvdb::Int64Grid::create(0);
    big->tree().setValue({1, 1, 1}, 3);
    auto vectors = openvdb::Vec3DGrid::create();
    vectors->tree().setValue({1, 1, 1}, openvdb::Vec3d(1.0));
    auto indices = openvdb::Vec3IGrid::create();
    indices->tree().setValue({1, 1, 1}, openvdb::Vec3i(1));
    auto mask = openvdb::BoolGrid::create(false);
    mask->tree().setValue({1, 1, 1}, true);
    auto topology = openvdb::MaskGrid::create();
    topology->tree().setValueOn({1, 1, 1});
    wide->setName("wide");
    counts->setName("counts");
    big->setName("big");
    vectors->setName("vectors");
    indices->setName("indices");
    mask->setName("mask");
    topology->setName("topology");
    const openvdb::GridPtrVec grids = {sparse, half,  velocity, halfVelocity, shared, wide,
                                       counts, big,   vectors,  indices,      mask,   topology};
    using openvdb::io::COMPRESS_ACTIVE_MASK;
    using openvdb::io::COMPRESS_BLOSC;
    using openvdb::io::COMPRESS_ZIP;
    for (const std::uint32_t compression :
         {0u, 0u + COMPRESS_ZIP, 0u + COMPRESS_ACTIVE_MASK,
          0u + COMPRESS_ZIP + COMPRESS_ACTIVE_MASK, 0u + COMPRESS_BLOSC,
          0u + COMPRESS_BLOSC + COMPRESS_ACTIVE_MASK}) {
        SCOPED_TRACE("compression " + std::to_string(compression));
        const std::string path = writeFile("grids.vdb", grids, compression);
        EXPECT_EQ(listVdbGrids(path).size(), grids.size());
        for (const char* name : {"sparse", "half", "velocity", "halfVelocity", "shared"})
            EXPECT_NO_THROW(readVdbGrid(path, name)) << name;
    }
    // A file written as a stream: OpenVDB reads its trees on opening it.
    const std::string streamed = testPath("streamed.vdb");
    {
        std::ofstream out(streamed, std::ios::binary);
        openvdb::io::Stream(out).write(openvdb::GridPtrVec{sparse, velocity, half});
    }
    EXPECT_EQ(readEveryGrid(streamed), "no IoError");
}

TEST(VdbTree, aCompressedBlockLargerThanTheRestOfTheFileIsRefused) {
    // Found by fuzz_vdb_reader: OpenVDB allocated what a damaged block size said (new char[2^56],
    // std::bad_alloc in a normal build, a crash under AddressSanitizer) before reading it.
    std::string bytes = contents(writeFile(
        "zip.vdb", {denseLeaf()}, openvdb::io::COMPRESS_ZIP | openvdb::io::COMPRESS_ACTIVE_MASK));
    const std::size_t at = lastBlockSizeAt(bytes);
    setInt64At(bytes, at, std::int64_t{1} << 56);
    const std::string path = save("damaged.vdb", bytes);
    const std::string expected = path + ": truncated or corrupt VDB file: grid 'density': a "
                                        "compressed block at byte " + std::to_string(at + 8) +
                                 " needs 72057594037927936 bytes, but the file ends at byte " +
                                 std::to_string(bytes.size());
    EXPECT_EQ(ioErrorOf([&] { listVdbGrids(path); }), expected);
    EXPECT_EQ(ioErrorOf([&] { readVdbGrid(path, "density"); }), expected);
}

TEST(VdbTree, anUncompressedBlockOfAnotherSizeThanItsNodeIsRefused) {
    // A block stored uncompressed says its size negated; OpenVDB reads that many bytes into the
    // node's buffer of 512 values before it compares the sizes.
    std::string bytes = contents(writeFile(
        "zip.vdb", {denseLeaf()}, openvdb::io::COMPRESS_ZIP | openvdb::io::COMPRESS_ACTIVE_MASK));
    const std::size_t at = lastBlockSizeAt(bytes);
    setInt64At(bytes, at, -4096);
    const std::string path = save("damaged.vdb", bytes);
    EXPECT_EQ(readEveryGrid(path),
              path + ": truncated or corrupt VDB file: grid 'density': an uncompressed block at "
                     "byte " + std::to_string(at) +
                  " declares 4096 bytes, but its node holds 2048");
}

TEST(VdbTree, aBloscBlockWhoseHeaderDisagreesWithItsSizeIsRefused) {
    // Blosc is given a block without its size: a header that says more makes it read beyond.
    std::string bytes = contents(writeFile(
        "blosc.vdb", {denseLeaf()},
        openvdb::io::COMPRESS_BLOSC | openvdb::io::COMPRESS_ACTIVE_MASK));
    const std::size_t at = lastBlockSizeAt(bytes);
    const std::int64_t size = int64At(bytes, at);
    bytes[at + 8 + 12 + 2] = '\x01'; // the compressed size in blosc's header: 65536 more
    const std::string path = save("damaged.vdb", bytes);
    EXPECT_EQ(readEveryGrid(path),
              path + ": truncated or corrupt VDB file: grid 'density': a blosc block at byte " +
                  std::to_string(at + 8) + " of " + std::to_string(size) +
                  " bytes says it holds " + std::to_string(size + 65536) +
                  " bytes compressed, 2048 uncompressed, where 2048 are expected");
}

TEST(VdbTree, aTileCountBeyondTheFileIsRefused) {
    // Found by fuzz_vdb_reader: a damaged count made OpenVDB's root loop over tiles and child
    // nodes at the end of the file for longer than the fuzzer's 10 s.
    constexpr float kBackground = 1.2345678e-7f;
    std::string bytes = contents(writeFile("tiles.vdb", {denseLeaf(kBackground)},
                                           openvdb::io::COMPRESS_ZIP));
    const std::string background(reinterpret_cast<const char*>(&kBackground), 4);
    const std::size_t at = bytes.find(background);
    ASSERT_NE(at, std::string::npos);
    ASSERT_EQ(bytes.find(background, at + 1), std::string::npos);
    bytes.replace(at + 4, 4, "\xe2\xe2\xe2\xe2"); // the root's tile count
    std::string path = save("tiles.vdb", bytes);
    EXPECT_EQ(readEveryGrid(path),
              path + ": truncated or corrupt VDB file: grid 'density': the root's tiles at byte " +
                  std::to_string(at + 12) +
                  " declares 3806520034 items of at least 17 bytes, but the file ends at byte " +
                  std::to_string(bytes.size()));
    bytes.replace(at + 4, 8, std::string("\0\0\0\0\xe2\xe2\xe2\xe2", 8)); // the child count
    path = save("children.vdb", bytes);
    EXPECT_EQ(readEveryGrid(path),
              path + ": truncated or corrupt VDB file: grid 'density': the root's child nodes "
                     "at byte " + std::to_string(at + 12) +
                  " declares 3806520034 items of at least 8205 bytes, but the file ends at byte " +
                  std::to_string(bytes.size()));
}

TEST(VdbTree, aRootChildOriginOpenVdbDoesNotWriteIsRefused) {
    // Found by fuzz_vdb_reader: origins near the ends of the int range overflowed the index
    // arithmetic of OpenVDB's bounding boxes (UndefinedBehaviorSanitizer); OpenVDB writes the
    // root's tiles and children at multiples of 4096.
    constexpr float kBackground = 1.2345678e-7f;
    std::string bytes = contents(writeFile("origin.vdb", {denseLeaf(kBackground)},
                                           openvdb::io::COMPRESS_ZIP));
    const std::string background(reinterpret_cast<const char*>(&kBackground), 4);
    const std::size_t at = bytes.find(background);
    ASSERT_NE(at, std::string::npos);
    // No tile, one child, at the origin.
    ASSERT_EQ(bytes.substr(at + 4, 20),
              std::string("\0\0\0\0\x01\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0", 20));
    bytes.replace(at + 12, 4, "\xff\xff\xff\x7f"); // the child's x: 2^31 - 1
    const std::string path = save("origin.vdb", bytes);
    EXPECT_EQ(readEveryGrid(path),
              path + ": truncated or corrupt VDB file: grid 'density': a child node's origin at "
                     "byte " + std::to_string(at + 12) +
                  " is (2147483647, 0, 0), not a multiple of 4096");
}

TEST(VdbTree, aGridAsWideAsTheIndexRangeIsRead) {
    // Its box has 2^32 voxels a side, more than OpenVDB's int Coord::dim() holds (it overflowed).
    openvdb::initialize();
    auto wide = openvdb::FloatGrid::create(0.0f);
    wide->setName("wide");
    wide->tree().setValue({std::numeric_limits<std::int32_t>::min(), 0, 0}, 1.0f);
    wide->tree().setValue({std::numeric_limits<std::int32_t>::max(), 0, 0}, 2.0f);
    const std::string path = writeFile("wide.vdb", {wide}, openvdb::io::COMPRESS_ZIP);
    const ScalarGridPtr grid = std::get<ScalarGridPtr>(readVdbGrid(path, "wide"));
    EXPECT_EQ(grid->geometry().dims(), glm::i64vec3(std::int64_t{1} << 32, 1, 1));
    EXPECT_EQ(grid->value({0, 0, 0}), 1.0f);
    EXPECT_EQ(grid->value({(std::int64_t{1} << 32) - 1, 0, 0}), 2.0f);
}

TEST(VdbTree, aSingularTransformIsReportedWithTheGrid) {
    // Found by fuzz_vdb_reader (scripts/fuzz-long.sh, seed 2026): a damaged scale of 0 made
    // OpenVDB throw ArithmeticError while texsplat asked for the grid's affine map, outside the
    // wrapper of OpenVDB's calls (std::terminate in the fuzzer, an internal error in texsplat).
    openvdb::FloatGrid::Ptr grid = denseLeaf();
    grid->setTransform(openvdb::math::Transform::createLinearTransform(0.375));
    std::string bytes = contents(writeFile("scale.vdb", {grid}, openvdb::io::COMPRESS_ZIP));
    const double scale = 0.375;
    const std::string three(3 * sizeof scale, '\0');
    std::string pattern;
    for (int i = 0; i < 3; ++i)
        pattern.append(reinterpret_cast<const char*>(&scale), sizeof scale);
    const std::size_t at = bytes.find(pattern); // the map's scale, its first vector
    ASSERT_NE(at, std::string::npos);
    bytes.replace(at, pattern.size(), three);
    const std::string path = save("scale.vdb", bytes);
    const std::string error = readEveryGrid(path);
    EXPECT_EQ(error.rfind(path + ": grid 'density' has a transform OpenVDB cannot use "
                                 "(ArithmeticError: ", 0),
              0u)
        << error;
}

TEST(VdbTree, aGridPlacedOutsideTheFileIsRefused) {
    std::string bytes = contents(writeFile("grid.vdb", {denseLeaf()}, openvdb::io::COMPRESS_ZIP));
    // The header (65 bytes, as in VdbVolumeTest), the name "density", the type
    // "Tree_float_5_4_3", no instance parent, then the grid's start, buffers and end.
    constexpr std::size_t kEnd = 65 + 4 + 7 + 4 + 16 + 4 + 16;
    ASSERT_EQ(int64At(bytes, kEnd), std::int64_t(bytes.size()));
    setInt64At(bytes, kEnd, std::int64_t{1} << 40);
    const std::string path = save("outside.vdb", bytes);
    EXPECT_EQ(readEveryGrid(path),
              path + ": truncated or corrupt VDB file: grid 'density': its descriptor places it "
                     "from byte 124 to byte 1099511627776, but the file ends at byte " +
                  std::to_string(bytes.size()));
    setInt64At(bytes, kEnd, std::int64_t(bytes.size()));
    setInt64At(bytes, kEnd - 16, 100); // the grid's start, inside its descriptor
    const std::string inside = save("inside.vdb", bytes);
    EXPECT_EQ(readEveryGrid(inside),
              inside + ": truncated or corrupt VDB file: grid 'density': its descriptor places "
                       "it from byte 100 to byte " + std::to_string(bytes.size()) +
                  ", not after the descriptor, which ends at byte 124");
}

TEST(VdbTree, filesOfFormatsBefore222AreRefused) {
    std::string bytes = contents(writeFile("old.vdb", {denseLeaf()}, openvdb::io::COMPRESS_ZIP));
    bytes[8] = '\xdd'; // format 221, OpenVDB 2
    const std::string path = save("old.vdb", bytes);
    EXPECT_EQ(readEveryGrid(path),
              path + ": VDB file format 221 is older than 222 (OpenVDB 3), which texsplat cannot "
                     "check before OpenVDB reads it; write the file again with a newer OpenVDB");
}

TEST(VdbTree, theUuidIsReadAsOpenVdbReadsItWhitespaceAndAll) {
    // Found by fuzz_vdb_reader (scripts/fuzz-long.sh, seed 20261127): OpenVDB reads the UUID as
    // text and skips whitespace in it, so a space there moved everything after it by a byte from
    // where the walk read it, and OpenVDB allocated 1.4 GB for a grid name. A stream has no
    // positions to move: with whitespace in its UUID it is a file OpenVDB reads.
    constexpr std::size_t kUuidAt = 8 + 4 + 8 + 1; // magic, format, library, the offsets flag
    const std::string path = testPath("spaced.vdb");
    {
        std::ofstream out(path, std::ios::binary);
        openvdb::io::Stream(out).write(openvdb::GridPtrVec{denseLeaf()});
    }
    std::string bytes = contents(path);
    ASSERT_EQ(bytes[kUuidAt + 8], '-');
    bytes.insert(kUuidAt + 5, " \n\t");
    bytes.insert(kUuidAt, "\r\r");
    const std::string spaced = save("spaced.vdb", bytes);
    EXPECT_EQ(readEveryGrid(spaced), "no IoError");
    const auto grid = std::get<ScalarGridPtr>(readVdbGrid(spaced, "density"));
    EXPECT_EQ(grid->statistics().finiteCount, 512);
    // What Boost's UUID reading fails on, OpenVDB would go on reading from a failed stream.
    bytes[kUuidAt + 2 + 12] = 'g';
    const std::string bad = save("bad.vdb", bytes);
    EXPECT_EQ(readEveryGrid(bad), bad + ": truncated or corrupt VDB file: the file's UUID at "
                                        "byte 21 is not one (8-4-4-4-12 hex digits)");
}

TEST(VdbTree, aStreamedFileWithAGridWhoseTreeIsNotCheckedIsRefused) {
    openvdb::initialize();
    auto mask = openvdb::BoolGrid::create(false);
    mask->setName("mask");
    mask->tree().setValue({1, 1, 1}, true);
    const std::string path = testPath("streamed.vdb");
    {
        std::ofstream out(path, std::ios::binary);
        openvdb::io::Stream(out).write(openvdb::GridPtrVec{denseLeaf(), mask});
    }
    EXPECT_EQ(readEveryGrid(path),
              path + ": grid 'mask' is a Tree_bool_5_4_3 grid in a VDB file written as a stream, "
                     "which OpenVDB reads whole on opening it; texsplat checks only grids of "
                     "float, double, integer and vector values before that");
}

// A float grid named "density" of one voxel in each of 4 root children: a tree of 4 internal
// nodes of each size and 4 leaves, which a file holds in about 10 KB each.
openvdb::FloatGrid::Ptr fourChildren() {
    openvdb::initialize();
    auto grid = openvdb::FloatGrid::create(0.0f);
    grid->setName("density");
    for (int i = 0; i < 4; ++i)
        grid->tree().setValue({4096 * i, 0, 0}, 1.0f);
    return grid;
}

std::string writeFourChildren() {
    return writeFile("children.vdb", {fourChildren()},
                     openvdb::io::COMPRESS_ZIP | openvdb::io::COMPRESS_ACTIVE_MASK);
}

TEST(VdbTree, aTreeLargerThanTheMemoryLimitIsRefusedBeforeOpenVdbReadsIt) {
    // Each internal node of 32^3 costs OpenVDB 264 KiB for the 8 KiB of its masks in the file.
    const std::string path = writeFourChildren();
    ASSERT_LT(std::filesystem::file_size(path), 40000u);
    // 1232 + 16 (the tree), 393216 (reading a node of 32^3), 4 x 80 (root entries),
    // 4 x 270368, 4 x 33824, 4 x 2176 (internal nodes and leaves, 16 bytes of malloc's each).
    constexpr std::uint64_t kTreeBytes = 1620256;
    const ScopedMemoryLimit limit(1u << 20);
    EXPECT_EQ(errorOf<ResourceError>([&] { readVdbGrid(path, "density"); }),
              path + ": grid 'density': reading its tree of 4 internal nodes of 32^3, 4 of 16^3 "
                     "and 4 leaves into OpenVDB would need " + bytesText(kTreeBytes) +
                  ", more than the memory limit of 1048576 bytes (1 MiB); use a volume of lower "
                  "resolution, or a larger --memory-limit");
    EXPECT_EQ(listVdbGrids(path).size(), 1u); // reads no tree
    // A file written as a stream: OpenVDB reads every tree on opening it.
    const std::string streamed = testPath("streamed.vdb");
    {
        std::ofstream out(streamed, std::ios::binary);
        openvdb::io::Stream(out).write(openvdb::GridPtrVec{fourChildren()});
    }
    EXPECT_EQ(errorOf<ResourceError>([&] { listVdbGrids(streamed); }),
              streamed + ": reading the trees of its 1 grid into OpenVDB, which reads them all "
                         "on opening a file written as a stream, would need " +
                  bytesText(kTreeBytes) +
                  ", more than the memory limit of 1048576 bytes (1 MiB); use a volume of lower "
                  "resolution, or a larger --memory-limit");
}

TEST(VdbTree, aGridThatNeedsJustTheMemoryLimitIsRead) {
    // While the grid is copied, OpenVDB's tree is held too: the read needs both.
    const std::string path = writeFourChildren();
    const std::uint64_t tree = detail::checkVdbDeclaredSizes(path).find("density")->bytes;
    const std::uint64_t needed = tree + SparseGrid<float>::memoryBytesForBlocks(4);
    {
        const ScopedMemoryLimit limit(needed);
        EXPECT_EQ(std::get<ScalarGridPtr>(readVdbGrid(path, "density"))->value({4096 * 3, 0, 0}),
                  1.0f);
    }
    const ScopedMemoryLimit limit(needed - 1);
    const std::string error = errorOf<ResourceError>([&] { readVdbGrid(path, "density"); });
    EXPECT_EQ(error.rfind(path + ": grid 'density': copying its 4 active voxels (tiles included) "
                                 "would need " + bytesText(needed) + ", more than",
                          0),
              0u)
        << error;
}

// A shell of radius 70 voxels and 4 thick about the origin (8 root children, ~250 000 voxels).
template <typename GridType> typename GridType::Ptr shell(const std::string& name) {
    openvdb::initialize();
    auto grid = GridType::create();
    grid->setName(name);
    auto accessor = grid->getAccessor();
    for (int x = -72; x <= 72; ++x)
        for (int y = -72; y <= 72; ++y)
            for (int z = -72; z <= 72; ++z)
                if (std::abs(std::sqrt(float(x * x + y * y + z * z)) - 70.0f) < 2.0f)
                    accessor.setValue({x, y, z}, typename GridType::ValueType(1.0f));
    return grid;
}

TEST(VdbTree, theTreeEstimateBoundsWhatOpenVdbsTreeHoldsOnceRead) {
    // At least what the tree's own memUsage() counts, and at most 20 % more (the estimate adds
    // malloc's headers, the root's map and the arrays held while a node of 32^3 is read).
    const std::string path = writeFile(
        "shell.vdb", {shell<openvdb::FloatGrid>("float"), shell<openvdb::Vec3SGrid>("vector")},
        openvdb::io::COMPRESS_BLOSC | openvdb::io::COMPRESS_ACTIVE_MASK);
    const detail::VdbFileTrees trees = detail::checkVdbDeclaredSizes(path);
    openvdb::io::File file(path);
    file.open(false);
    for (const char* name : {"float", "vector"}) {
        SCOPED_TRACE(name);
        const std::uint64_t estimate = trees.find(name)->bytes;
        const std::uint64_t used = file.readGrid(name)->memUsage();
        EXPECT_GE(estimate, used);
        EXPECT_LE(double(estimate), 1.2 * double(used));
        std::printf("%s: estimate %llu bytes, memUsage() %llu bytes (%.3f)\n", name,
                    static_cast<unsigned long long>(estimate),
                    static_cast<unsigned long long>(used), double(estimate) / double(used));
    }
}

} // namespace
} // namespace texsplat::volume
#endif
