#include "octree/CutTraversal.h"

#include "OctreeTestSupport.h"
#include "octree/Cut.h"
#include "octree/Octree.h"

#include <gtest/gtest.h>

#include <array>
#include <set>
#include <vector>

using texsplat::octree::Cut;
using texsplat::octree::NodeRef;
using texsplat::octree::Octree;
using texsplat::octree::View;
using texsplat::octree::test::Cell;
using texsplat::octree::test::checkVisibilityOrder;
using texsplat::octree::test::randomGrid;
using texsplat::octree::test::unitRandom;

namespace {

// A cut with nodes of many levels side by side: split the root, then each node with
// probability 0.75.
Cut mixedCut(const Octree& octree, unsigned seed) {
    Cut cut(octree);
    std::mt19937 engine(seed);
    std::vector<NodeRef> pending{octree.root()};
    std::array<NodeRef, 8> children;
    while (!pending.empty()) {
        const NodeRef node = pending.back();
        pending.pop_back();
        if (node.level == 0 || (node.level < octree.rootLevel() && unitRandom(engine) > 0.75f)) {
            continue;
        }
        cut.split(node);
        const int count = octree.children(node, children);
        pending.insert(pending.end(), children.begin(), children.begin() + count);
    }
    return cut;
}

std::vector<View> orthographicViews() {
    std::vector<View> views;
    for (int axis = 0; axis < 3; ++axis) {
        for (const double sign : {1.0, -1.0}) {
            glm::dvec3 direction(0.0);
            direction[axis] = sign;
            views.push_back(View::orthographic(direction));
        }
    }
    views.push_back(View::orthographic({1.0, 1.0, 1.0}));
    views.push_back(View::orthographic({1.0, -2.0, 0.5}));
    views.push_back(View::orthographic({-0.3, 0.2, -1.0}));
    views.push_back(View::orthographic({0.05, -1.0, 0.7}));
    return views;
}

// Eyes outside the grid [-0.5, 15.5]^3 and inside it, looking at or across the volume.
std::vector<View> perspectiveViews() {
    return {View::perspective({40.0, 30.0, 25.0}, {-1.0, -0.8, -0.6}),
            View::perspective({7.5, 7.5, -30.0}, {0.0, 0.0, 1.0}),
            View::perspective({-5.0, 20.0, 3.0}, {1.0, -0.5, 0.2}),
            View::perspective({7.2, 7.9, 8.3}, {0.3, -0.2, 1.0}),
            View::perspective({2.0, 13.0, 5.5}, {1.0, 0.1, -0.4}),
            View::perspective({8.0, 8.0, 8.0}, {-1.0, 0.0, 0.0})};
}

// Visits the cut for the view and checks it against the brute force: every node once (those in
// front of the eye for a perspective view), and no cell drawn before a cell behind it.
// Returns how many pairs of cells on common rays were compared.
std::uint64_t checkTraversal(const Cut& cut, const View& view) {
    const Octree& octree = cut.octree();
    std::vector<Cell> cells;
    std::set<std::uint64_t> seen;
    std::uint64_t visited = 0;
    traverseBackToFront(cut, view, [&](const NodeRef& node) {
        EXPECT_FALSE(cut.isSplit(node));
        EXPECT_TRUE(seen.insert(octree.grid().index(octree.voxelBegin(node))).second);
        if (view.isPerspective()) {
            EXPECT_GT(view.depth(octree.center(node)), 0.0) << "behind the eye: culled";
        }
        cells.push_back({octree.cellMin(node), octree.cellMax(node)});
        ++visited;
    });
    if (!view.isPerspective()) {
        EXPECT_EQ(visited, cut.splatCount());
    }
    const NodeRef root = octree.root();
    const auto check = checkVisibilityOrder(cells, view, octree.cellMin(root),
                                            octree.cellMax(root), 400, 17);
    EXPECT_EQ(check.violations, 0u);
    return check.orderedPairs;
}

} // namespace

TEST(CutTraversal, fullResolutionCutIsBackToFrontForOrthographicViews) {
    const Octree octree(randomGrid(glm::u64vec3(16), 3));
    const Cut cut = Cut::byError(octree, 0.0);
    for (const View& view : orthographicViews()) {
        SCOPED_TRACE(::testing::Message() << "direction " << view.direction().x << " "
                                          << view.direction().y << " " << view.direction().z);
        EXPECT_GT(checkTraversal(cut, view), 400u) << "the rays must cross several cells";
    }
}

