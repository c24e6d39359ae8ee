#include "scenegraph/Switch.h"

#include "TestNodes.h"
#include "scenegraph/actions/BoundingBoxAction.h"
#include "scenegraph/actions/SearchAction.h"

#include <gtest/gtest.h>

namespace texsplat::sg {
namespace {

using test::TestCube;

// A switch over cubes of size 2, 4 and 6.
Switch::Ptr makeSwitch() {
    Switch::Ptr node = Switch::create();
    for (float size : {2.0f, 4.0f, 6.0f}) {
        TestCube::Ptr cube = TestCube::create();
        cube->size = size;
        node->addChild(cube);
    }
    return node;
}

Box3 boxOf(Node& node) {
    BoundingBoxAction action;
    action.apply(node);
    return action.boundingBox();
}

TEST(Switch, defaultsToNone) {
    Switch::Ptr node = makeSwitch();
    EXPECT_EQ(node->whichChild.value(), Switch::kNone);
    EXPECT_TRUE(node->whichChild.isDefault());
    EXPECT_TRUE(boxOf(*node).isEmpty());
}

TEST(Switch, traversesTheChosenChild) {
    Switch::Ptr node = makeSwitch();
    node->whichChild = 1;
    EXPECT_EQ(boxOf(*node), Box3(glm::vec3(-2.0f), glm::vec3(2.0f)));
}

TEST(Switch, allTraversesEveryChild) {
    Switch::Ptr node = makeSwitch();
    node->whichChild = Switch::kAll;
    EXPECT_EQ(boxOf(*node), Box3(glm::vec3(-3.0f), glm::vec3(3.0f)));
}

TEST(Switch, outOfRangeAndOtherNegativesTraverseNothing) {
    Switch::Ptr node = makeSwitch();
    node->whichChild = 3;
    EXPECT_TRUE(boxOf(*node).isEmpty());
    node->whichChild = -2;
    EXPECT_TRUE(boxOf(*node).isEmpty());
}

TEST(Switch, searchingAllLooksPastTheChoice) {
    Switch::Ptr node = makeSwitch();
    node->whichChild = 0;
    SearchAction search;
    search.setType(TestCube::classType());
    search.setInterest(SearchAction::Interest::All);
    search.apply(*node);
    EXPECT_EQ(search.paths().size(), 1u);
    search.setSearchingAll(true);
    search.apply(*node);
    EXPECT_EQ(search.paths().size(), 3u);
}

} // namespace
} // namespace texsplat::sg
