#include "scenegraph/sensors/FieldSensor.h"

#include "scenegraph/sensors/SensorQueue.h"
#include "scenegraph/sensors/SimulatedClock.h"

#include "TestNodes.h"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

using namespace texsplat::sg;

TEST(FieldSensor, firesAtTheNextProcessingAfterAChange) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    auto cube = test::TestCube::create();
    std::vector<float> seen;
    FieldSensor sensor(queue, [&] { seen.push_back(cube->size.value()); });
    sensor.attach(cube->size);
    EXPECT_EQ(sensor.attachedField(), &cube->size);
    queue.process();
    EXPECT_TRUE(seen.empty());
    cube->size = 3.0f;
    EXPECT_TRUE(sensor.isScheduled());
    EXPECT_TRUE(seen.empty());
    queue.process();
    EXPECT_EQ(seen, std::vector<float>{3.0f});
    EXPECT_FALSE(sensor.isScheduled());
}

TEST(FieldSensor, coalescesChangesBeforeTheNextProcessing) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    auto cube = test::TestCube::create();
    std::vector<float> seen;
    FieldSensor sensor(queue, [&] { seen.push_back(cube->size.value()); });
    sensor.attach(cube->size);
    cube->size = 3.0f;
    cube->size = 4.0f;
    cube->size.touch();
    cube->size = 5.0f;
    queue.process();
    queue.process();
    EXPECT_EQ(seen, std::vector<float>{5.0f});
}

TEST(FieldSensor, firesForChangesThroughAConnection) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    auto source = test::TestCube::create();
    auto target = test::TestCube::create();
    target->size.connectFrom(source->size);
    int count = 0;
    FieldSensor sensor(queue, [&] { ++count; });
    sensor.attach(target->size);
    source->size = 7.0f;
    queue.process();
    EXPECT_EQ(count, 1);
}

TEST(FieldSensor, changeMadeByItsOwnCallbackFiresAtTheNextProcessing) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    auto cube = test::TestCube::create();
    std::vector<float> seen;
    FieldSensor sensor(queue, [&] {
        seen.push_back(cube->size.value());
        if (cube->size.value() < 3.0f) {
            cube->size = cube->size.value() + 1.0f;
        }
    });
    sensor.attach(cube->size);
    cube->size = 1.0f;
    queue.process();
    EXPECT_EQ(seen, std::vector<float>{1.0f});
    queue.process();
    queue.process();
    queue.process();
    EXPECT_EQ(seen, (std::vector<float>{1.0f, 2.0f, 3.0f}));
}

TEST(FieldSensor, detachesAndUnschedulesWhenTheNodeDies) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    auto cube = test::TestCube::create();
    int count = 0;
    int detached = 0;
    FieldSensor sensor(queue, [&] { ++count; });
    sensor.setDetachCallback([&] { ++detached; });
    sensor.attach(cube->size);
    cube->size = 3.0f;
    EXPECT_TRUE(sensor.isScheduled());
    cube.reset();
    EXPECT_FALSE(sensor.isAttached());
    EXPECT_EQ(sensor.attachedField(), nullptr);
    EXPECT_FALSE(sensor.isScheduled());
    EXPECT_EQ(detached, 1);
    queue.process();
    EXPECT_EQ(count, 0);
}

TEST(FieldSensor, detachCallbackMayDestroyTheSensor) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    auto cube = test::TestCube::create();
    auto sensor = std::make_unique<FieldSensor>(queue);
    sensor->setDetachCallback([&sensor] { sensor.reset(); });
    sensor->attach(cube->size);
    cube.reset();
    EXPECT_EQ(sensor, nullptr);
    queue.process();
}

TEST(FieldSensor, detachStopsWatchingAndAttachMoves) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    auto first = test::TestCube::create();
    auto second = test::TestCube::create();
    int count = 0;
    FieldSensor sensor(queue, [&] { ++count; });
    sensor.attach(first->size);
    sensor.attach(second->size);
    EXPECT_EQ(first->size.observerCount(), 0u);
    first->size = 3.0f;
    EXPECT_FALSE(sensor.isScheduled());
    second->size = 3.0f;
    sensor.detach();
    EXPECT_FALSE(sensor.isScheduled());
    EXPECT_EQ(second->size.observerCount(), 0u);
    second->size = 4.0f;
    queue.process();
    EXPECT_EQ(count, 0);
}

TEST(FieldSensor, destroyedSensorStopsWatching) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    auto cube = test::TestCube::create();
    {
        FieldSensor sensor(queue);
        sensor.attach(cube->size);
        cube->size = 2.0f;
    }
    EXPECT_EQ(cube->size.observerCount(), 0u);
    EXPECT_FALSE(queue.hasDelaySensors());
    cube->size = 3.0f;
    queue.process();
}
