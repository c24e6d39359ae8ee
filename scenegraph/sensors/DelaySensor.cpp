#include "scenegraph/sensors/DelaySensor.h"

namespace texsplat::sg {

DelaySensor::DelaySensor(SensorQueue& queue, detail::QueueLane lane, Callback callback)
    : Sensor(queue, lane, std::move(callback)) {}

void DelaySensor::schedule() {
    if (!isScheduled()) {
        enqueue(static_cast<double>(mPriority));
    }
}

void DelaySensor::setPriority(std::uint32_t priority) {
    mPriority = priority;
    if (isScheduled()) {
        enqueue(static_cast<double>(mPriority));
    }
}

} // namespace texsplat::sg
