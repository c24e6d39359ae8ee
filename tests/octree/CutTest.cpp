#include "octree/Cut.h"

#include "OctreeTestSupport.h"
#include "octree/CutTraversal.h"
#include "octree/Octree.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <vector>

using texsplat::octree::ClassifiedGrid;
using texsplat::octree::Cut;
using texsplat::octree::NodeRef;
using texsplat::octree::Octree;
using texsplat::octree::View;
using texsplat::octree::test::randomGrid;

namespace {

std::vector<NodeRef> nodesOf(const Cut& cut) {
    std::vector<NodeRef> nodes;
    texsplat::octree::traverseBackToFront(
        cut, View::orthographic({0.0, 0.0, 1.0}),
        [&](const NodeRef& node) { nodes.push_back(node); });
    return nodes;
}

} // namespace

TEST(Cut, coarsestCutIsTheRoot) {
    const Octree octree(randomGrid({5, 7, 3}, 1));
    const Cut cut(octree);
    EXPECT_EQ(cut.splatCount(), 1u);
    const std::vector<NodeRef> nodes = nodesOf(cut);
    ASSERT_EQ(nodes.size(), 1u);
    EXPECT_EQ(nodes[0].level, octree.rootLevel());
}

TEST(Cut, zeroThresholdSplatsExactlyTheNonEmptyVoxels) {
    for (const glm::u64vec3 dims : {glm::u64vec3(1), glm::u64vec3(1, 9, 9),
                                    glm::u64vec3(5, 7, 3), glm::u64vec3(16)}) {
        SCOPED_TRACE(::testing::Message() << dims.x << "x" << dims.y << "x" << dims.z);
        const Octree octree(randomGrid(dims, 5, dims == glm::u64vec3(1) ? 0.0f : 0.3f));
        const Cut cut = Cut::byError(octree, 0.0);
        std::vector<std::uint64_t> splatted;
        for (const NodeRef& node : nodesOf(cut)) {
            // A node clipped to a single voxel by the grid's faces is that voxel's splat.
            EXPECT_EQ(octree.voxelCount(node), 1u);
            splatted.push_back(octree.grid().index(octree.voxelBegin(node)));
        }
        std::vector<std::uint64_t> nonEmpty;
        for (std::uint64_t index = 0; index < octree.grid().voxelCount(); ++index) {
            if (!octree.grid().isEmptyVoxel(octree.grid().coordinates(index))) {
                nonEmpty.push_back(index);
            }
        }
        std::sort(splatted.begin(), splatted.end());
        EXPECT_EQ(splatted, nonEmpty);
        EXPECT_EQ(cut.splatCount(), nonEmpty.size());
    }
}

TEST(Cut, uniformBlockIsExactAtItsMean) {
    // A uniform, full 2x2x2 block has error 0: a zero threshold keeps it as one splat.
    auto grid = std::make_shared<ClassifiedGrid>(glm::u64vec3(4, 2, 2), glm::dvec3(1.0),
                                                 glm::dvec3(0.0));
    for (std::uint64_t index = 0; index < 8; ++index) {
        grid->setVoxel({index & 1, (index >> 1) & 1, (index >> 2) & 1}, glm::vec3(0.5f), 1.0f);
    }
    grid->setVoxel({3, 1, 1}, glm::vec3(0.25f), 2.0f);
    const Octree octree(grid);
    const Cut cut = Cut::byError(octree, 0.0);
    const std::vector<NodeRef> nodes = nodesOf(cut);
    ASSERT_EQ(nodes.size(), 2u);
    EXPECT_EQ(cut.splatCount(), 2u);
    EXPECT_EQ(octree.node(nodes[0]).error + octree.node(nodes[1]).error, 0.0f);
}

TEST(Cut, everySplattedNodeMeetsTheThreshold) {
    const Octree octree(randomGrid(glm::u64vec3(16), 9));
    std::uint64_t previousCount = 0;
    for (const double threshold : {1.0, 0.6, 0.45, 0.3, 0.0}) {
        const Cut cut = Cut::byError(octree, threshold);
        const std::vector<NodeRef> nodes = nodesOf(cut);
        EXPECT_EQ(nodes.size(), cut.splatCount());
        EXPECT_GE(cut.splatCount(), previousCount) << "a lower threshold never coarsens";
        previousCount = cut.splatCount();
        std::uint64_t voxels = 0;
        for (const NodeRef& node : nodes) {
            EXPECT_LE(octree.node(node).error, threshold);
            voxels += octree.node(node).nonEmptyCount;
        }
        EXPECT_EQ(voxels, octree.node(octree.root()).nonEmptyCount) << "the cut covers all";
    }
}

