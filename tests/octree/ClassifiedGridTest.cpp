#include "octree/ClassifiedGrid.h"

#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

using texsplat::DataError;
using texsplat::octree::ClassifiedGrid;

namespace {

template <typename Function> std::string errorOf(Function function) {
    try {
        function();
    } catch (const DataError& error) {
        return error.what();
    }
    return "no error";
}

} // namespace

TEST(ClassifiedGrid, startsEmptyWithLinearIndexXFastest) {
    ClassifiedGrid grid({5, 7, 3}, {1.0, 2.0, 0.5}, {10.0, 0.0, -1.0});
    EXPECT_EQ(grid.voxelCount(), 105u);
    EXPECT_EQ(grid.index({1, 2, 1}), 1u + 5u * (2u + 7u * 1u));
    EXPECT_TRUE(grid.isEmptyVoxel(glm::u64vec3(4, 6, 2)));
    grid.setVoxel({4, 6, 2}, {0.0f, 0.0f, 0.0f}, 0.25f);
    EXPECT_FALSE(grid.isEmptyVoxel(glm::u64vec3(4, 6, 2)));
    EXPECT_EQ(grid.voxel(glm::u64vec3(4, 6, 2)).w, 0.25f);
    EXPECT_EQ(grid.toWorld({4.0, 6.0, 2.0}), glm::dvec3(14.0, 12.0, 0.0));
}

TEST(ClassifiedGrid, rejectsZeroDimensions) {
    EXPECT_EQ(errorOf([] { ClassifiedGrid({4, 0, 2}, glm::dvec3(1.0), glm::dvec3(0.0)); }),
              "ClassifiedGrid: dimensions must be positive, got 4x0x2");
}

TEST(ClassifiedGrid, rejectsUnaddressableVoxelCounts) {
    const std::uint64_t huge = std::uint64_t{1} << 40;
    EXPECT_EQ(errorOf([&] {
                  ClassifiedGrid({huge, huge, 2}, glm::dvec3(1.0), glm::dvec3(0.0));
              }),
              "ClassifiedGrid: 1099511627776x1099511627776x2 voxels exceed the addressable "
              "memory");
}

TEST(ClassifiedGrid, rejectsBadSpacingAndOrigin) {
    EXPECT_EQ(errorOf([] { ClassifiedGrid({2, 2, 2}, {1.0, 0.0, 1.0}, glm::dvec3(0.0)); }),
              "ClassifiedGrid: spacing must be finite and positive, got (1, 0, 1)");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(errorOf([&] { ClassifiedGrid({2, 2, 2}, glm::dvec3(1.0), {0.0, nan, 0.0}); }),
              "ClassifiedGrid: origin must be finite, got (0, nan, 0)");
}

TEST(ClassifiedGrid, rejectsNegativeOrNonFiniteValues) {
    ClassifiedGrid grid({2, 2, 2}, glm::dvec3(1.0), glm::dvec3(0.0));
    EXPECT_EQ(errorOf([&] { grid.setVoxel({1, 0, 1}, {0.0f, -1.0f, 0.0f}, 1.0f); }),
              "ClassifiedGrid: voxel (1, 0, 1): color must be finite and >= 0, got -1");
    EXPECT_EQ(errorOf([&] {
                  grid.setVoxel({0, 1, 0}, glm::vec3(0.5f),
                                std::numeric_limits<float>::infinity());
              }),
              "ClassifiedGrid: voxel (0, 1, 0): extinction must be finite and >= 0, got inf");
    EXPECT_TRUE(grid.isEmptyVoxel(glm::u64vec3(1, 0, 1)));
}

