#include "scenegraph/sensors/TimerSensor.h"

#include "scenegraph/Error.h"
#include "scenegraph/sensors/SensorQueue.h"
#include "scenegraph/sensors/SimulatedClock.h"

#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <vector>

using namespace texsplat;
using namespace texsplat::sg;

TEST(TimerSensor, firstTriggerIsOneIntervalAfterSchedule) {
    SimulatedClock clock(5.0);
    SensorQueue queue(clock);
    std::vector<double> times;
    TimerSensor timer(queue, [&] { times.push_back(queue.time()); });
    timer.setInterval(0.5);
    timer.schedule();
    EXPECT_TRUE(timer.isScheduled());
    EXPECT_EQ(timer.baseTime(), 5.0);
    EXPECT_EQ(timer.triggerTime(), 5.5);
    queue.process();
    EXPECT_TRUE(times.empty());
    clock.setTime(5.5);
    queue.process();
    EXPECT_EQ(times, std::vector<double>{5.5});
    EXPECT_TRUE(timer.isScheduled());
    EXPECT_EQ(timer.triggerTime(), 6.0);
}

TEST(TimerSensor, triggersDoNotDriftOver10000Intervals) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    const double interval = 0.1;
    std::int64_t count = 0;
    std::int64_t offGrid = 0;
    TimerSensor timer(queue);
    timer.setCallback([&] {
        // Trigger n is exactly at base + n * interval, never at base + a sum of n steps.
        offGrid += timer.lastTriggerTime() != static_cast<double>(count) * interval ? 1 : 0;
        ++count;
    });
    timer.setInterval(interval);
    timer.setBaseTime(0.0);
    timer.schedule();
    // Trigger 0 is at the base time itself; then the queue runs late by a varying amount (up
    // to 0.6 interval) at every frame.
    for (int n = 0; n <= 10000; ++n) {
        clock.setTime(n * interval + (n % 7) * 0.01);
        queue.process();
    }
    EXPECT_EQ(count, 10001);
    EXPECT_EQ(offGrid, 0);
    EXPECT_EQ(timer.lastTriggerTime(), 10000 * interval);
    EXPECT_EQ(timer.triggerTime(), 10001 * interval);
    double summed = 0.0;
    for (int n = 0; n < 10000; ++n) {
        summed += interval;
    }
    // What a timer that adds the interval to its last trigger would have drifted to.
    EXPECT_NE(summed, timer.lastTriggerTime());
}

TEST(TimerSensor, lateQueueCoalescesMissedTriggers) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    int count = 0;
    TimerSensor timer(queue, [&] { ++count; });
    timer.setInterval(1.0);
    timer.schedule();
    clock.setTime(3.5);
    queue.process();
    EXPECT_EQ(count, 1);
    EXPECT_EQ(timer.lastTriggerTime(), 1.0);
    EXPECT_EQ(timer.missedTriggerCount(), 2);
    EXPECT_EQ(timer.triggerTime(), 4.0);
    clock.setTime(4.0);
    queue.process();
    EXPECT_EQ(count, 2);
    EXPECT_EQ(timer.missedTriggerCount(), 0);
    EXPECT_EQ(timer.triggerTime(), 5.0);
}

TEST(TimerSensor, explicitBaseTimeStartsAtFirstGridTimeNotBeforeNow) {
    SimulatedClock clock(2.25);
    SensorQueue queue(clock);
    TimerSensor timer(queue);
    timer.setInterval(0.5);
    timer.setBaseTime(10.0);
    timer.schedule();
    EXPECT_EQ(timer.triggerTime(), 10.0);
    timer.unschedule();
    timer.setBaseTime(1.0);
    timer.schedule();
    EXPECT_EQ(timer.triggerTime(), 2.5);
    timer.unschedule();
    timer.setBaseTime(0.25);
    timer.schedule();
    EXPECT_EQ(timer.triggerTime(), 2.25);
}

TEST(TimerSensor, changingTheIntervalMovesAScheduledTimer) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    TimerSensor timer(queue);
    timer.setInterval(1.0);
    timer.schedule();
    clock.setTime(3.2);
    timer.setInterval(0.5);
    EXPECT_EQ(timer.triggerTime(), 3.5);
    EXPECT_EQ(timer.baseTime(), 0.0);
}

TEST(TimerSensor, rejectsBadIntervalAndBaseTime) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    TimerSensor timer(queue);
    try {
        timer.setInterval(0.0);
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "TimerSensor::setInterval(): interval must be finite and > 0, "
                                   "got 0");
    }
    try {
        timer.setInterval(std::numeric_limits<double>::infinity());
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "TimerSensor::setInterval(): interval must be finite and > 0, "
                                   "got inf");
    }
    try {
        timer.setBaseTime(std::numeric_limits<double>::quiet_NaN());
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "TimerSensor::setBaseTime(): base time must be finite, got nan");
    }
    EXPECT_EQ(timer.interval(), TimerSensor::kDefaultInterval);
}

TEST(TimerSensor, equalTriggerTimesRunInScheduleOrder) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    std::vector<int> order;
    TimerSensor slow(queue, [&] { order.push_back(2); });
    TimerSensor first(queue, [&] { order.push_back(0); });
    TimerSensor second(queue, [&] { order.push_back(1); });
    slow.setInterval(2.0);
    first.setInterval(1.0);
    second.setInterval(1.0);
    slow.schedule();
    first.schedule();
    second.schedule();
    clock.setTime(2.0);
    queue.process();
    // Trigger times 1, 1 and 2: earliest first, ties in the order they were scheduled.
    EXPECT_EQ(order, (std::vector<int>{0, 1, 2}));
}

TEST(TimerSensor, callbackMayUnscheduleItself) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    int count = 0;
    TimerSensor timer(queue);
    timer.setCallback([&] {
        ++count;
        timer.unschedule();
    });
    timer.setInterval(1.0);
    timer.schedule();
    for (int second = 1; second <= 3; ++second) {
        clock.setTime(second);
        queue.process();
    }
    EXPECT_EQ(count, 1);
    EXPECT_FALSE(timer.isScheduled());
}

TEST(TimerSensor, callbackMayDestroyItsOwnTimer) {
    SimulatedClock clock;
    SensorQueue queue(clock);
    int count = 0;
    auto timer = std::make_unique<TimerSensor>(queue);
    timer->setCallback([&count, &timer] {
        timer.reset();
        ++count; // the captures are still alive: the queue holds the callback while it runs
    });
    timer->setInterval(1.0);
    timer->schedule();
    clock.setTime(5.0);
    queue.process();
    EXPECT_EQ(count, 1);
    EXPECT_EQ(timer, nullptr);
    EXPECT_FALSE(queue.nextTimerTime().has_value());
}
