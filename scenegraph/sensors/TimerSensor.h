#pragma once

#include "scenegraph/sensors/Sensor.h"

#include <cstdint>

namespace texsplat::sg {

/// @brief Runs its callback periodically, at times base + n * interval (Inventor's
/// SoTimerSensor).
///
/// Trigger times do not drift: the n-th trigger is computed as `base + n * interval`, never by
/// adding the interval to the previous trigger, so however late the queue runs, the schedule
/// stays on the grid (10000 intervals of 0.1 s from base 0 end at exactly 10000 * 0.1).
///
/// Late queues coalesce: when processing comes after several trigger times have passed, the
/// callback runs once (`lastTriggerTime()` is the earliest missed one, `missedTriggerCount()`
/// says how many more were skipped) and the next trigger is the first grid time after the
/// queue's time. An animation that must see every step reads the count (or, better, computes
/// its state from the queue's time, as ElapsedTime does).
///
/// The base time is set with `setBaseTime()`; otherwise `schedule()` takes the queue's time as
/// the base, and the first trigger comes one interval later. With an explicit base, the first
/// trigger is the first grid time at or after the queue's time. A periodic sensor keeps itself
/// scheduled; `unschedule()` stops it.
class TimerSensor final : public Sensor {
public:
    /// @brief Inventor's default interval: 1/30 s.
    static constexpr double kDefaultInterval = 1.0 / 30.0;

    /// @brief An unscheduled timer of `queue` running `callback` every kDefaultInterval.
    explicit TimerSensor(SensorQueue& queue, Callback callback = {});

    /// @brief Puts the timer on its grid (see the class). No-op when already scheduled.
    void schedule() override;

    /// @brief Sets the period in seconds; a scheduled timer moves to the first time of the new
    /// grid at or after the queue's time. Throws DataError unless `seconds` is finite and > 0.
    void setInterval(double seconds);

    /// @brief The period in seconds.
    double interval() const { return mInterval; }

    /// @brief Sets the time of trigger 0 and keeps it for later `schedule()` calls; a scheduled
    /// timer moves to the new grid. Throws DataError unless `time` is finite.
    void setBaseTime(double time);

    /// @brief The time of trigger 0 (the schedule time when no base was set).
    double baseTime() const { return mBaseTime; }

    /// @brief The time of the pending trigger (meaningful while scheduled).
    double triggerTime() const { return timeOf(mIndex); }

    /// @brief The grid time of the trigger the callback runs for (during the callback), or of
    /// the last one run.
    double lastTriggerTime() const { return mLastTriggerTime; }

    /// @brief How many grid times the last trigger skipped because the queue ran late.
    std::int64_t missedTriggerCount() const { return mMissedTriggerCount; }

protected:
    /// @copydoc Sensor::trigger
    void trigger() override;

private:
    double timeOf(std::int64_t index) const {
        return mBaseTime + static_cast<double>(index) * mInterval;
    }
    std::int64_t firstIndexAfter(double time, bool isInclusive) const;
    void moveToGrid();

    double mInterval = kDefaultInterval;
    double mBaseTime = 0.0;
    bool mHasBaseTime = false;
    std::int64_t mIndex = 0;
    double mLastTriggerTime = 0.0;
    std::int64_t mMissedTriggerCount = 0;
};

} // namespace texsplat::sg
