#include "scenegraph/engines/TimeInputs.h"

#include "scenegraph/Group.h"
#include "scenegraph/NodeRegistry.h"
#include "scenegraph/engines/ElapsedTime.h"
#include "scenegraph/engines/EngineTypes.h"
#include "scenegraph/io/SceneReader.h"
#include "scenegraph/io/WriteAction.h"
#include "scenegraph/sensors/SensorQueue.h"
#include "scenegraph/sensors/SimulatedClock.h"

#include "TestNodes.h"

#include <gtest/gtest.h>

using namespace texsplat::sg;

TEST(TimeInputs, connectsEveryUnconnectedEngineTimeInputOnce) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    auto root = Group::create();
    auto first = test::TestCube::create();
    auto second = test::TestCube::create();
    root->addChild(first);
    root->addChild(second);
    root->addChild(first);
    auto elapsed = ElapsedTime::create();
    auto other = ElapsedTime::create();
    auto driver = ElapsedTime::create();
    first->size.connectFrom(elapsed->timeOut);
    second->size.connectFrom(other->timeOut);
    other->timeIn.connectFrom(driver->timeOut); // already has its time: left alone
    EXPECT_EQ(connectTimeInputs(*root, queue.timeField()), 2u);
    EXPECT_EQ(elapsed->timeIn.connectedField(), &queue.timeField());
    EXPECT_EQ(driver->timeIn.connectedField(), &queue.timeField());
    EXPECT_EQ(other->timeIn.connectedOutput(), &driver->timeOut);
    EXPECT_EQ(connectTimeInputs(*root, queue.timeField()), 0u);
}

TEST(TimeInputs, sceneFileEnginesRunOnTheQueueTimeAndAreWrittenWithoutIt) {
    registerEngineTypes(NodeRegistry::instance());
    NodeRegistry::instance().add<test::TestCube>();
    const std::string text = "#Inventor V2.1 ascii\n\n"
                             "Separator {\n"
                             "    TestCube {\n"
                             "        size = ElapsedTime {\n"
                             "            speed 2\n"
                             "        } . timeOut\n"
                             "    }\n"
                             "}\n";
    Node::Ptr root = SceneReader::readString(text, "animated.iv");
    SimulatedClock clock(50.0);
    SensorQueue queue(clock);
    EXPECT_EQ(connectTimeInputs(*root, queue.timeField()), 1u);
    clock.setTime(51.5);
    queue.process();
    auto& cube = static_cast<test::TestCube&>(*static_cast<Group&>(*root).child(0));
    EXPECT_EQ(cube.size.value(), 3.0f);
    const std::string written = WriteAction::writeString(*root);
    EXPECT_EQ(written.find("timeIn"), std::string::npos) << written;
    EXPECT_NE(written.find("speed 2"), std::string::npos) << written;
}
