#include "octree/Splat.h"

#include <gtest/gtest.h>

#include <cstddef>

using texsplat::octree::Splat;
using texsplat::octree::SplatList;
using texsplat::octree::SplatVector;

TEST(Splat, layoutIsTwoPackedVec4s) {
    EXPECT_EQ(sizeof(Splat), 32u);
    EXPECT_EQ(offsetof(Splat, position), 0u);
    EXPECT_EQ(offsetof(Splat, size), 12u);
    EXPECT_EQ(offsetof(Splat, color), 16u);
    EXPECT_EQ(offsetof(Splat, extinction), 28u);
    EXPECT_EQ(sizeof(SplatVector), 16u);
}

TEST(SplatList, keepsScalarSplatsInOrder) {
    SplatList list;
    EXPECT_TRUE(list.isEmpty());
    Splat first;
    first.size = 2.0f;
    Splat second;
    second.extinction = 0.5f;
    list.add(first);
    list.add(second);
    ASSERT_EQ(list.size(), 2u);
    EXPECT_FALSE(list.hasVectors());
    EXPECT_EQ(list.splats()[0].size, 2.0f);
    EXPECT_EQ(list.splats()[1].extinction, 0.5f);
    list.clear();
    EXPECT_TRUE(list.isEmpty());
}

TEST(SplatList, keepsVectorsParallelToSplats) {
    SplatList list;
    list.reserve(4, true);
    SplatVector vector;
    vector.vector = glm::vec3(1.0f, 0.0f, 0.0f);
    vector.row = 3;
    vector.column = 7;
    list.add(Splat{}, vector);
    ASSERT_TRUE(list.hasVectors());
    ASSERT_EQ(list.vectors().size(), list.size());
    EXPECT_EQ(list.vectors()[0].row, 3);
    EXPECT_EQ(list.vectors()[0].column, 7);
}
