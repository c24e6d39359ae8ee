#include "scenegraph/engines/AnimationSpeed.h"

#include "scenegraph/Error.h"
#include "scenegraph/Group.h"
#include "scenegraph/NodeRegistry.h"
#include "scenegraph/engines/ElapsedTime.h"
#include "scenegraph/engines/EngineTypes.h"
#include "scenegraph/engines/TimeInputs.h"
#include "scenegraph/io/SceneReader.h"
#include "scenegraph/sensors/SensorQueue.h"
#include "scenegraph/sensors/SimulatedClock.h"

#include "TestNodes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace texsplat::sg;

namespace {

test::TestCube& cubeAt(Node& root, int index) {
    return static_cast<test::TestCube&>(*static_cast<Group&>(root).child(index));
}

} // namespace

TEST(AnimationSpeed, findsEveryElapsedTimeReachableFromTheRootOnce) {
    auto root = Group::create();
    auto first = test::TestCube::create();
    auto second = test::TestCube::create();
    root->addChild(first);
    root->addChild(second);
    root->addChild(first); // shared: its engine counts once
    auto elapsed = ElapsedTime::create();
    auto driver = ElapsedTime::create();
    auto other = ElapsedTime::create();
    first->size.connectFrom(elapsed->timeOut);
    second->size.connectFrom(other->timeOut);
    other->timeIn.connectFrom(driver->timeOut); // found through the connection chain
    auto unrelated = ElapsedTime::create();     // not in the scene
    AnimationSpeed speed(*root);
    EXPECT_EQ(speed.engineCount(), 3u);
    EXPECT_FALSE(speed.isEmpty());
    EXPECT_EQ(speed.factor(), 1.0f);
    EXPECT_FALSE(speed.isPaused());
    speed.setFactor(2.0f);
    EXPECT_EQ(elapsed->speed.value(), 2.0f);
    EXPECT_EQ(driver->speed.value(), 2.0f);
    EXPECT_EQ(other->speed.value(), 2.0f);
    EXPECT_EQ(unrelated->speed.value(), 1.0f);
    EXPECT_TRUE(AnimationSpeed(*test::TestCube::create()).isEmpty()); // a scene without engines
}

TEST(AnimationSpeed, factorScalesEachEngineOwnSpeedAndOneRestoresIt) {
    registerEngineTypes(NodeRegistry::instance());
    NodeRegistry::instance().add<test::TestCube>();
    Node::Ptr root =
        SceneReader::readString("#Inventor V2.1 ascii\n"
                                "Group {\n"
                                "  TestCube { size = ElapsedTime { } . timeOut }\n"
                                "  TestCube { size = ElapsedTime { speed 0.5 } . timeOut }\n"
                                "  TestCube { size = ElapsedTime { speed -2 } . timeOut }\n"
                                "}\n",
                                "speeds.iv");
    AnimationSpeed speed(*root);
    ASSERT_EQ(speed.engineCount(), 3u);
    const auto speedOf = [&](int index) {
        return static_cast<ElapsedTime&>(cubeAt(*root, index).size.connectedOutput()->engine())
            .speed.value();
    };
    speed.setFactor(4.0f);
    EXPECT_EQ(speedOf(0), 4.0f);
    EXPECT_EQ(speedOf(1), 2.0f);
    EXPECT_EQ(speedOf(2), -8.0f);
    speed.setFactor(1.0f);
    EXPECT_EQ(speedOf(0), 1.0f);
    EXPECT_EQ(speedOf(1), 0.5f);
    EXPECT_EQ(speedOf(2), -2.0f);
}

TEST(AnimationSpeed, pauseFreezesTheOutputsAndResumeGoesOnWithoutAJump) {
    registerEngineTypes(NodeRegistry::instance());
    NodeRegistry::instance().add<test::TestCube>();
    Node::Ptr root = SceneReader::readString(
        "#Inventor V2.1 ascii\nGroup { TestCube { size = ElapsedTime { speed 0.5 } . timeOut } }\n",
        "paused.iv");
    SimulatedClock clock;
    SensorQueue queue(clock);
    connectTimeInputs(*root, queue.timeField());
    AnimationSpeed speed(*root);
    const auto sizeAt = [&](double time) {
        clock.setTime(time);
        queue.process();
        return cubeAt(*root, 0).size.value();
    };
    EXPECT_EQ(sizeAt(0.0), 0.0f);
    EXPECT_EQ(sizeAt(2.0), 1.0f);
    speed.setPaused(true);
    EXPECT_TRUE(speed.isPaused());
    EXPECT_EQ(sizeAt(3.0), 1.0f);
    EXPECT_EQ(sizeAt(10.0), 1.0f);
    speed.setFactor(2.0f); // while paused: takes effect on resume
    EXPECT_EQ(sizeAt(12.0), 1.0f);
    speed.setPaused(false);
    EXPECT_EQ(sizeAt(12.0), 1.0f); // no jump
    EXPECT_EQ(sizeAt(13.0), 2.0f); // 2 x 0.5 per second
}

TEST(AnimationSpeed, leavesConnectedSpeedsAloneAndRefusesANonFiniteFactor) {
    auto root = Group::create();
    auto cube = test::TestCube::create();
    root->addChild(cube);
    auto elapsed = ElapsedTime::create();
    auto rate = ElapsedTime::create();
    cube->size.connectFrom(elapsed->timeOut);
    elapsed->speed.connectFrom(rate->timeOut); // its speed is animated: not the control's
    AnimationSpeed speed(*root);
    EXPECT_EQ(speed.engineCount(), 1u); // `rate` only
    speed.setFactor(3.0f);
    EXPECT_EQ(rate->speed.value(), 3.0f);
    EXPECT_TRUE(elapsed->speed.isConnected());
    try {
        speed.setFactor(std::numeric_limits<float>::quiet_NaN());
        FAIL() << "expected a DataError";
    } catch (const texsplat::DataError& error) {
        EXPECT_STREQ(error.what(), "AnimationSpeed: the speed factor must be finite, got nan");
    }
    EXPECT_EQ(speed.factor(), 3.0f);
}
