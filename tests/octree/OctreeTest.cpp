#include "octree/Octree.h"

#include "OctreeTestSupport.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>
#include <vector>

using texsplat::octree::ClassifiedGrid;
using texsplat::octree::NodeRef;
using texsplat::octree::Octree;
using texsplat::octree::OctreeNode;
using texsplat::octree::test::randomGrid;

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

} // namespace

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

// The build reads a scalar grid's blocks straight from their storage; a grid with vectors takes
// the general path. With every vector zero the two must give the same records, bit for bit.
TEST(Octree, readsScalarBlocksLikeTheGeneralBuild) {
    for (const glm::u64vec3& dims : {glm::u64vec3(37, 29, 21), glm::u64vec3(24, 8, 17)}) {
        SCOPED_TRACE(::testing::Message() << dims.x << "x" << dims.y << "x" << dims.z);
        const auto scalar = randomGrid(dims, 11, 0.5f);
        auto withVectors =
            std::make_shared<ClassifiedGrid>(dims, scalar->spacing(), scalar->origin());
        withVectors->enableVectors();
        for (std::uint64_t k = 0; k < dims.z; ++k)
            for (std::uint64_t j = 0; j < dims.y; ++j)
                for (std::uint64_t i = 0; i < dims.x; ++i) {
                    const glm::vec4 value = scalar->voxel({i, j, k});
                    withVectors->setVoxel({i, j, k}, glm::vec3(value), value.w);
                }
        const Octree fast(scalar);
        const Octree general(withVectors);
        ASSERT_EQ(fast.nodes().size(), general.nodes().size());
        ASSERT_GT(fast.nodes().size(), 100u);
        for (std::size_t i = 0; i < fast.nodes().size(); ++i) {
            const OctreeNode& a = fast.nodes()[i];
            const OctreeNode& b = general.nodes()[i];
            ASSERT_EQ(a.meanColor, b.meanColor) << i;
            ASSERT_EQ(a.meanExtinction, b.meanExtinction) << i;
            ASSERT_EQ(a.error, b.error) << i;
            ASSERT_EQ(a.childMask, b.childMask) << i;
            ASSERT_EQ(a.firstChild, b.firstChild) << i;
            ASSERT_EQ(a.nonEmptyCount, b.nonEmptyCount) << i;
        }
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
