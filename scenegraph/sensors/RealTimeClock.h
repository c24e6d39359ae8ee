#pragma once

#include "scenegraph/sensors/Clock.h"

#include <chrono>

namespace texsplat::sg {

/// @brief Wall-clock time for interactive use: seconds since the clock was made.
///
/// Based on `std::chrono::steady_clock`, so it never jumps when the system time is set. Counting
/// from the clock's creation (rather than from the epoch) keeps the values small, which matters
/// because the scene graph's time field (`SensorQueue::timeField()`) is an SFFloat: a float has
/// about 1 ms resolution up to 2 hours.
class RealTimeClock final : public Clock {
public:
    /// @brief A clock that reads 0 now.
    RealTimeClock();

    /// @copydoc Clock::now
    double now() const override;

private:
    std::chrono::steady_clock::time_point mStart;
};

} // namespace texsplat::sg