TEST(ClassifiedGrid, aWholeBlockIsSetAsItsVoxelsWouldBe) {
    ClassifiedGrid grid({20, 9, 9}, glm::dvec3(1.0), glm::dvec3(0.0));
    std::array<glm::vec4, ClassifiedGrid::kBlockVoxels> voxels{};
    voxels[0] = glm::vec4(1.0f, 2.0f, 3.0f, 4.0f);
    voxels[3 + 8 * (1 + 8 * 2)] = glm::vec4(0.0f, 0.0f, 0.0f, 0.5f); // voxel (3, 1, 2)
    grid.setBlock({2, 0, 0}, voxels); // x 16..19 inside, 20..23 beyond the grid (all zero)
    EXPECT_EQ(grid.blockCount(), 1u);
    EXPECT_EQ(grid.nonEmptyVoxelCount(), 2u);
    EXPECT_EQ(grid.voxel({16, 0, 0}), glm::vec4(1.0f, 2.0f, 3.0f, 4.0f));
    EXPECT_EQ(grid.voxel({19, 1, 2}), glm::vec4(0.0f, 0.0f, 0.0f, 0.5f));
    // Setting it again replaces it and counts again; an all-empty block allocates nothing.
    voxels[0] = glm::vec4(0.0f);
    grid.setBlock({2, 0, 0}, voxels);
    EXPECT_EQ(grid.nonEmptyVoxelCount(), 1u);
    grid.setBlock({0, 1, 1}, std::array<glm::vec4, ClassifiedGrid::kBlockVoxels>{});
    EXPECT_EQ(grid.blockCount(), 1u);
    // A bad value is reported with its voxel, as setVoxel() reports it, and changes nothing.
    voxels[1 + 8 * (2 + 8 * 3)] = glm::vec4(0.0f, -1.0f, 0.0f, 0.0f); // voxel (1, 2, 3)
    EXPECT_EQ(errorOf([&] { grid.setBlock({1, 0, 1}, voxels); }),
              "ClassifiedGrid: voxel (9, 2, 11): color must be finite and >= 0, got -1");
    voxels[1 + 8 * (2 + 8 * 3)] = glm::vec4(0.0f, 0.0f, 0.0f, std::nanf(""));
    EXPECT_EQ(errorOf([&] { grid.setBlock({1, 0, 1}, voxels); }),
              "ClassifiedGrid: voxel (9, 2, 11): extinction must be finite and >= 0, got nan");
    EXPECT_EQ(grid.blockCount(), 1u);
    // The extremes count as non-empty: a denormal in one channel, FLT_MAX in all four (their
    // sum overflows); -0 is empty.
    std::array<glm::vec4, ClassifiedGrid::kBlockVoxels> extremes{};
    extremes[4] = glm::vec4(0.0f, std::numeric_limits<float>::denorm_min(), 0.0f, 0.0f);
    extremes[5] = glm::vec4(std::numeric_limits<float>::max());
    extremes[6] = glm::vec4(-0.0f);
    grid.setBlock({1, 0, 0}, extremes);
    EXPECT_EQ(grid.blockCount(), 2u);
    EXPECT_EQ(grid.nonEmptyVoxelCount(), 1u + 2u);
}

TEST(ClassifiedGrid, aPaletteGridHoldsTwoBytesAVoxelAndReadsAsItsMedia) {
    const std::vector<glm::vec4> palette = {glm::vec4(0.0f), glm::vec4(1.0f, 2.0f, 3.0f, 4.0f),
                                            glm::vec4(0.0f, 0.0f, 0.0f, 0.5f)};
    ClassifiedGrid grid({20, 9, 9}, glm::dvec3(1.0), glm::dvec3(0.0), palette);
    EXPECT_EQ(grid.storage(), ClassifiedGrid::Storage::Palette);
    ClassifiedGrid::PaletteBlock indices{};
    indices[0] = 1;
    indices[3 + 8 * (1 + 8 * 2)] = 2;  // voxel (3, 1, 2)
    grid.setBlock({2, 0, 0}, indices); // x 16..19 inside, 20..23 beyond the grid (all 0)
    EXPECT_EQ(grid.blockCount(), 1u);
    EXPECT_EQ(grid.nonEmptyVoxelCount(), 2u);
    EXPECT_EQ(grid.voxel({16, 0, 0}), palette[1]);
    EXPECT_EQ(grid.voxel({19, 1, 2}), palette[2]);
    EXPECT_EQ(grid.voxel({17, 0, 0}), glm::vec4(0.0f));
    const ClassifiedGrid::StorageIndex first = grid.blockStorage({2, 0, 0});
    EXPECT_EQ(grid.paletteBlock(first)[0], 1u);
    std::array<glm::vec4, ClassifiedGrid::kBlockVoxels> media{};
    grid.readBlock(first, media);
    EXPECT_EQ(media[0], palette[1]);
    EXPECT_EQ(media[3 + 8 * (1 + 8 * 2)], palette[2]);
    // Setting it again replaces it and counts again; an all-empty block allocates nothing.
    indices[0] = 0;
    grid.setBlock({2, 0, 0}, indices);
    EXPECT_EQ(grid.nonEmptyVoxelCount(), 1u);
    grid.setBlock({0, 1, 1}, ClassifiedGrid::PaletteBlock{});
    EXPECT_EQ(grid.blockCount(), 1u);
    // A block costs its 512 indices, not 512 media; the palette is paid once.
    const ClassifiedGrid direct({20, 9, 9}, glm::dvec3(1.0), glm::dvec3(0.0));
    const std::uint64_t table = direct.memoryBytes();
    const std::uint64_t block = grid.memoryBytes() - table - palette.size() * sizeof(glm::vec4);
    EXPECT_GE(block, ClassifiedGrid::kBlockVoxels * 2);
    EXPECT_LT(block, ClassifiedGrid::kBlockVoxels * 2 + 256);
    EXPECT_EQ(grid.memoryBytes(),
              ClassifiedGrid::memoryBytesFor({20, 9, 9}, 1, false, palette.size()));
}

