#include "scenegraph/Engine.h"

#include "TestNodes.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <memory>

namespace texsplat::sg {
namespace {

using test::TestCube;
using test::TestDoubler;

TEST(Engine, isATypeWithNamedInputsAndOutputs) {
    TestDoubler::Ptr doubler = TestDoubler::create();
    EXPECT_TRUE(doubler->type().isDerivedFrom(Engine::classType()));
    EXPECT_EQ(doubler->asNode(), nullptr);
    EXPECT_EQ(doubler->findField("input"), &doubler->input);
    EXPECT_EQ(doubler->findOutput("output"), &doubler->output);
    EXPECT_EQ(doubler->findOutput("nothing"), nullptr);
    EXPECT_EQ(doubler->output.typeName(), "SFFloat");
    EXPECT_EQ(doubler->output.fullName(), "TestDoubler.output");
}

TEST(Engine, evaluatesLazilyWhenNotConnected) {
    TestDoubler::Ptr doubler = TestDoubler::create();
    doubler->input = 2.0f;
    doubler->input = 3.0f;
    EXPECT_EQ(doubler->evaluations, 0);
    EXPECT_EQ(doubler->output.value(), 6.0f);
    EXPECT_EQ(doubler->evaluations, 1);
    EXPECT_EQ(doubler->output.value(), 6.0f);
    EXPECT_EQ(doubler->evaluations, 1);
}

TEST(Engine, pushesToConnectedFieldsOnInputChange) {
    TestDoubler::Ptr doubler = TestDoubler::create();
    TestCube::Ptr cube = TestCube::create();
    cube->size.connectFrom(doubler->output);
    EXPECT_EQ(cube->size.connectedOutput(), &doubler->output);
    EXPECT_EQ(cube->size.value(), 2.0f);
    test::RecordingObserver observer;
    cube->addObserver(observer);
    doubler->input = 10.0f;
    EXPECT_EQ(cube->size.value(), 20.0f);
    EXPECT_EQ(observer.subjects.size(), 1u);
    // The writer writes the connection; the value it carries is not a user setting.
    EXPECT_TRUE(cube->size.isDefault());
    cube->removeObserver(observer);
}

TEST(Engine, connectedFieldKeepsTheEngineAlive) {
    TestCube::Ptr cube = TestCube::create();
    std::weak_ptr<TestDoubler> weak;
    {
        TestDoubler::Ptr doubler = TestDoubler::create();
        weak = doubler;
        cube->size.connectFrom(doubler->output);
    }
    ASSERT_FALSE(weak.expired());
    weak.lock()->input = 4.0f;
    EXPECT_EQ(cube->size.value(), 8.0f);
    cube->size.disconnect();
    EXPECT_TRUE(weak.expired());
}

TEST(Engine, engineInputsCanFollowFields) {
    TestCube::Ptr source = TestCube::create();
    TestCube::Ptr target = TestCube::create();
    TestDoubler::Ptr doubler = TestDoubler::create();
    doubler->input.connectFrom(source->size);
    target->size.connectFrom(doubler->output);
    source->size = 1.25f;
    EXPECT_EQ(target->size.value(), 2.5f);
}

TEST(Engine, outputTypeMustMatch) {
    TestDoubler::Ptr doubler = TestDoubler::create();
    test::TestTranslation::Ptr move = test::TestTranslation::create();
    try {
        move->translation.connectFrom(doubler->output);
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "cannot connect SFVec3f TestTranslation.translation from "
                                   "SFFloat TestDoubler.output: the types differ");
    }
}

} // namespace
} // namespace texsplat::sg
