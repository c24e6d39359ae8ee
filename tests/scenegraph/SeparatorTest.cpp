#include "scenegraph/Separator.h"

#include "TestNodes.h"
#include "scenegraph/actions/BoundingBoxAction.h"

#include <gtest/gtest.h>

namespace texsplat::sg {
namespace {

using test::TestCube;
using test::TestTranslation;

TestTranslation::Ptr translation(const glm::vec3& offset) {
    TestTranslation::Ptr node = TestTranslation::create();
    node->translation = offset;
    return node;
}

TEST(Separator, restoresTheStateForItsSiblings) {
    // Separator { Translation 10 0 0  Cube }  Cube: the second cube is not moved.
    Group::Ptr root = Group::create();
    Separator::Ptr separator = Separator::create();
    separator->addChild(translation(glm::vec3(10.0f, 0.0f, 0.0f)));
    separator->addChild(TestCube::create());
    root->addChild(separator);
    root->addChild(TestCube::create());
    BoundingBoxAction action;
    action.apply(*root);
    EXPECT_EQ(action.boundingBox(), Box3(glm::vec3(-1.0f), glm::vec3(11.0f, 1.0f, 1.0f)));
    EXPECT_EQ(action.state().depth(), 0u);
}

TEST(Separator, aGroupDoesNotRestore) {
    Group::Ptr root = Group::create();
    Group::Ptr group = Group::create();
    group->addChild(translation(glm::vec3(10.0f, 0.0f, 0.0f)));
    root->addChild(group);
    root->addChild(TestCube::create());
    BoundingBoxAction action;
    action.apply(*root);
    EXPECT_EQ(action.boundingBox(),
        Box3(glm::vec3(9.0f, -1.0f, -1.0f), glm::vec3(11.0f, 1.0f, 1.0f)));
}

TEST(Separator, isRegisteredAsAGroup) {
    Separator::Ptr separator = Separator::create();
    EXPECT_EQ(separator->typeName(), "Separator");
    EXPECT_TRUE(separator->type().isDerivedFrom(Group::classType()));
    EXPECT_TRUE(separator->fields().empty());
}

} // namespace
} // namespace texsplat::sg
