#include "octree/Octree.h"

#include "OctreeTestSupport.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <string_view>
#include <thread>
#include <vector>

using texsplat::octree::ClassifiedGrid;
using texsplat::octree::NodeRef;
using texsplat::octree::Octree;
using texsplat::octree::OctreeNode;
using texsplat::octree::test::randomGrid;
using texsplat::octree::test::unitRandom;

namespace {

struct BruteForce {
    glm::dvec4 mean{0.0};
    double error = 0.0;
    std::uint64_t nonEmpty = 0;
};

BruteForce bruteForce(const ClassifiedGrid& grid, glm::u64vec3 begin, glm::u64vec3 end) {
    BruteForce result;
    std::vector<glm::dvec4> values;
    for (std::uint64_t k = begin.z; k < end.z; ++k) {
        for (std::uint64_t j = begin.y; j < end.y; ++j) {
            for (std::uint64_t i = begin.x; i < end.x; ++i) {
                values.emplace_back(grid.voxel(glm::u64vec3(i, j, k)));
                result.nonEmpty += grid.isEmptyVoxel(glm::u64vec3(i, j, k)) ? 0 : 1;
            }
        }
    }
    for (const glm::dvec4& value : values) {
        result.mean += value / static_cast<double>(values.size());
    }
    for (const glm::dvec4& value : values) {
        for (int channel = 0; channel < 4; ++channel) {
            result.error = std::max(result.error, std::abs(value[channel] - result.mean[channel]));
        }
    }
    return result;
}

// Walks every node reachable from the root and checks its summary and children against a
// brute-force computation over its voxels; returns how many nodes of level >= 1 it met.
std::uint64_t checkAllNodes(const Octree& octree) {
    const ClassifiedGrid& grid = octree.grid();
    std::uint64_t interiorNodes = 0;
    std::vector<NodeRef> pending{octree.root()};
    std::array<NodeRef, 8> children;
    while (!pending.empty()) {
        const NodeRef node = pending.back();
        pending.pop_back();
        const OctreeNode summary = octree.node(node);
        const BruteForce expected =
            bruteForce(grid, octree.voxelBegin(node), octree.voxelEnd(node));
        EXPECT_EQ(summary.nonEmptyCount, expected.nonEmpty);
        EXPECT_GT(summary.nonEmptyCount, 0u) << "empty subtrees must be pruned";
        EXPECT_NEAR(summary.meanColor.x, expected.mean.x, 1e-6);
        EXPECT_NEAR(summary.meanColor.y, expected.mean.y, 1e-6);
        EXPECT_NEAR(summary.meanColor.z, expected.mean.z, 1e-6);
        EXPECT_NEAR(summary.meanExtinction, expected.mean.w, 1e-6);
        EXPECT_NEAR(summary.error, expected.error, 1e-6);
        const int count = octree.children(node, children);
        int expectedCount = 0;
        if (node.level > 0) {
            ++interiorNodes;
            // Every octant block that exists and holds a non-empty voxel must be a child.
            const std::uint64_t half = std::uint64_t{1} << (node.level - 1);
            for (int octant = 0; octant < 8; ++octant) {
                const glm::u64vec3 begin =
                    octree.voxelBegin(node) +
                    half * glm::u64vec3(octant & 1, (octant >> 1) & 1, (octant >> 2) & 1);
                const glm::u64vec3 end = glm::min(begin + half, octree.voxelEnd(node));
                if (begin.x < end.x && begin.y < end.y && begin.z < end.z &&
                    bruteForce(grid, begin, end).nonEmpty > 0) {
                    const NodeRef& child = children[static_cast<std::size_t>(expectedCount)];
                    EXPECT_EQ(octree.voxelBegin(child), begin);
                    EXPECT_EQ(octree.voxelEnd(child), end);
                    ++expectedCount;
                }
            }
        }
        EXPECT_EQ(count, expectedCount);
        pending.insert(pending.end(), children.begin(), children.begin() + count);
    }
    return interiorNodes;
}

// A box of `dims` in which about `blockFraction` of the 8³ blocks hold random voxels and the
// rest are not allocated; with vectors (some zero) when `withVectors`.
std::shared_ptr<ClassifiedGrid> sparseGrid(glm::u64vec3 dims, unsigned seed, float blockFraction,
                                           bool withVectors) {
    auto grid = std::make_shared<ClassifiedGrid>(dims, glm::dvec3(1.0), glm::dvec3(0.0));
    if (withVectors) {
        grid->enableVectors();
    }
    std::mt19937 engine(seed);
    const glm::u64vec3 blocks = grid->blockDims();
    for (std::uint64_t bz = 0; bz < blocks.z; ++bz)
        for (std::uint64_t by = 0; by < blocks.y; ++by)
            for (std::uint64_t bx = 0; bx < blocks.x; ++bx) {
                if (unitRandom(engine) >= blockFraction) {
                    continue;
                }
                const glm::u64vec3 begin = glm::u64vec3(bx, by, bz) * ClassifiedGrid::kBlockSize;
                const glm::u64vec3 end = glm::min(begin + ClassifiedGrid::kBlockSize, dims);
                for (std::uint64_t k = begin.z; k < end.z; ++k)
                    for (std::uint64_t j = begin.y; j < end.y; ++j)
                        for (std::uint64_t i = begin.x; i < end.x; ++i) {
                            if (unitRandom(engine) < 0.4f) {
                                continue;
                            }
                            grid->setVoxel({i, j, k}, glm::vec3(unitRandom(engine), 0.5f, 0.0f),
                                           unitRandom(engine));
                            if (withVectors && unitRandom(engine) < 0.9f) {
                                grid->setVector({i, j, k},
                                                glm::vec3(unitRandom(engine) - 0.5f, 1.0f,
                                                          unitRandom(engine) - 0.5f));
                            }
                        }
            }
    return grid;
}

// The same nodes, field by field and bit for bit (OctreeNode's padding bytes are not data), and
// the same mean vectors, scale and root.
void expectSameOctree(const Octree& expected, const Octree& actual) {
    const auto sameBytes = [](const auto& a, const auto& b) {
        return std::memcmp(&a, &b, sizeof(a)) == 0;
    };
    EXPECT_EQ(actual.isEmpty(), expected.isEmpty());
    EXPECT_EQ(actual.rootLevel(), expected.rootLevel());
    EXPECT_TRUE(sameBytes(actual.valueScale(), expected.valueScale()));
    ASSERT_EQ(actual.nodes().size(), expected.nodes().size());
    for (std::size_t i = 0; i < expected.nodes().size(); ++i) {
        const OctreeNode& a = expected.nodes()[i];
        const OctreeNode& b = actual.nodes()[i];
        ASSERT_TRUE(sameBytes(a.meanColor, b.meanColor) &&
                    sameBytes(a.meanExtinction, b.meanExtinction) && sameBytes(a.error, b.error) &&
                    a.childMask == b.childMask && a.firstChild == b.firstChild &&
                    a.nonEmptyCount == b.nonEmptyCount)
            << "record " << i;
    }
}

} // namespace

