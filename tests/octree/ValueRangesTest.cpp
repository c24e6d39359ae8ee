#include "octree/ValueRanges.h"

#include <gtest/gtest.h>

#include <vector>

namespace texsplat::octree {
namespace {

TEST(ValueRanges, keepsTheSmallestAndLargestValueOfEachBlock) {
    ValueRanges ranges(glm::u64vec3(20, 9, 17)); // 3 x 2 x 3 blocks, clipped at the far faces
    EXPECT_EQ(ranges.blockCount(), 0u);
    EXPECT_EQ(ranges.valueRange(), glm::vec2(0.0f));
    ranges.add({1, 2, 3}, 0.5f);
    ranges.add({7, 7, 7}, -2.0f);  // same block (0, 0, 0)
    ranges.add({19, 8, 16}, 4.0f); // the far corner block (2, 1, 2)
    ranges.add({16, 8, 16}, 3.0f);
    EXPECT_EQ(ranges.blockCount(), 2u);
    EXPECT_EQ(ranges.valueRange(), glm::vec2(-2.0f, 4.0f));
    std::vector<glm::vec2> seen;
    const std::vector<bool> visible = ranges.visibleBlocks([&](float minimum, float maximum) {
        seen.emplace_back(minimum, maximum);
        return maximum > 3.5f;
    });
    ASSERT_EQ(seen.size(), 2u);
    EXPECT_EQ(seen[0], glm::vec2(-2.0f, 0.5f));
    EXPECT_EQ(seen[1], glm::vec2(3.0f, 4.0f));
    EXPECT_FALSE(ranges.isVisibleBlock(visible, {0, 0, 0}));
    EXPECT_TRUE(ranges.isVisibleBlock(visible, {17, 8, 16}));
    EXPECT_FALSE(ranges.isVisibleBlock(visible, {9, 0, 0})) << "a block holding no value";
}

TEST(ValueRanges, costsATableEntryPerBlockOfTheBoxAndARangePerBlockHoldingAValue) {
    ValueRanges ranges(glm::u64vec3(1024));
    ranges.add({512, 512, 512}, 1.0f);
    EXPECT_GE(ranges.memoryBytes(), 128u * 128u * 128u * 4u + 8u);
    EXPECT_LT(ranges.memoryBytes(), 128u * 128u * 128u * 4u + 1024u);
}

} // namespace
} // namespace texsplat::octree
