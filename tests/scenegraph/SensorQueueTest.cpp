#include "scenegraph/sensors/SensorQueue.h"

#include "scenegraph/Error.h"
#include "scenegraph/engines/ElapsedTime.h"
#include "scenegraph/sensors/Clock.h"
#include "scenegraph/sensors/FieldSensor.h"
#include "scenegraph/sensors/IdleSensor.h"
#include "scenegraph/sensors/OneShotSensor.h"
#include "scenegraph/sensors/SimulatedClock.h"
#include "scenegraph/sensors/TimerSensor.h"

#include "TestNodes.h"

#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

using namespace texsplat;
using namespace texsplat::sg;

TEST(SensorQueue, processRunsTimersThenDelayThenIdle) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    std::vector<std::string> order;
    IdleSensor idle(queue, [&] { order.push_back("idle"); });
    OneShotSensor oneShot(queue, [&] { order.push_back("oneShot"); });
    TimerSensor timer(queue, [&] { order.push_back("timer"); });
    idle.schedule();
    oneShot.schedule();
    timer.setInterval(1.0);
    timer.schedule();
    clock.setTime(1.0);
    queue.process();
    EXPECT_EQ(order, (std::vector<std::string>{"timer", "oneShot", "idle"}));
}

TEST(SensorQueue, delaySensorsRunByPriorityThenInScheduleOrder) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    std::vector<int> order;
    OneShotSensor late(queue, [&] { order.push_back(3); });
    OneShotSensor first(queue, [&] { order.push_back(1); });
    OneShotSensor second(queue, [&] { order.push_back(2); });
    OneShotSensor urgent(queue, [&] { order.push_back(0); });
    late.setPriority(200);
    urgent.setPriority(10);
    late.schedule();
    first.schedule();
    second.schedule();
    urgent.schedule();
    queue.process();
    EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3}));
    EXPECT_EQ(first.priority(), DelaySensor::kDefaultPriority);
}

TEST(SensorQueue, sensorScheduledDuringAPassRunsInItButEachSensorOnlyOnce) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    std::vector<std::string> order;
    OneShotSensor other(queue, [&] { order.push_back("other"); });
    OneShotSensor self(queue);
    self.setCallback([&] {
        order.push_back("self");
        other.schedule(); // not run yet in this pass: runs in it
        self.schedule();  // already ran in this pass: waits for the next
    });
    self.schedule();
    queue.process();
    EXPECT_EQ(order, (std::vector<std::string>{"self", "other"}));
    EXPECT_TRUE(self.isScheduled());
    queue.process();
    EXPECT_EQ(order, (std::vector<std::string>{"self", "other", "self", "other"}));
}

TEST(SensorQueue, callbackMayUnscheduleOrDestroyAnotherScheduledSensor) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    std::vector<std::string> order;
    auto doomed = std::make_unique<OneShotSensor>(queue, [&] { order.push_back("doomed"); });
    OneShotSensor spared(queue, [&] { order.push_back("spared"); });
    OneShotSensor killer(queue, [&] {
        order.push_back("killer");
        doomed.reset();
        spared.unschedule();
    });
    killer.schedule();
    doomed->schedule();
    spared.schedule();
    queue.process();
    EXPECT_EQ(order, std::vector<std::string>{"killer"});
    EXPECT_FALSE(queue.hasDelaySensors());
}

TEST(SensorQueue, processingFromACallbackThrows) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    std::string message;
    OneShotSensor nested(queue, [&] {
        try {
            queue.processDelayQueue();
        } catch (const DataError& error) {
            message = error.what();
        }
    });
    nested.schedule();
    queue.process();
    EXPECT_EQ(message, "SensorQueue::processDelayQueue(): called from a sensor callback; "
                       "processing is not reentrant");
}

TEST(SensorQueue, exceptionFromACallbackLeavesTheQueueUsable) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    int count = 0;
    OneShotSensor thrower(queue, [] { throw std::runtime_error("callback failed"); });
    OneShotSensor counter(queue, [&] { ++count; });
    thrower.schedule();
    counter.schedule();
    EXPECT_THROW(queue.process(), std::runtime_error);
    EXPECT_FALSE(thrower.isScheduled());
    EXPECT_TRUE(counter.isScheduled());
    queue.process();
    EXPECT_EQ(count, 1);
}

TEST(SensorQueue, sensorsOutlivingTheirQueueAreDetached) {
    SimulatedClock clock;
    auto node = test::TestCube::create();
    auto queue = std::make_unique<SensorQueue>(clock);
    OneShotSensor oneShot(*queue);
    FieldSensor fieldSensor(*queue);
    TimerSensor timer(*queue);
    fieldSensor.attach(node->size);
    oneShot.schedule();
    timer.schedule();
    queue.reset();
    EXPECT_EQ(oneShot.queue(), nullptr);
    EXPECT_FALSE(oneShot.isScheduled());
    EXPECT_FALSE(timer.isScheduled());
    EXPECT_FALSE(fieldSensor.isAttached());
    EXPECT_EQ(node->size.observerCount(), 0u);
    node->size = 3.0f;
    oneShot.unschedule();
    try {
        oneShot.schedule();
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "Sensor::schedule(): the sensor's SensorQueue no longer exists");
    }
    try {
        timer.schedule();
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(),
                     "TimerSensor::schedule(): the sensor's SensorQueue no longer exists");
    }
    try {
        fieldSensor.attach(node->size);
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(),
                     "DataSensor::attach(): the sensor's SensorQueue no longer exists");
    }
}

