#include "scenegraph/actions/SearchAction.h"

#include "TestNodes.h"
#include "scenegraph/Separator.h"

#include <gtest/gtest.h>

namespace texsplat::sg {
namespace {

using test::TestCube;

// root { a: Separator { cube "box" }  b: Group { cube "box" (shared), other } }
struct Scene {
    Scene() {
        root->setName("root");
        box->setName("box");
        a->addChild(box);
        b->addChild(box);
        b->addChild(other);
        root->addChild(a);
        root->addChild(b);
    }
    Group::Ptr root = Group::create();
    Separator::Ptr a = Separator::create();
    Group::Ptr b = Group::create();
    TestCube::Ptr box = TestCube::create();
    TestCube::Ptr other = TestCube::create();
};

TEST(SearchAction, findsTheFirstMatchByName) {
    Scene scene;
    SearchAction search;
    search.setName("box");
    search.apply(*scene.root);
    ASSERT_EQ(search.paths().size(), 1u);
    const Path& path = search.paths()[0];
    ASSERT_EQ(path.length(), 3u);
    EXPECT_EQ(path.head(), scene.root);
    EXPECT_EQ(path.node(1), scene.a);
    EXPECT_EQ(path.tail(), scene.box);
}

TEST(SearchAction, findsAllMatchesByTypeWithPaths) {
    Scene scene;
    SearchAction search;
    search.setType(TestCube::classType());
    search.setInterest(SearchAction::Interest::All);
    search.apply(*scene.root);
    ASSERT_EQ(search.paths().size(), 3u);
    EXPECT_EQ(search.paths()[0].node(1), scene.a);
    EXPECT_EQ(search.paths()[1].node(1), scene.b);
    EXPECT_EQ(search.paths()[2].tail(), scene.other);
}

TEST(SearchAction, typeMatchesDerivedTypesUnlessExact) {
    Scene scene;
    SearchAction search;
    search.setInterest(SearchAction::Interest::All);
    search.setType(Group::classType());
    search.apply(*scene.root);
    EXPECT_EQ(search.paths().size(), 3u);
    search.setType(Group::classType(), false);
    search.apply(*scene.root);
    EXPECT_EQ(search.paths().size(), 2u);
}

TEST(SearchAction, nameAndTypeMustBothMatch) {
    Scene scene;
    SearchAction search;
    search.setInterest(SearchAction::Interest::All);
    search.setName("root");
    search.setType(TestCube::classType());
    search.apply(*scene.root);
    EXPECT_TRUE(search.paths().empty());
    search.setName("box");
    search.apply(*scene.root);
    EXPECT_EQ(search.paths().size(), 2u);
}

} // namespace
} // namespace texsplat::sg