TEST(Octree, isTheSameForAnyNumberOfThreads) {
    // Blocks are built in parallel and the levels above serially: the records must not depend on
    // which thread built which block. The sparse grids hold more blocks than one batch.
    auto oneVoxel = std::make_shared<ClassifiedGrid>(glm::u64vec3(1), glm::dvec3(1.0),
                                                     glm::dvec3(0.0));
    oneVoxel->setVoxel({0, 0, 0}, glm::vec3(0.5f), 1.0f);
    const std::vector<std::shared_ptr<const ClassifiedGrid>> grids{
        sparseGrid({37, 5, 70}, 1, 0.8f, false),
        sparseGrid({37, 5, 70}, 2, 0.8f, true),
        sparseGrid({1, 33, 9}, 3, 1.0f, true),
        sparseGrid({17, 1, 1}, 4, 1.0f, false),
        sparseGrid({3, 4, 2}, 5, 1.0f, true), // the root below the blocks' level
        sparseGrid({200, 130, 180}, 6, 0.15f, false),
        sparseGrid({130, 201, 90}, 7, 0.3f, true),
        randomGrid({40, 40, 40}, 8),
        oneVoxel,
        std::make_shared<ClassifiedGrid>(glm::u64vec3(90, 7, 100), glm::dvec3(1.0),
                                         glm::dvec3(0.0)), // empty
    };
    for (const auto& grid : grids) {
        const glm::u64vec3 dims = grid->dims();
        SCOPED_TRACE(::testing::Message() << dims.x << "x" << dims.y << "x" << dims.z
                                          << (grid->hasVectors() ? " with vectors" : ""));
        const auto buildWith = [&grid](int threads) {
            std::unique_ptr<Octree> octree;
            tbb::task_arena(threads).execute([&] { octree = std::make_unique<Octree>(grid); });
            return octree;
        };
        const std::unique_ptr<Octree> serial = buildWith(1);
        for (const int threads : {2, 7}) {
            SCOPED_TRACE(::testing::Message() << threads << " threads");
            expectSameOctree(*serial, *buildWith(threads));
        }
    }
}

