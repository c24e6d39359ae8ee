#include "scenegraph/sensors/OneShotSensor.h"

#include "scenegraph/sensors/SensorQueue.h"
#include "scenegraph/sensors/SimulatedClock.h"

#include <gtest/gtest.h>

using namespace texsplat::sg;

TEST(OneShotSensor, runsOnceAtTheNextProcessing) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    int count = 0;
    OneShotSensor sensor(queue, [&] { ++count; });
    queue.process();
    EXPECT_EQ(count, 0);
    sensor.schedule();
    sensor.schedule();
    EXPECT_TRUE(sensor.isScheduled());
    queue.process();
    queue.process();
    EXPECT_EQ(count, 1);
    EXPECT_FALSE(sensor.isScheduled());
}

TEST(OneShotSensor, unscheduledSensorDoesNotRun) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    int count = 0;
    OneShotSensor sensor(queue, [&] { ++count; });
    sensor.schedule();
    sensor.unschedule();
    sensor.unschedule();
    queue.process();
    EXPECT_EQ(count, 0);
}

TEST(OneShotSensor, emptyOrReplacedCallback) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    OneShotSensor sensor(queue);
    sensor.schedule();
    queue.process();
    int count = 0;
    sensor.setCallback([&] { ++count; });
    sensor.schedule();
    queue.process();
    EXPECT_EQ(count, 1);
}
