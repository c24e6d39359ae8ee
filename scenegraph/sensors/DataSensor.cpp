#include "scenegraph/sensors/DataSensor.h"

#include "scenegraph/Error.h"
#include "scenegraph/Notifier.h"

namespace texsplat::sg {

DataSensor::DataSensor(SensorQueue& queue, Callback callback)
    : DelaySensor(queue, detail::QueueLane::Delay, std::move(callback)) {}

DataSensor::~DataSensor() { detach(); }

void DataSensor::detach() {
    unschedule();
    if (mSubject != nullptr) {
        mSubject->removeObserver(*this);
        mSubject = nullptr;
    }
}

void DataSensor::attachTo(Notifier& subject) {
    if (queue() == nullptr) {
        throw DataError("DataSensor::attach(): the sensor's SensorQueue no longer exists");
    }
    detach();
    subject.addObserver(*this);
    mSubject = &subject;
}

void DataSensor::changed(Notifier& /*subject*/, const Field* /*source*/) { schedule(); }

void DataSensor::subjectDestroyed(Notifier& /*subject*/) {
    // The notifier has already dropped this observer; only forget it.
    mSubject = nullptr;
    unschedule();
    if (mDetachCallback) {
        // A copy: the callback may destroy this sensor.
        const Callback callback = mDetachCallback;
        callback();
    }
}

void DataSensor::queueDestroyed() {
    // Without a queue a change could not schedule the sensor; stop watching.
    detach();
}

} // namespace texsplat::sg
