#include "scenegraph/actions/BoundingBoxAction.h"

#include "TestNodes.h"
#include "scenegraph/Separator.h"

#include <gtest/gtest.h>

namespace texsplat::sg {
namespace {

using test::TestCube;
using test::TestTranslation;

TEST(BoundingBoxAction, emptyGraphHasEmptyBox) {
    Group::Ptr root = Group::create();
    BoundingBoxAction action;
    action.apply(*root);
    EXPECT_TRUE(action.boundingBox().isEmpty());
}

TEST(BoundingBoxAction, transformsAccumulateDownThePath) {
    // Translation(1,0,0) Separator { Translation(0,2,0) Cube(size 2) }  Cube(size 4)
    Group::Ptr root = Group::create();
    TestTranslation::Ptr first = TestTranslation::create();
    first->translation = glm::vec3(1.0f, 0.0f, 0.0f);
    Separator::Ptr separator = Separator::create();
    TestTranslation::Ptr second = TestTranslation::create();
    second->translation = glm::vec3(0.0f, 2.0f, 0.0f);
    separator->addChild(second);
    separator->addChild(TestCube::create());
    TestCube::Ptr big = TestCube::create();
    big->size = 4.0f;
    root->addChild(first);
    root->addChild(separator);
    root->addChild(big);

    BoundingBoxAction action;
    action.apply(*root);
    // First cube spans [0,2]x[1,3]x[-1,1]; the big one [-1,3]x[-2,2]x[-2,2].
    EXPECT_EQ(action.boundingBox(),
        Box3(glm::vec3(-1.0f, -2.0f, -2.0f), glm::vec3(3.0f, 3.0f, 2.0f)));

    // A second apply starts from scratch; the big cube is now the point (1,0,0).
    big->size = 0.0f;
    action.apply(*root);
    EXPECT_EQ(action.boundingBox(),
        Box3(glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(2.0f, 3.0f, 1.0f)));
}

TEST(BoundingBoxAction, sharedNodesCountOncePerPath) {
    TestCube::Ptr cube = TestCube::create();
    Group::Ptr root = Group::create();
    for (float x : {-5.0f, 5.0f}) {
        Separator::Ptr separator = Separator::create();
        TestTranslation::Ptr move = TestTranslation::create();
        move->translation = glm::vec3(x, 0.0f, 0.0f);
        separator->addChild(move);
        separator->addChild(cube);
        root->addChild(separator);
    }
    BoundingBoxAction action;
    action.apply(*root);
    EXPECT_EQ(action.boundingBox(),
        Box3(glm::vec3(-6.0f, -1.0f, -1.0f), glm::vec3(6.0f, 1.0f, 1.0f)));
}

TEST(BoundingBoxAction, extendByPointUsesTheModelMatrix) {
    Group::Ptr root = Group::create();
    BoundingBoxAction action;
    action.apply(*root);
    action.state().modify<ModelMatrixElement>().matrix[3] = glm::vec4(1.0f, 1.0f, 1.0f, 1.0f);
    action.extendBy(glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(action.boundingBox(), Box3(glm::vec3(2.0f, 1.0f, 1.0f), glm::vec3(2.0f, 1.0f, 1.0f)));
}

} // namespace
} // namespace texsplat::sg
