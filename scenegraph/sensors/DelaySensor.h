#pragma once

#include "scenegraph/sensors/Sensor.h"

#include <cstdint>

namespace texsplat::sg {

/// @brief Base of the sensors that wait in the delay (or idle) queue, ordered by priority
/// (Inventor's SoDelayQueueSensor).
///
/// Lower priority numbers run first; equal priorities run in the order they were scheduled.
/// Scheduling a sensor that is already scheduled keeps its place, so any number of triggers
/// before the next processing coalesce into one callback.
///
/// Unlike Inventor, priority 0 is not "immediate": it is just the first to run. A callback that
/// must run inside the change notification is an Observer, not a sensor; sensors always run
/// from the queue, where they may safely change the graph.
class DelaySensor : public Sensor {
public:
    /// @brief Inventor's default priority.
    static constexpr std::uint32_t kDefaultPriority = 100;

    /// @brief Puts the sensor in its queue, behind the scheduled sensors of the same priority;
    /// it runs at the queue's next processing. No-op when already scheduled.
    void schedule() override;

    /// @brief Sets the priority; a scheduled sensor moves to its new place (behind the others of
    /// that priority).
    void setPriority(std::uint32_t priority);

    /// @brief The priority (lower runs first).
    std::uint32_t priority() const { return mPriority; }

protected:
    /// @brief A sensor that waits in `lane` (Delay or Idle).
    DelaySensor(SensorQueue& queue, detail::QueueLane lane, Callback callback);

private:
    std::uint32_t mPriority = kDefaultPriority;
};

} // namespace texsplat::sg
