#pragma once

#include "scenegraph/sensors/Clock.h"

namespace texsplat::sg {

/// @brief A clock that moves only when told: batch rendering and tests.
///
/// Two runs that advance the clock by the same steps see the same times, so timers, engines and
/// animations are reproducible frame for frame. For frame `n` of a movie at `fps` frames per
/// second prefer `setTime(n / fps)`: it gives exactly the time a TimerSensor computes for its
/// n-th trigger (`base + n * interval`). `advance()` sums its steps with compensated (Kahan)
/// summation, so 10000 steps of 1/30 s end within one rounding of 10000/30 instead of
/// accumulating an error of 10000 roundings.
class SimulatedClock final : public Clock {
public:
    /// @brief A clock that reads `startTime` (finite; throws DataError otherwise).
    explicit SimulatedClock(double startTime = 0.0);

    /// @copydoc Clock::now
    double now() const override { return mTime; }

    /// @brief Moves the clock forward by `seconds`. Throws DataError unless `seconds` is
    /// finite and >= 0.
    void advance(double seconds);

    /// @brief Sets the time. Throws DataError unless `time` is finite and not before now()
    /// (the queue's timers and engines assume time never runs backwards).
    void setTime(double time);

private:
    double mTime;
    // The low-order part lost by the last additions (Kahan summation).
    double mCompensation = 0.0;
};

} // namespace texsplat::sg