TEST(Cut, emptyOctreeHasNoSplats) {
    const Octree octree(std::make_shared<ClassifiedGrid>(glm::u64vec3(3), glm::dvec3(1.0),
                                                         glm::dvec3(0.0)));
    EXPECT_EQ(Cut::byError(octree, 0.0).splatCount(), 0u);
    EXPECT_TRUE(nodesOf(Cut(octree)).empty());
}

TEST(Cut, rejectsNegativeOrNonFiniteThresholds) {
    const Octree octree(randomGrid({2, 2, 2}, 1, 0.0f, false));
    for (const double threshold : {-0.5, std::numeric_limits<double>::quiet_NaN()}) {
        try {
            (void)Cut::byError(octree, threshold);
            FAIL() << "expected a DataError";
        } catch (const texsplat::DataError& error) {
            EXPECT_EQ(std::string(error.what()),
                      std::string("Cut: error threshold must be finite and >= 0, got ") +
                          (threshold < 0.0 ? "-0.5" : "nan"));
        }
    }
}

TEST(Cut, isDeterministic) {
    const Octree first(randomGrid(glm::u64vec3(16), 21));
    const Octree second(randomGrid(glm::u64vec3(16), 21));
    EXPECT_EQ(first.nodes().size(), second.nodes().size());
    const Cut a = Cut::byError(first, 0.6);
    const Cut b = Cut::byError(first, 0.6);
    EXPECT_TRUE(a == b);
    EXPECT_TRUE(a != Cut::byError(first, 0.0));
    EXPECT_LT(a.splatCount(), Cut::byError(first, 0.0).splatCount());
}

namespace {

// The same grid with every value scaled: what a transfer function's opacity scale does (its
// colour is premultiplied by the opacity, so all four channels scale).
std::shared_ptr<ClassifiedGrid> scaledGrid(const ClassifiedGrid& grid, float factor) {
    auto scaled = std::make_shared<ClassifiedGrid>(grid.dims(), grid.spacing(), grid.origin());
    const glm::u64vec3 dims = grid.dims();
    for (std::uint64_t k = 0; k < dims.z; ++k) {
        for (std::uint64_t j = 0; j < dims.y; ++j) {
            for (std::uint64_t i = 0; i < dims.x; ++i) {
                const glm::vec4 value = grid.voxel(glm::u64vec3(i, j, k)) * factor;
                scaled->setVoxel({i, j, k}, glm::vec3(value), value.w);
            }
        }
    }
    return scaled;
}

} // namespace

TEST(Cut, relativeThresholdGivesTheSameCutWhateverTheValuesScale) {
    const auto grid = randomGrid(glm::u64vec3(16), 5);
    const Octree octree(grid);
    const Octree scaled(scaledGrid(*grid, 10.0f));
    EXPECT_FLOAT_EQ(scaled.valueScale(), 10.0f * octree.valueScale());
    for (const double fraction : {0.0, 0.1, 0.3, 0.6, 1.0}) {
        const std::vector<NodeRef> expected = nodesOf(Cut::byRelativeError(octree, fraction));
        const std::vector<NodeRef> actual = nodesOf(Cut::byRelativeError(scaled, fraction));
        ASSERT_EQ(actual.size(), expected.size()) << fraction;
        for (std::size_t i = 0; i < expected.size(); ++i) {
            EXPECT_EQ(actual[i].level, expected[i].level) << fraction;
            EXPECT_EQ(actual[i].coord, expected[i].coord) << fraction;
        }
    }
    // The absolute threshold is what the scale changes: it refines the brighter grid further.
    const double absolute = 0.6 * static_cast<double>(octree.valueScale());
    EXPECT_LT(Cut::byError(octree, absolute).splatCount(),
              Cut::byError(scaled, absolute).splatCount());
}

TEST(Cut, relativeThresholdRunsFromEveryVoxelToTheRoot) {
    const Octree octree(randomGrid(glm::u64vec3(12), 9));
    EXPECT_TRUE(Cut::byRelativeError(octree, 0.0) == Cut::byError(octree, 0.0));
    EXPECT_EQ(Cut::byRelativeError(octree, 1.0).splatCount(), 1u);
    EXPECT_THROW((void)Cut::byRelativeError(octree, -0.1), texsplat::DataError);
}
