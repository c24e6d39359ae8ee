#pragma once

#include <chrono>

namespace texsplat::sg {

/// @brief The clock that work is timed with (render phases, benchmarks, progress): steady, so it
/// never jumps when the system time is set.
using TimingClock = std::chrono::steady_clock;

/// @brief Seconds from @p start to now.
inline double secondsSince(TimingClock::time_point start) {
    return std::chrono::duration<double>(TimingClock::now() - start).count();
}

} // namespace texsplat::sg