TEST(Octree, reportsOnTheCallingThreadOnly) {
    // 2,197 blocks: three batches built by several threads; the viewer polls its window inside
    // the callback, which only the thread that asked for the octree may do.
    const auto grid = sparseGrid({104, 104, 104}, 9, 1.0f, false);
    const std::thread::id caller = std::this_thread::get_id();
    std::vector<double> fractions;
    bool onOtherThread = false;
    tbb::task_arena(4).execute([&] {
        const Octree octree(grid, [&](std::string_view, double fraction) {
            onOtherThread = onOtherThread || std::this_thread::get_id() != caller;
            fractions.push_back(fraction);
            return true;
        });
    });
    EXPECT_FALSE(onOtherThread);
    ASSERT_GE(fractions.size(), 4u);
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_EQ(fractions.back(), 1.0);
}

TEST(Octree, stopsBetweenBatchesWhenCancelled) {
    // Cancelled after the first of three batches, while the threads would build the next ones.
    const auto grid = sparseGrid({104, 104, 104}, 10, 1.0f, true);
    std::vector<double> fractions;
    try {
        tbb::task_arena(4).execute([&] {
            const Octree octree(grid, [&fractions](std::string_view, double fraction) {
                fractions.push_back(fraction);
                return fraction == 0.0;
            });
        });
        ADD_FAILURE() << "not cancelled";
    } catch (const texsplat::sg::Cancelled& error) {
        EXPECT_STREQ(error.what(), "building the octree: cancelled");
    }
    ASSERT_EQ(fractions.size(), 2u);
    EXPECT_GT(fractions.back(), 0.0);
    EXPECT_LT(fractions.back(), 1.0);
}

TEST(Octree, summarizesEveryNodeLikeABruteForceComputation) {
    const std::array<glm::u64vec3, 5> sizes{
        {{1, 1, 1}, {1, 9, 9}, {9, 1, 9}, {5, 7, 3}, {16, 16, 16}}};
    for (const glm::u64vec3& dims : sizes) {
        SCOPED_TRACE(::testing::Message() << dims.x << "x" << dims.y << "x" << dims.z);
        // The single voxel of a 1x1x1 grid must be non-empty for there to be a root.
        const Octree octree(randomGrid(dims, 7, dims == glm::u64vec3(1) ? 0.0f : 0.3f,
                                       dims.x * dims.y * dims.z > 64));
        ASSERT_FALSE(octree.isEmpty());
        EXPECT_EQ(checkAllNodes(octree), octree.nodes().size()) << "no orphan records";
    }
}

