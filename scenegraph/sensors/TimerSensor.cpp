#include "scenegraph/sensors/TimerSensor.h"

#include "scenegraph/Error.h"
#include "scenegraph/sensors/SensorQueue.h"
#include "scenegraph/sensors/detail/FormatTime.h"

#include <algorithm>
#include <cmath>

namespace texsplat::sg {

namespace {

// Beyond 2^53 a double no longer holds every integer: the grid index saturates there.
constexpr double kMaxIndex = 9007199254740992.0;

} // namespace

TimerSensor::TimerSensor(SensorQueue& queue, Callback callback)
    : Sensor(queue, detail::QueueLane::Timer, std::move(callback)) {}

void TimerSensor::schedule() {
    if (isScheduled()) {
        return;
    }
    if (queue() == nullptr) {
        throw DataError("TimerSensor::schedule(): the sensor's SensorQueue no longer exists");
    }
    if (mHasBaseTime) {
        mIndex = firstIndexAfter(queue()->time(), true);
    } else {
        mBaseTime = queue()->time();
        mIndex = 1;
    }
    enqueue(timeOf(mIndex));
}

void TimerSensor::setInterval(double seconds) {
    if (!std::isfinite(seconds) || seconds <= 0.0) {
        throw DataError("TimerSensor::setInterval(): interval must be finite and > 0, got " +
                        detail::formatTime(seconds));
    }
    mInterval = seconds;
    moveToGrid();
}

void TimerSensor::setBaseTime(double time) {
    if (!std::isfinite(time)) {
        throw DataError("TimerSensor::setBaseTime(): base time must be finite, got " +
                        detail::formatTime(time));
    }
    mBaseTime = time;
    mHasBaseTime = true;
    moveToGrid();
}

void TimerSensor::trigger() {
    // Reschedule before the callback, so that the callback may unschedule or destroy the timer.
    mLastTriggerTime = timeOf(mIndex);
    const std::int64_t next = firstIndexAfter(queue()->time(), false);
    mMissedTriggerCount = std::max<std::int64_t>(0, next - mIndex - 1);
    mIndex = next;
    enqueue(timeOf(mIndex));
    runCallback();
}

std::int64_t TimerSensor::firstIndexAfter(double time, bool isInclusive) const {
    const double estimate = std::clamp(std::floor((time - mBaseTime) / mInterval), 0.0, kMaxIndex);
    auto index = static_cast<std::int64_t>(estimate);
    // The division rounds; step to the exact answer by comparing the grid times themselves.
    const auto isBefore = [&](std::int64_t i) {
        return isInclusive ? timeOf(i) < time : timeOf(i) <= time;
    };
    while (index > 0 && !isBefore(index - 1)) {
        --index;
    }
    while (isBefore(index)) {
        ++index;
    }
    return index;
}

void TimerSensor::moveToGrid() {
    if (isScheduled()) {
        mIndex = firstIndexAfter(queue()->time(), true);
        enqueue(timeOf(mIndex));
    }
}

} // namespace texsplat::sg
