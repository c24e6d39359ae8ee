#pragma once

namespace texsplat::sg {

/// @brief The time source of a SensorQueue: seconds as a double, never going backwards.
///
/// The scene graph has no hidden global clock (Inventor's `realTime` global field): every
/// SensorQueue is built on an explicit clock, and a scene's time is that queue's time. The viewer
/// uses a RealTimeClock; batch rendering and tests use a SimulatedClock, so an animation is the
/// same frame for frame on every run.
class Clock {
public:
    virtual ~Clock() = default;

    /// @brief The current time in seconds. Successive calls never decrease.
    virtual double now() const = 0;

protected:
    Clock() = default;
    Clock(const Clock&) = default;
    Clock& operator=(const Clock&) = default;
};

} // namespace texsplat::sg
