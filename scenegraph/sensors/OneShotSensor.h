#pragma once

#include "scenegraph/sensors/DelaySensor.h"

namespace texsplat::sg {

/// @brief Runs its callback once, at the queue's next processing after `schedule()`
/// (Inventor's SoOneShotSensor): defer work out of a notification or an event handler.
///
/// Scheduling it several times before that processing runs it once.
class OneShotSensor final : public DelaySensor {
public:
    /// @brief An unscheduled sensor of `queue` running `callback`.
    explicit OneShotSensor(SensorQueue& queue, Callback callback = {});
};

} // namespace texsplat::sg