TEST(ClassifiedGrid, rejectsAPaletteThatCannotNameItsMedia) {
    const auto make = [](std::vector<glm::vec4> palette) {
        return errorOf([&] {
            ClassifiedGrid({2, 2, 2}, glm::dvec3(1.0), glm::dvec3(0.0), std::move(palette));
        });
    };
    EXPECT_EQ(make({}), "ClassifiedGrid: a palette holds 1 to 65536 media, got 0");
    EXPECT_EQ(make(std::vector<glm::vec4>(65537, glm::vec4(0.0f))),
              "ClassifiedGrid: a palette holds 1 to 65536 media, got 65537");
    EXPECT_EQ(make({glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)}),
              "ClassifiedGrid: the palette's first medium must be empty");
    EXPECT_EQ(make({glm::vec4(0.0f), glm::vec4(0.0f, -1.0f, 0.0f, 1.0f)}),
              "ClassifiedGrid: palette medium 1: color must be finite and >= 0, got -1");
    EXPECT_EQ(make({glm::vec4(0.0f), glm::vec4(0.0f, 0.0f, 0.0f, INFINITY)}),
              "ClassifiedGrid: palette medium 1: extinction must be finite and >= 0, got inf");
}

TEST(ClassifiedGrid, vectorsAreThereOnlyWhenEnabledAndMustBeFinite) {
    ClassifiedGrid grid({2, 1, 1}, glm::dvec3(1.0), glm::dvec3(0.0));
    EXPECT_FALSE(grid.hasVectors());
    grid.enableVectors();
    ASSERT_TRUE(grid.hasVectors());
    EXPECT_EQ(grid.vector(glm::u64vec3(1, 0, 0)), glm::vec3(0.0f));
    // An empty voxel draws nothing: in a block that holds nothing its vector is not kept.
    grid.setVector({1, 0, 0}, {1.0f, -2.0f, 3.0f});
    EXPECT_EQ(grid.vector(glm::u64vec3(1, 0, 0)), glm::vec3(0.0f));
    EXPECT_EQ(grid.blockCount(), 0u);
    grid.setVoxel({1, 0, 0}, glm::vec3(0.0f), 1.0f);
    grid.setVector({1, 0, 0}, {1.0f, -2.0f, 3.0f});
    EXPECT_EQ(grid.vector(glm::u64vec3(1, 0, 0)), glm::vec3(1.0f, -2.0f, 3.0f));
    EXPECT_EQ(errorOf([&] {
                  grid.setVector({0, 0, 0}, {0.0f, std::numeric_limits<float>::quiet_NaN(), 0.0f});
              }),
              "ClassifiedGrid: voxel (0, 0, 0): vector must be finite, got (0, nan, 0)");
    EXPECT_EQ(grid.vector(glm::u64vec3(0, 0, 0)), glm::vec3(0.0f));
}

