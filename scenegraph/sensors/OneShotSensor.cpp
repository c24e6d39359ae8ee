#include "scenegraph/sensors/OneShotSensor.h"

namespace texsplat::sg {

OneShotSensor::OneShotSensor(SensorQueue& queue, Callback callback)
    : DelaySensor(queue, detail::QueueLane::Delay, std::move(callback)) {}

} // namespace texsplat::sg
