#include "octree/Splat.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>

using texsplat::octree::Splat;
using texsplat::octree::SplatList;
using texsplat::octree::SplatMark;

TEST(Splat, layoutIsTwoPackedVec4s) {
    EXPECT_EQ(sizeof(Splat), 32u);
    EXPECT_EQ(offsetof(Splat, position), 0u);
    EXPECT_EQ(offsetof(Splat, size), 12u);
    EXPECT_EQ(offsetof(Splat, color), 16u);
    EXPECT_EQ(offsetof(Splat, extinction), 28u);
    EXPECT_EQ(sizeof(SplatMark), 44u);
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
    EXPECT_FALSE(list.hasMarks());
    EXPECT_EQ(list.splats()[0].size, 2.0f);
    EXPECT_EQ(list.splats()[1].extinction, 0.5f);
    list.clear();
    EXPECT_TRUE(list.isEmpty());
}

TEST(SplatList, keepsEachSplatsMarksInOrder) {
    SplatList list;
    list.reserve(4, true);
    SplatMark marks[3];
    for (int i = 0; i < 3; ++i) {
        marks[i].vector = glm::vec3(1.0f, 0.0f, 0.0f);
        marks[i].phase = 0.25f * static_cast<float>(i);
    }
    list.add(Splat{}, marks, 2);
    list.add(Splat{}, marks, 0);
    list.add(Splat{}, marks + 2, 1);
    ASSERT_TRUE(list.hasMarks());
    ASSERT_EQ(list.markBegins().size(), list.size() + 1);
    ASSERT_EQ(list.marks().size(), 3u);
    EXPECT_EQ(list.markBegin(0), 0u);
    EXPECT_EQ(list.markBegin(1), 2u);
    EXPECT_EQ(list.markBegin(2), 2u);
    EXPECT_EQ(list.markBegin(3), 3u);
    EXPECT_EQ(list.marks()[1].phase, 0.25f);
    EXPECT_EQ(list.marks()[2].phase, 0.5f);
    list.clear();
    EXPECT_FALSE(list.hasMarks());
    EXPECT_TRUE(list.marks().empty());
}

TEST(SplatList, everyChangeMovesTheRevisionOn) {
    // A backend keeps what it uploaded of a list while the list's revision stays; a node
    // refills one list frame after frame, so every change must move it on, never back (an
    // assigned list brings its own, smaller count).
    SplatList list;
    std::uint64_t last = list.revision();
    const auto movedOn = [&] {
        const bool grew = list.revision() > last;
        last = list.revision();
        return grew;
    };
    list.add(Splat{});
    EXPECT_TRUE(movedOn());
    list.resize(5, false);
    EXPECT_TRUE(movedOn());
    (void)list.writableSplats();
    EXPECT_TRUE(movedOn());
    list.resize(5, true, 9);
    EXPECT_TRUE(movedOn());
    EXPECT_EQ(list.marks().size(), 9u);
    (void)list.writableMarks();
    EXPECT_TRUE(movedOn());
    (void)list.writableMarkBegins();
    EXPECT_TRUE(movedOn());
    list.clear();
    EXPECT_TRUE(movedOn());
    SplatList fresh;
    fresh.add(Splat{});
    list = fresh;
    EXPECT_TRUE(movedOn());
    list = SplatList();
    EXPECT_TRUE(movedOn());
    EXPECT_EQ(list.size(), 0u);
}
