// Grid::occupiedBlocks() and Grid::readBlock(), what classification reads grids by (in parallel,
// a block at a time): every grid type must answer what value() and isActive() answer voxel by
// voxel, at blocks the box clips, across a sparse grid's own (offset) block boundaries, and with
// non-finite voxels, which are empty.
#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/ExternalGrid.h"
#include "nodes/volume/SparseGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <tuple>
#include <vector>

namespace texsplat::volume {
namespace {

constexpr std::int64_t kEdge = ScalarGrid::kBlockEdge;

// Expects `grid`'s blocks to hold exactly its voxels, and its occupied blocks to be ordered by
// z, y, x, distinct, and to cover every non-empty voxel; answers the number of non-empty voxels.
std::int64_t expectBlocksHoldTheVoxels(const ScalarGrid& grid) {
    const std::vector<glm::i64vec3> blocks = grid.occupiedBlocks();
    const auto key = [](const glm::i64vec3& block) {
        return std::make_tuple(block.z, block.y, block.x);
    };
    EXPECT_TRUE(std::is_sorted(blocks.begin(), blocks.end(),
                               [&](const auto& a, const auto& b) { return key(a) < key(b); }));
    std::set<std::tuple<std::int64_t, std::int64_t, std::int64_t>> occupied;
    for (const glm::i64vec3& block : blocks) {
        EXPECT_TRUE(occupied.insert(key(block)).second) << "a block listed twice";
    }
    std::int64_t nonEmpty = 0;
    std::int64_t wrong = 0; // voxels read as non-empty that are not, or the other way round
    ScalarGrid::VoxelBlock read;
    for (const glm::i64vec3& block : blocks) {
        grid.readBlock(block, read);
        for (std::int64_t z = 0; z < kEdge; ++z) {
            for (std::int64_t y = 0; y < kEdge; ++y) {
                for (std::int64_t x = 0; x < kEdge; ++x) {
                    const glm::i64vec3 index = block * kEdge + glm::i64vec3(x, y, z);
                    const auto slot = static_cast<std::size_t>(x + kEdge * (y + kEdge * z));
                    const bool active = grid.geometry().contains(index) && grid.isActive(index);
                    if (read.nonEmpty[slot] != active) {
                        ++wrong;
                    } else if (active) {
                        EXPECT_EQ(read.values[slot], grid.value(index));
                        ++nonEmpty;
                    }
                }
            }
        }
    }
    EXPECT_EQ(wrong, 0);
    std::int64_t visited = 0;
    grid.forEachActive([&](const glm::i64vec3& index, float) {
        ++visited;
        EXPECT_EQ(occupied.count(key(index / kEdge)), 1u) << "a voxel outside the blocks";
    });
    EXPECT_EQ(nonEmpty, visited);
    return nonEmpty;
}

// Voxel `index`'s test value: NaN or infinite at some, so that they are stored but empty.
float valueAt(const glm::i64vec3& index) {
    const std::int64_t hash = index.x * 7 + index.y * 13 + index.z * 29;
    if (hash % 11 == 0) {
        return std::numeric_limits<float>::quiet_NaN();
    }
    if (hash % 17 == 0) {
        return -std::numeric_limits<float>::infinity();
    }
    return static_cast<float>(hash % 23) - 5.0f;
}

TEST(GridBlocks, aSparseGridWithOffsetBlocksReadsAsItsVoxels) {
    // Offset block boundaries: each stored block overlaps up to 8 read blocks; the box
    // (41 × 30 × 19) clips the last ones.
    SparseScalarGrid grid(GridGeometry({41, 30, 19}), -1.0f, {3, 0, 5});
    for (std::int64_t i = 0; i < 400; ++i) {
        const glm::i64vec3 index((i * 37) % 20, (i * 11) % 30, (i * 5) % 19); // x < 20 only
        grid.setValue(index, valueAt(index));
    }
    grid.setValue({40, 29, 18}, 2.0f); // the far corner, in a clipped block
    EXPECT_GT(expectBlocksHoldTheVoxels(grid), 300);
    EXPECT_LT(grid.occupiedBlocks().size(), std::size_t{6 * 4 * 3}) << "not every block";
}

TEST(GridBlocks, denseAndExternalGridsReadAsTheirVoxels) {
    const GridGeometry geometry({19, 10, 9});
    DenseScalarGrid dense(geometry);
    std::vector<float> values(static_cast<std::size_t>(geometry.voxelCount()));
    for (std::int64_t z = 0; z < 9; ++z) {
        for (std::int64_t y = 0; y < 10; ++y) {
            for (std::int64_t x = 0; x < 19; ++x) {
                const glm::i64vec3 index(x, y, z);
                dense.setValue(index, valueAt(index));
                values[static_cast<std::size_t>(geometry.linearIndex(index))] = valueAt(index);
            }
        }
    }
    EXPECT_EQ(dense.occupiedBlocks().size(), std::size_t{3 * 2 * 2}) << "every block of the box";
    const std::int64_t nonEmpty = expectBlocksHoldTheVoxels(dense);
    EXPECT_GT(nonEmpty, 1000);
    EXPECT_LT(nonEmpty, geometry.voxelCount()) << "some voxels are not finite";
    const ExternalScalarGrid external(geometry, values.data(), values.size());
    EXPECT_EQ(expectBlocksHoldTheVoxels(external), nonEmpty);
}

} // namespace
} // namespace texsplat::volume
