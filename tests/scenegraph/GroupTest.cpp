#include "scenegraph/Group.h"

#include "TestNodes.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <memory>

namespace texsplat::sg {
namespace {

using test::TestCube;

std::string errorOf(const std::function<void()>& run) {
    try {
        run();
    } catch (const DataError& error) {
        return error.what();
    }
    return "no error";
}

TEST(Group, childrenAreOrderedAndShared) {
    Group::Ptr a = Group::create();
    Group::Ptr b = Group::create();
    TestCube::Ptr cube = TestCube::create();
    TestCube::Ptr other = TestCube::create();
    a->addChild(cube);
    a->addChild(cube);
    b->addChild(cube);
    a->insertChild(other, 0);
    EXPECT_EQ(a->childCount(), 3u);
    EXPECT_EQ(a->child(0), other);
    EXPECT_EQ(a->findChild(*cube), 1u);
    EXPECT_EQ(b->findChild(*other), std::nullopt);
    EXPECT_EQ(cube->parents().size(), 3u);
    a->replaceChild(0, cube);
    EXPECT_TRUE(other->parents().empty());
    a->removeChild(2);
    EXPECT_EQ(cube->parents().size(), 3u);
    a->removeAllChildren();
    EXPECT_EQ(a->childCount(), 0u);
    EXPECT_EQ(cube->parents().size(), 1u);
}

TEST(Group, changingChildrenNotifiesWithoutSource) {
    Group::Ptr group = Group::create();
    test::RecordingObserver observer;
    group->addObserver(observer);
    group->addChild(TestCube::create());
    group->removeChild(0);
    ASSERT_EQ(observer.sources.size(), 2u);
    EXPECT_EQ(observer.sources[0], nullptr);
    group->removeObserver(observer);
}

TEST(Group, rejectsNullChildrenAndBadIndices) {
    Group::Ptr group = Group::create();
    group->setName("g");
    EXPECT_EQ(errorOf([&] { group->addChild(nullptr); }), "Group(g): cannot add a null child");
    EXPECT_EQ(errorOf([&] { group->removeChild(0); }),
              "Group(g): child index 0 is out of range (0 children)");
    EXPECT_EQ(errorOf([&] { group->insertChild(TestCube::create(), 2); }),
              "Group(g): child index 2 is out of range (0 children)");
}

TEST(Group, rejectsCycles) {
    Group::Ptr outer = Group::create();
    Group::Ptr inner = Group::create();
    outer->setName("outer");
    inner->setName("inner");
    outer->addChild(inner);
    EXPECT_EQ(errorOf([&] { inner->addChild(outer); }),
              "cannot make Group(outer) a child of Group(inner): the scene graph would contain "
              "a cycle");
    EXPECT_EQ(errorOf([&] { outer->addChild(outer); }),
              "cannot make Group(outer) a child of Group(outer): the scene graph would contain "
              "a cycle");
    EXPECT_EQ(inner->childCount(), 0u);
    EXPECT_EQ(outer->childCount(), 1u);
}

TEST(Group, aVeryDeepChainIsBuiltAndDestroyedWithoutRecursion) {
    // Built bottom-up, as a reader does: each new parent has no ancestors to notify yet.
    constexpr int kDepth = 100000;
    Group::Ptr deepest = Group::create();
    Group::Ptr root = deepest;
    for (int i = 0; i < kDepth; ++i) {
        Group::Ptr parent = Group::create();
        parent->addChild(root);
        root = parent;
    }
    std::weak_ptr<Group> weakDeepest = deepest;
    test::RecordingObserver observer;
    root->addObserver(observer);
    deepest->addChild(TestCube::create());
    EXPECT_EQ(observer.subjects.size(), 1u);
    root->removeObserver(observer);
    deepest.reset();
    root.reset();
    EXPECT_TRUE(weakDeepest.expired());
}

} // namespace
} // namespace texsplat::sg
