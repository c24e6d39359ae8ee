#include "scenegraph/sensors/IdleSensor.h"

#include "scenegraph/sensors/OneShotSensor.h"
#include "scenegraph/sensors/SensorQueue.h"
#include "scenegraph/sensors/SimulatedClock.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace texsplat::sg;

TEST(IdleSensor, runsOnlyWhenTheDelayQueueIsEmpty) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    int idleCount = 0;
    IdleSensor idle(queue, [&] { ++idleCount; });
    OneShotSensor busy(queue);
    idle.schedule();
    busy.schedule();
    queue.processIdleQueue(); // delay work pending: not idle
    EXPECT_EQ(idleCount, 0);
    queue.processDelayQueue(); // the delay queue never runs idle sensors
    EXPECT_EQ(idleCount, 0);
    queue.processIdleQueue();
    EXPECT_EQ(idleCount, 1);
}

TEST(IdleSensor, reschedulingStepsOncePerProcessing) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    int step = 0;
    IdleSensor refine(queue);
    refine.setCallback([&] {
        ++step;
        if (step < 3) {
            refine.schedule();
        }
    });
    refine.schedule();
    queue.process();
    EXPECT_EQ(step, 1);
    queue.process();
    queue.process();
    queue.process();
    EXPECT_EQ(step, 3);
    EXPECT_FALSE(refine.isScheduled());
}

TEST(IdleSensor, delayWorkCausedByAnIdleStepRunsFirst) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    std::vector<std::string> order;
    OneShotSensor redraw(queue, [&] { order.push_back("redraw"); });
    IdleSensor first(queue, [&] {
        order.push_back("first");
        redraw.schedule();
    });
    IdleSensor second(queue, [&] { order.push_back("second"); });
    first.schedule();
    second.schedule();
    queue.process();
    EXPECT_EQ(order, std::vector<std::string>{"first"});
    queue.process();
    EXPECT_EQ(order, (std::vector<std::string>{"first", "redraw", "second"}));
}
