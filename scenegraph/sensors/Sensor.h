#pragma once

#include "scenegraph/sensors/detail/QueueLane.h"

#include <cstdint>
#include <functional>
#include <memory>

namespace texsplat::sg {

class SensorQueue;

/// @brief Base of the sensors: a callback that a SensorQueue runs when the sensor is due.
///
/// As in Open Inventor, a sensor is scheduled (by the application, by a field change, or by
/// itself for a periodic timer), waits in its queue, and runs its callback when the queue is
/// processed; it is then no longer scheduled unless it schedules itself again. The concrete
/// sensors say when they are due: TimerSensor (at times base + n * interval), OneShotSensor (at
/// the next processing), FieldSensor / NodeSensor (after a change), IdleSensor (when there is
/// nothing else to do). See docs/sensors.md for the ordering rules.
///
/// Lifetime: a sensor belongs to one queue, given at construction; neither owns the other.
/// Destroying a scheduled sensor unschedules it, even from inside a callback (its own included);
/// destroying the queue first leaves the sensor unscheduled and detached (`queue()` becomes
/// nullptr; `schedule()` then throws DataError). Sensors are neither copyable nor movable, since
/// the queue refers to them. A queue and its sensors belong to one thread.
class Sensor {
public:
    /// @brief What the sensor runs. It may schedule, unschedule or destroy any sensor, this one
    /// included, and change fields; it must not process the queue again.
    using Callback = std::function<void()>;

    Sensor(const Sensor&) = delete;
    Sensor& operator=(const Sensor&) = delete;

    /// @brief Unschedules the sensor and leaves its queue.
    virtual ~Sensor();

    /// @brief Puts the sensor in its queue; see the concrete class for when it becomes due.
    /// Scheduling a sensor that is already scheduled does nothing (changes coalesce). Throws
    /// DataError when the queue no longer exists.
    virtual void schedule() = 0;

    /// @brief Takes the sensor out of its queue; its callback will not run. No-op when not
    /// scheduled.
    void unschedule();

    /// @brief True while the sensor waits in its queue.
    bool isScheduled() const { return mIsScheduled; }

    /// @brief Replaces the callback (an empty one does nothing when triggered).
    void setCallback(Callback callback);

    /// @brief The queue the sensor belongs to, or nullptr once that queue is destroyed.
    SensorQueue* queue() const { return mQueue; }

protected:
    /// @brief A sensor of `queue` that waits in `lane` when scheduled.
    Sensor(SensorQueue& queue, detail::QueueLane lane, Callback callback);

    /// @brief Called by the queue when the sensor is due; it is already unscheduled. The default
    /// runs the callback; a periodic sensor schedules itself again first.
    virtual void trigger();

    /// @brief Called when the queue is destroyed before the sensor (the sensor is already
    /// unscheduled and `queue()` is nullptr): drop whatever could schedule it later.
    virtual void queueDestroyed() {}

    /// @brief Runs the callback. Safe when the callback destroys this sensor.
    void runCallback();

    /// @brief Puts the sensor in its lane at `key` (trigger time or priority); a scheduled
    /// sensor moves there and goes behind the sensors already at that key. Throws DataError
    /// when the queue no longer exists.
    void enqueue(double key);

private:
    friend class SensorQueue;

    SensorQueue* mQueue;
    detail::QueueLane mLane;
    // Shared so that a callback that destroys its own sensor keeps running on a live object.
    std::shared_ptr<const Callback> mCallback;
    bool mIsScheduled = false;
    // Position in the lane: (key, order) is unique; order counts schedules, first come first.
    double mKey = 0.0;
    std::uint64_t mOrder = 0;
    // The queue pass in which the sensor last ran: scheduled again in that pass, it waits for
    // the next one.
    std::uint64_t mLastPass = 0;
};

} // namespace texsplat::sg
