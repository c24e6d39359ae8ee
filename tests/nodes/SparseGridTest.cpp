#include "nodes/volume/SparseGrid.h"

#include <gtest/gtest.h>

#include <limits>
#include <map>
#include <tuple>

namespace texsplat::volume {
namespace {

TEST(SparseGrid, unsetVoxelsReadAsBackground) {
    SparseScalarGrid grid(GridGeometry({100, 100, 100}), -1.0f);
    grid.setValue({5, 6, 7}, 2.5f);
    EXPECT_EQ(grid.value({5, 6, 7}), 2.5f);
    EXPECT_TRUE(grid.isActive({5, 6, 7}));
    EXPECT_EQ(grid.value({5, 6, 8}), -1.0f) << "same block, inactive";
    EXPECT_FALSE(grid.isActive({5, 6, 8}));
    EXPECT_EQ(grid.value({99, 99, 99}), -1.0f) << "no block";
    EXPECT_EQ(grid.blockCount(), 1u);
    EXPECT_EQ(grid.activeVoxelCount(), 1);
}

TEST(SparseGrid, visitsExactlyTheActiveVoxels) {
    SparseVectorGrid grid(GridGeometry({40, 30, 20}), glm::vec3(0.0f), {3, 0, 5});
    const std::map<std::tuple<std::int64_t, std::int64_t, std::int64_t>, glm::vec3> expected = {
        {{0, 0, 0}, {1, 2, 3}}, {{4, 0, 2}, {4, 5, 6}}, {{5, 0, 2}, {7, 8, 9}},
        {{39, 29, 19}, {1, 1, 1}}};
    for (const auto& [key, value] : expected)
        grid.setValue({std::get<0>(key), std::get<1>(key), std::get<2>(key)}, value);
    grid.setValue({10, 10, 10}, {0.0f, std::numeric_limits<float>::infinity(), 0.0f});

    std::map<std::tuple<std::int64_t, std::int64_t, std::int64_t>, glm::vec3> visited;
    grid.forEachActive([&](const glm::i64vec3& index, const glm::vec3& value) {
        visited[{index.x, index.y, index.z}] = value;
    });
    EXPECT_EQ(visited, expected);
    EXPECT_EQ(grid.activeVoxelCount(), 5);
    EXPECT_FALSE(grid.isActive({10, 10, 10})) << "active but infinite is empty";
    // The block offset moves block boundaries: x 0..4 and 5..12 lie in different blocks.
    EXPECT_EQ(grid.blockCount(), 4u);
    const GridStatistics statistics = grid.statistics();
    EXPECT_EQ(statistics.finiteCount, 4);
    EXPECT_EQ(statistics.nonFiniteCount, 1);
}

TEST(SparseGrid, aBlockSetAtOnceHoldsWhatItsVoxelsSetOneByOneHold) {
    // Offset blocks: the block at lattice corner (5, -2, 1) holds voxels 5..12, 0..5, 1..8.
    const glm::i64vec3 offset(3, 2, 7);
    const glm::i64vec3 first(5, -2, 1);
    SparseScalarGrid whole(GridGeometry({20, 20, 20}), -1.0f, offset);
    SparseScalarGrid single(GridGeometry({20, 20, 20}), -1.0f, offset);
    whole.setValue({6, 0, 1}, 42.0f); // in the same block: a block set after it merges
    single.setValue({6, 0, 1}, 42.0f);
    SparseScalarGrid::BlockVoxels voxels;
    voxels.values.fill(std::numeric_limits<float>::quiet_NaN()); // inactive slots: not stored
    for (std::size_t slot = 0; slot < 512; ++slot) {
        const glm::i64vec3 index =
            first + glm::i64vec3(slot % 8, (slot / 8) % 8, slot / 64);
        if (slot % 3 == 0 && index.y >= 0) {
            voxels.values[slot] = static_cast<float>(slot);
            voxels.active.set(slot);
            single.setValue(index, static_cast<float>(slot));
        }
    }
    whole.setBlock(first, voxels);
    whole.setBlock({5, 14, 9}, SparseScalarGrid::BlockVoxels{}); // nothing active: no block
    EXPECT_EQ(whole.blockCount(), single.blockCount());
    EXPECT_EQ(whole.activeVoxelCount(), single.activeVoxelCount());
    for (std::int64_t z = 0; z < 20; ++z)
        for (std::int64_t y = 0; y < 20; ++y)
            for (std::int64_t x = 0; x < 20; ++x) {
                EXPECT_EQ(whole.value({x, y, z}), single.value({x, y, z}));
                EXPECT_EQ(whole.isActive({x, y, z}), single.isActive({x, y, z}));
            }
    EXPECT_EQ(whole.value({6, 0, 1}), 42.0f) << "kept: its slot, 17, is not active in the block";
}

TEST(SparseGrid, memoryIsProportionalToActiveBlocks) {
    // A 2^36-voxel grid (256 GiB dense) holding one line of 1000 voxels.
    SparseScalarGrid grid(GridGeometry({4096, 4096, 4096}));
    for (std::int64_t i = 0; i < 1000; ++i)
        grid.setValue({i * 4, 2048, 4095}, float(i));
    EXPECT_EQ(grid.activeVoxelCount(), 1000);
    EXPECT_EQ(grid.blockCount(), 500u);
    EXPECT_LT(grid.memoryBytes(), 500u * 2 * 8 * 8 * 8 * sizeof(float));
    EXPECT_EQ(grid.value({3996, 2048, 4095}), 999.0f);
}

} // namespace
} // namespace texsplat::volume
