#pragma once

#include <cstdint>

namespace texsplat::sg::detail {

/// @brief The three queues of a SensorQueue, in the order one `process()` runs them.
enum class QueueLane : std::uint8_t {
    Timer, ///< ordered by trigger time (TimerSensor)
    Delay, ///< ordered by priority, then first scheduled first (OneShot, Field, Node sensors)
    Idle,  ///< as Delay, run only when the delay queue is empty (IdleSensor)
};

/// @brief Number of QueueLane values.
inline constexpr int kQueueLaneCount = 3;

} // namespace texsplat::sg::detail
