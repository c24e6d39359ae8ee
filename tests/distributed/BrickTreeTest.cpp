#include "nodes/distributed/BrickTree.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

namespace texsplat::distributed {
namespace {

using volume::IndexBox;

// Whether `bricks` share no voxel and together hold every voxel of `box`.
bool partitions(const std::vector<IndexBox>& bricks, const IndexBox& box) {
    std::int64_t voxels = 0;
    for (std::size_t a = 0; a < bricks.size(); ++a) {
        if (bricks[a].intersection(box) != bricks[a] && !bricks[a].isEmpty()) {
            return false;
        }
        voxels += bricks[a].voxelCount();
        for (std::size_t b = a + 1; b < bricks.size(); ++b) {
            if (!bricks[a].intersection(bricks[b]).isEmpty()) {
                return false;
            }
        }
    }
    return voxels == box.voxelCount();
}

TEST(BrickTree, splitsAnyCountIntoBricksThatPartitionTheBox) {
    const IndexBox box{{0, 0, 0}, {100, 70, 41}};
    for (int count = 1; count <= 13; ++count) {
        for (int sliceAxis = -1; sliceAxis < 3; ++sliceAxis) {
            const BrickTree tree = BrickTree::split(box, count, sliceAxis);
            ASSERT_EQ(tree.bricks().size(), std::size_t(count));
            EXPECT_TRUE(partitions(tree.bricks(), box)) << count << " bricks, axis " << sliceAxis;
            for (const IndexBox& brick : tree.bricks()) {
                EXPECT_FALSE(brick.isEmpty());
            }
        }
    }
}

TEST(BrickTree, splitsAcrossTheSlicingAxisWhileBricksStayThickEnough) {
    const IndexBox cube{{0, 0, 0}, {320, 320, 320}};
    for (int count = 2; count <= 16; ++count) {
        const std::vector<int> axes = BrickTree::split(cube, count, 1).splitAxes();
        EXPECT_TRUE(std::all_of(axes.begin(), axes.end(), [](int axis) { return axis == 1; }))
            << count << " bricks";
    }
    // 32 slabs of 10 voxels would be 32 times wider than thick: some planes run along y.
    const std::vector<int> axes = BrickTree::split(cube, 32, 1).splitAxes();
    EXPECT_TRUE(std::any_of(axes.begin(), axes.end(), [](int axis) { return axis != 1; }));
    // Without a slicing axis, the longest axis.
    EXPECT_EQ(BrickTree::split({{0, 0, 0}, {10, 50, 20}}, 2).splitAxes(), std::vector<int>{1});
}

TEST(BrickTree, putsPlanesOnBlockBoundariesWhenBothSidesKeepVoxels) {
    const BrickTree tree = BrickTree::split({{0, 0, 0}, {100, 8, 8}}, 3, 0);
    for (const IndexBox& brick : tree.bricks()) {
        EXPECT_TRUE(brick.lo.x % 8 == 0 || brick.lo.x == 0) << brick.text();
    }
}

TEST(BrickTree, leavesBricksEmptyWhenTheBoxHasFewerVoxelsThanBricks) {
    const IndexBox box{{0, 0, 0}, {2, 1, 1}};
    const BrickTree tree = BrickTree::split(box, 5, 2);
    EXPECT_TRUE(partitions(tree.bricks(), box));
    const auto empty = std::count_if(tree.bricks().begin(), tree.bricks().end(),
                                     [](const IndexBox& brick) { return brick.isEmpty(); });
    EXPECT_EQ(empty, 3);
}

TEST(BrickTree, ordersBricksBackToFrontForAnOrthographicView) {
    const BrickTree tree = BrickTree::split({{0, 0, 0}, {64, 64, 64}}, 4, 2);
    Viewpoint view;
    view.direction = {0.1, 0.2, 1.0}; // towards +z: the low z slabs are nearest
    const std::vector<int> order = tree.backToFront(view);
    std::vector<std::int64_t> starts;
    for (const int brick : order) {
        starts.push_back(tree.bricks()[static_cast<std::size_t>(brick)].lo.z);
    }
    EXPECT_TRUE(std::is_sorted(starts.rbegin(), starts.rend()));
    view.direction = -view.direction;
    const std::vector<int> reversed = tree.backToFront(view);
    EXPECT_TRUE(std::equal(order.begin(), order.end(), reversed.rbegin()));
}

TEST(BrickTree, ordersTheBrickHoldingAPerspectiveEyeLast) {
    const BrickTree tree = BrickTree::split({{0, 0, 0}, {64, 64, 64}}, 5, -1);
    Viewpoint view;
    view.isPerspective = true;
    for (int brick = 0; brick < 5; ++brick) {
        const IndexBox& box = tree.bricks()[static_cast<std::size_t>(brick)];
        view.eye = (glm::dvec3(box.lo) + glm::dvec3(box.hi)) * 0.5;
        EXPECT_EQ(tree.backToFront(view).back(), brick);
    }
}

TEST(BrickTree, findsTheTreeOfAGridOfBlocks) {
    std::vector<IndexBox> blocks;
    for (int z = 0; z < 2; ++z) {
        for (int y = 0; y < 3; ++y) {
            blocks.push_back({{0, 10 * y, 7 * z}, {16, 10 * y + 10, 7 * z + 7}});
        }
    }
    blocks.push_back({}); // a rank without voxels
    const BrickTree tree = BrickTree::of(blocks);
    EXPECT_EQ(tree.bricks(), blocks);
    std::vector<int> order = tree.backToFront({});
    std::sort(order.begin(), order.end());
    std::vector<int> all(blocks.size());
    std::iota(all.begin(), all.end(), 0);
    EXPECT_EQ(order, all);
}

TEST(BrickTree, refusesBlocksThatOverlap) {
    try {
        BrickTree::of({{{0, 0, 0}, {9, 8, 8}}, {{8, 0, 0}, {16, 8, 8}}});
        FAIL() << "expected DataError";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(),
                     "the blocks of ranks 0 and 1 overlap: [0, 9) x [0, 8) x [0, 8) and [8, 16) "
                     "x [0, 8) x [0, 8) share the voxels [8, 9) x [0, 8) x [0, 8); each voxel "
                     "must belong to one rank (leave ghost cells out of the blocks' boxes)");
    }
}

TEST(BrickTree, refusesAPinwheelOfBlocks) {
    // Four blocks around a fifth in the middle: no plane parts them.
    const std::vector<IndexBox> pinwheel = {{{0, 0, 0}, {2, 1, 1}},
                                            {{2, 0, 0}, {3, 2, 1}},
                                            {{1, 2, 0}, {3, 3, 1}},
                                            {{0, 1, 0}, {1, 3, 1}},
                                            {{1, 1, 0}, {2, 2, 1}}};
    try {
        BrickTree::of(pinwheel);
        FAIL() << "expected DataError";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "no plane parts the blocks of ranks 0, 1, 2, 3, 4 into two "
                                   "groups (a pinwheel of blocks has no visibility order); lay "
                                   "the blocks out as a grid or a k-d tree");
    }
}

} // namespace
} // namespace texsplat::distributed