TEST(ClassifiedGrid, allocatesABlockOnlyWhereANonEmptyValueIsSet) {
    const glm::u64vec3 dims(64, 40, 17);
    ClassifiedGrid grid(dims, glm::dvec3(1.0), glm::dvec3(0.0));
    EXPECT_EQ(grid.blockDims(), glm::u64vec3(8, 5, 3));
    const std::uint64_t table = ClassifiedGrid::boxBlockCount(dims) * sizeof(std::uint32_t);
    EXPECT_EQ(grid.memoryBytes(), table);
    for (std::uint64_t k = 0; k < dims.z; ++k) {
        grid.setVoxel({3, 5, k}, glm::vec3(0.0f), 0.0f);
    }
    EXPECT_EQ(grid.blockCount(), 0u);
    EXPECT_EQ(grid.memoryBytes(), table);

    grid.setVoxel({63, 39, 16}, glm::vec3(1.0f), 2.0f); // in a block clipped by all three faces
    grid.setVoxel({56, 32, 16}, glm::vec3(0.5f), 0.0f); // the same block
    grid.setVoxel({8, 0, 0}, glm::vec3(0.0f), 1.0f);
    EXPECT_EQ(grid.blockCount(), 2u);
    EXPECT_EQ(grid.nonEmptyVoxelCount(), 3u);
    EXPECT_TRUE(grid.hasBlock({7, 4, 2}));
    EXPECT_TRUE(grid.hasBlock({1, 0, 0}));
    EXPECT_FALSE(grid.hasBlock({0, 0, 0}));
    EXPECT_EQ(grid.memoryBytes(), ClassifiedGrid::memoryBytesFor(dims, 2, false));
    EXPECT_GT(grid.memoryBytes(), table + 2 * ClassifiedGrid::kBlockVoxels * sizeof(glm::vec4));
    EXPECT_EQ(grid.voxel(glm::u64vec3(63, 39, 16)), glm::vec4(1.0f, 1.0f, 1.0f, 2.0f));
    EXPECT_EQ(grid.voxel(glm::u64vec3(56, 32, 16)), glm::vec4(0.5f, 0.5f, 0.5f, 0.0f));
    EXPECT_TRUE(grid.isEmptyVoxel(glm::u64vec3(57, 32, 16)));

    // An allocated block takes empty values like any other (the voxel is empty again).
    grid.setVoxel({8, 0, 0}, glm::vec3(0.0f), 0.0f);
    EXPECT_TRUE(grid.isEmptyVoxel(glm::u64vec3(8, 0, 0)));
    EXPECT_EQ(grid.nonEmptyVoxelCount(), 2u);

    std::uint64_t visited = 0;
    grid.forEachBlock([&](glm::u64vec3 block, ClassifiedGrid::StorageIndex first) {
        EXPECT_EQ(first, grid.blockStorage(block));
        EXPECT_EQ(grid.storedVoxel(first + ClassifiedGrid::offsetInBlock({63, 39, 16})),
                  grid.voxel(block * ClassifiedGrid::kBlockSize + glm::u64vec3(7, 7, 0)));
        ++visited;
    });
    EXPECT_EQ(visited, 2u);
    EXPECT_EQ(grid.blockStorage({0, 0, 0}), ClassifiedGrid::kNoStorage);
}

TEST(ClassifiedGrid, vectorsOfBlocksAllocatedAfterEnablingAreKept) {
    ClassifiedGrid grid({20, 3, 3}, glm::dvec3(1.0), glm::dvec3(0.0));
    grid.setVoxel({1, 1, 1}, glm::vec3(1.0f), 1.0f);
    grid.enableVectors();
    grid.setVoxel({17, 2, 2}, glm::vec3(1.0f), 1.0f);
    grid.setVector({1, 1, 1}, {1.0f, 0.0f, 0.0f});
    grid.setVector({17, 2, 2}, {0.0f, 0.0f, 4.0f});
    EXPECT_EQ(grid.vector(glm::u64vec3(1, 1, 1)), glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(grid.vector(glm::u64vec3(17, 2, 2)), glm::vec3(0.0f, 0.0f, 4.0f));
    EXPECT_EQ(grid.memoryBytes(), ClassifiedGrid::memoryBytesFor(grid.dims(), 2, true));
}