TEST(CutTraversal, mixedLevelCutIsBackToFrontForOrthographicViews) {
    const Octree octree(randomGrid({13, 16, 11}, 4, 0.2f, true, {1.0, 0.5, 2.0}));
    const Cut cut = mixedCut(octree, 8);
    for (const View& view : orthographicViews()) {
        SCOPED_TRACE(::testing::Message() << "direction " << view.direction().x << " "
                                          << view.direction().y << " " << view.direction().z);
        EXPECT_GT(checkTraversal(cut, view), 400u) << "the rays must cross several cells";
    }
    std::set<int> levels;
    traverseBackToFront(cut, orthographicViews()[0],
                        [&](const NodeRef& node) { levels.insert(node.level); });
    EXPECT_GE(levels.size(), 3u) << "the cut mixes levels";
}

TEST(CutTraversal, isBackToFrontForPerspectiveEyesOutsideAndInside) {
    const Octree octree(randomGrid(glm::u64vec3(16), 6));
    for (const Cut& cut : {Cut::byError(octree, 0.0), mixedCut(octree, 2)}) {
        for (const View& view : perspectiveViews()) {
            SCOPED_TRACE(::testing::Message() << "eye " << view.eye().x << " " << view.eye().y
                                              << " " << view.eye().z);
            EXPECT_GT(checkTraversal(cut, view), 400u) << "the rays must cross several cells";
        }
    }
}

TEST(CutTraversal, isBackToFrontOnThinAndOddGrids) {
    for (const glm::u64vec3 dims :
         {glm::u64vec3(1, 9, 9), glm::u64vec3(9, 9, 1), glm::u64vec3(5, 7, 3)}) {
        SCOPED_TRACE(::testing::Message() << dims.x << "x" << dims.y << "x" << dims.z);
        const Octree octree(randomGrid(dims, 14, 0.2f, false, {0.5, 1.0, 2.0}));
        std::uint64_t pairs = 0;
        for (const Cut& cut : {Cut::byError(octree, 0.0), mixedCut(octree, 9)}) {
            for (const View& view : {View::orthographic({0.7, -0.4, 0.6}),
                                     View::orthographic({0.0, 0.0, -1.0}),
                                     View::perspective({1.1, 4.2, 2.3}, {0.0, 1.0, 0.0}),
                                     View::perspective({-6.0, 20.0, 9.0}, {1.0, -1.0, 0.0})}) {
                pairs += checkTraversal(cut, view);
            }
        }
        EXPECT_GT(pairs, 400u);
    }
}

TEST(CutTraversal, cullsExactlyTheNodesBehindTheEye) {
    const Octree octree(randomGrid(glm::u64vec3(16), 6));
    const Cut cut = mixedCut(octree, 5);
    const View inside = View::perspective({7.2, 7.9, 8.3}, {0.3, -0.2, 1.0});
    std::uint64_t expected = 0;
    traverseBackToFront(cut, View::orthographic({0.0, 0.0, 1.0}), [&](const NodeRef& node) {
        expected += inside.depth(octree.center(node)) > 0.0 ? 1 : 0;
    });
    std::uint64_t visited = 0;
    traverseBackToFront(cut, inside, [&](const NodeRef&) { ++visited; });
    EXPECT_EQ(visited, expected);
    EXPECT_LT(visited, cut.splatCount());
}

TEST(CutTraversal, isDeterministic) {
    const Octree octree(randomGrid({5, 7, 3}, 12));
    const Cut cut = mixedCut(octree, 3);
    const View view = View::perspective({2.0, 3.0, 1.0}, {1.0, 1.0, 0.0});
    std::vector<std::uint64_t> first;
    std::vector<std::uint64_t> second;
    traverseBackToFront(cut, view, [&](const NodeRef& node) { first.push_back(node.index); });
    traverseBackToFront(cut, view, [&](const NodeRef& node) { second.push_back(node.index); });
    EXPECT_FALSE(first.empty());
    EXPECT_EQ(first, second);
}
