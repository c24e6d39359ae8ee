#include "scenegraph/sensors/Sensor.h"

#include "scenegraph/Error.h"
#include "scenegraph/sensors/SensorQueue.h"

namespace texsplat::sg {

Sensor::Sensor(SensorQueue& queue, detail::QueueLane lane, Callback callback)
    : mQueue(&queue), mLane(lane),
      mCallback(std::make_shared<const Callback>(std::move(callback))) {
    queue.attach(*this);
}

Sensor::~Sensor() {
    if (mQueue != nullptr) {
        mQueue->detach(*this);
    }
}

void Sensor::unschedule() {
    if (mQueue != nullptr) {
        mQueue->remove(*this);
    }
}

void Sensor::setCallback(Callback callback) {
    mCallback = std::make_shared<const Callback>(std::move(callback));
}

void Sensor::trigger() { runCallback(); }

void Sensor::runCallback() {
    const std::shared_ptr<const Callback> callback = mCallback;
    if (*callback) {
        (*callback)();
    }
}

void Sensor::enqueue(double key) {
    if (mQueue == nullptr) {
        throw DataError("Sensor::schedule(): the sensor's SensorQueue no longer exists");
    }
    mQueue->insert(*this, key);
}

} // namespace texsplat::sg