TEST(SensorQueue, timeFieldFollowsTheClockAtTimerPassesOnly) {
    SimulatedClock clock(1.0);
    SensorQueue queue(clock);
    test::RecordingObserver observer;
    queue.timeField().addObserver(observer);
    EXPECT_EQ(queue.timeField().value(), 1.0f);
    clock.setTime(2.5);
    EXPECT_EQ(queue.time(), 2.5);
    queue.processDelayQueue();
    EXPECT_EQ(queue.timeField().value(), 1.0f);
    queue.process();
    EXPECT_EQ(queue.timeField().value(), 2.5f);
    queue.process(); // same time: no notification
    EXPECT_EQ(observer.subjects.size(), 1u);
    clock.setTime(3.0);
    queue.processTimerQueue();
    EXPECT_EQ(queue.timeField().value(), 3.0f);
    EXPECT_EQ(observer.subjects.size(), 2u);
    queue.timeField().removeObserver(observer);
}

TEST(SensorQueue, everySensorOfAPassSeesTheSameTime) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    std::vector<double> seen;
    OneShotSensor advancer(queue, [&] {
        seen.push_back(queue.time());
        clock.advance(1.0); // e.g. a slow callback on a real clock
    });
    OneShotSensor reader(queue, [&] { seen.push_back(queue.time()); });
    advancer.schedule();
    reader.schedule();
    queue.process();
    EXPECT_EQ(seen, (std::vector<double>{0.0, 0.0}));
    EXPECT_EQ(queue.time(), 1.0);
}

TEST(SensorQueue, reportsWhatIsPending) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    TimerSensor timer(queue);
    OneShotSensor oneShot(queue);
    IdleSensor idle(queue);
    EXPECT_FALSE(queue.nextTimerTime().has_value());
    EXPECT_FALSE(queue.hasDelaySensors());
    EXPECT_FALSE(queue.hasIdleSensors());
    timer.setInterval(0.25);
    timer.schedule();
    oneShot.schedule();
    idle.schedule();
    EXPECT_EQ(queue.nextTimerTime(), 0.25);
    EXPECT_TRUE(queue.hasDelaySensors());
    EXPECT_TRUE(queue.hasIdleSensors());
}

namespace {

/// One simulated run: an ElapsedTime drives a cube, a field sensor and a timer log what they
/// see; returns the log.
std::vector<std::string> simulatedRun() {
    SimulatedClock clock;
    SensorQueue queue(clock);
    std::vector<std::string> log;
    auto cube = test::TestCube::create();
    auto elapsed = ElapsedTime::create();
    elapsed->speed = 1.5f;
    elapsed->timeIn.connectFrom(queue.timeField());
    cube->size.connectFrom(elapsed->timeOut);
    FieldSensor sizeSensor(queue, [&] {
        log.push_back("size " + std::to_string(queue.time()) + " " +
                      std::to_string(cube->size.value()));
    });
    sizeSensor.attach(cube->size);
    TimerSensor timer(queue);
    timer.setCallback([&] {
        log.push_back("timer " + std::to_string(timer.lastTriggerTime()) + " missed " +
                      std::to_string(timer.missedTriggerCount()));
    });
    timer.setInterval(0.1);
    timer.schedule();
    for (int frame = 0; frame < 100; ++frame) {
        clock.advance(frame % 10 == 0 ? 0.25 : 1.0 / 30.0);
        queue.process();
    }
    return log;
}

} // namespace

TEST(SensorQueue, twoIdenticalSimulatedRunsAreIdentical) {
    const std::vector<std::string> first = simulatedRun();
    const std::vector<std::string> second = simulatedRun();
    EXPECT_GT(first.size(), 100u);
    EXPECT_EQ(first, second);
}

namespace {

/// A broken clock: reads nan after `broken` is set.
class BrokenClock final : public Clock {
public:
    double now() const override {
        return broken ? std::numeric_limits<double>::quiet_NaN() : 0.0;
    }
    bool broken = false;
};

} // namespace

TEST(SensorQueue, rejectsANonFiniteClockReading) {
    BrokenClock clock;
    SensorQueue queue(clock);
    TimerSensor timer(queue);
    clock.broken = true;
    try {
        queue.process();
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "SensorQueue: the clock returned a non-finite time nan");
    }
    EXPECT_THROW(timer.schedule(), DataError);
    clock.broken = false;
    queue.process(); // a failed pass did not leave the queue marked as processing
}

TEST(SensorQueue, manySelfReschedulingSensorsRunOncePerPass) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    constexpr int kCount = 10000;
    int runs = 0;
    std::vector<std::unique_ptr<OneShotSensor>> sensors;
    for (int i = 0; i < kCount; ++i) {
        sensors.push_back(std::make_unique<OneShotSensor>(queue));
        OneShotSensor& sensor = *sensors.back();
        sensor.setCallback([&runs, &sensor] {
            ++runs;
            sensor.schedule();
        });
        sensor.schedule();
    }
    queue.process();
    EXPECT_EQ(runs, kCount);
    queue.process();
    EXPECT_EQ(runs, 2 * kCount);
    EXPECT_TRUE(queue.hasDelaySensors());
}
