#pragma once

#include "scenegraph/sensors/DelaySensor.h"

namespace texsplat::sg {

/// @brief Runs its callback when the queue is idle: at a processing where the delay queue is
/// empty (Inventor's SoIdleSensor).
///
/// Made for progressive refinement: the callback does one bounded step and schedules the
/// sensor again while work is left. The rescheduled sensor runs at the next processing, never
/// twice in one, and any delay work a step causes (a redraw sensor) runs before the next step.
/// A viewer processes the idle queue only when no events are pending.
class IdleSensor final : public DelaySensor {
public:
    /// @brief An unscheduled sensor of `queue` running `callback`.
    explicit IdleSensor(SensorQueue& queue, Callback callback = {});
};

} // namespace texsplat::sg