TEST(Octree, reportsItsBuildAndStopsWhenCancelled) {
    const auto grid = randomGrid({40, 40, 40}, 3);
    std::vector<double> fractions;
    const Octree octree(grid, [&fractions](std::string_view step, double fraction) {
        EXPECT_EQ(step, "building the octree");
        fractions.push_back(fraction);
        return true;
    });
    ASSERT_GE(fractions.size(), 2u);
    EXPECT_EQ(fractions.front(), 0.0);
    EXPECT_EQ(fractions.back(), 1.0);
    try {
        const Octree cancelled(grid, [](std::string_view, double) { return false; });
        ADD_FAILURE() << "not cancelled";
    } catch (const texsplat::sg::Cancelled& error) {
        EXPECT_STREQ(error.what(), "building the octree: cancelled");
    }
}

TEST(Octree, singleVoxelGridIsItsOwnRoot) {
    auto grid = std::make_shared<ClassifiedGrid>(glm::u64vec3(1), glm::dvec3(2.0),
                                                 glm::dvec3(1.0, 2.0, 3.0));
    grid->setVoxel({0, 0, 0}, {0.5f, 0.25f, 0.125f}, 2.0f);
    const Octree octree(grid);
    EXPECT_EQ(octree.rootLevel(), 0);
    EXPECT_TRUE(octree.nodes().empty());
    EXPECT_EQ(octree.root().level, 0);
    EXPECT_EQ(octree.node(octree.root()).meanExtinction, 2.0f);
    EXPECT_EQ(octree.center(octree.root()), glm::dvec3(1.0, 2.0, 3.0));
    EXPECT_EQ(octree.cellMin(octree.root()), glm::dvec3(0.0, 1.0, 2.0));
}

TEST(Octree, emptyGridHasNoRoot) {
    const Octree octree(std::make_shared<ClassifiedGrid>(glm::u64vec3(5, 7, 3), glm::dvec3(1.0),
                                                         glm::dvec3(0.0)));
    EXPECT_TRUE(octree.isEmpty());
    EXPECT_TRUE(octree.nodes().empty());
}

TEST(Octree, prunesEmptySubtreesCompletely) {
    // One non-empty voxel in a 16^3 grid: exactly one chain of nodes from the root down.
    auto grid = std::make_shared<ClassifiedGrid>(glm::u64vec3(16), glm::dvec3(1.0),
                                                 glm::dvec3(0.0));
    grid->setVoxel({13, 2, 7}, glm::vec3(1.0f), 1.0f);
    const Octree octree(grid);
    EXPECT_EQ(octree.rootLevel(), 4);
    EXPECT_EQ(octree.nodes().size(), 4u);
    EXPECT_EQ(checkAllNodes(octree), 4u);
}

TEST(Octree, interiorNodesAreAboutOneSeventhOfDenseVoxels) {
    const Octree octree(randomGrid(glm::u64vec3(16), 3, 0.0f, false));
    // 8^3 + 4^3 + 2^3 + 1 = 585 = (4096 - 1) / 7 records: the voxels themselves are not copied.
    EXPECT_EQ(octree.nodes().size(), 585u);
    EXPECT_EQ(octree.memoryBytes(), 585u * sizeof(OctreeNode));
}

TEST(Octree, placesNodesWithAnisotropicSpacing) {
    const Octree octree(randomGrid({5, 7, 3}, 11, 0.0f, false, {1.0, 2.0, 0.5}, {1.0, 0.0, 0.0}));
    const NodeRef root = octree.root();
    EXPECT_EQ(octree.rootLevel(), 3);
    EXPECT_EQ(octree.voxelEnd(root), glm::u64vec3(5, 7, 3));
    EXPECT_EQ(octree.center(root), glm::dvec3(3.0, 6.0, 0.5));
    EXPECT_EQ(octree.cellMin(root), glm::dvec3(0.5, -1.0, -0.25));
    EXPECT_EQ(octree.cellMax(root), glm::dvec3(5.5, 13.0, 1.25));
    EXPECT_EQ(octree.splitPlanes(root), glm::dvec3(4.5, 7.0, 1.25));
}

TEST(Octree, rejectsAMissingGrid) {
    try {
        const Octree octree(nullptr);
        FAIL() << "expected a DataError";
    } catch (const texsplat::DataError& error) {
        EXPECT_STREQ(error.what(), "Octree: no grid to build from");
    }
}
