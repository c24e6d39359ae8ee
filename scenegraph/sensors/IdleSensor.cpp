#include "scenegraph/sensors/IdleSensor.h"

namespace texsplat::sg {

IdleSensor::IdleSensor(SensorQueue& queue, Callback callback)
    : DelaySensor(queue, detail::QueueLane::Idle, std::move(callback)) {}

} // namespace texsplat::sg
