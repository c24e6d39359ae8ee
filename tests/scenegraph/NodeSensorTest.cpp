#include "scenegraph/sensors/NodeSensor.h"

#include "scenegraph/Group.h"
#include "scenegraph/sensors/SensorQueue.h"
#include "scenegraph/sensors/SimulatedClock.h"

#include "TestNodes.h"

#include <gtest/gtest.h>

using namespace texsplat::sg;

TEST(NodeSensor, firesOnceForChangesBelowTheNode) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    auto root = Group::create();
    auto cube = test::TestCube::create();
    root->addChild(cube);
    int count = 0;
    NodeSensor sensor(queue, [&] { ++count; });
    sensor.attach(*root);
    EXPECT_EQ(sensor.attachedNode(), root.get());
    cube->size = 3.0f;
    root->addChild(test::TestCube::create());
    queue.process();
    EXPECT_EQ(count, 1);
}

TEST(NodeSensor, detachesWhenTheNodeDies) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    auto root = Group::create();
    int count = 0;
    NodeSensor sensor(queue, [&] { ++count; });
    sensor.attach(*root);
    root->touch();
    root.reset();
    EXPECT_FALSE(sensor.isAttached());
    EXPECT_FALSE(sensor.isScheduled());
    queue.process();
    EXPECT_EQ(count, 0);
}
