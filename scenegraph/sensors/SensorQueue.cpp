#include "scenegraph/sensors/SensorQueue.h"

#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"
#include "scenegraph/sensors/Clock.h"
#include "scenegraph/sensors/Sensor.h"
#include "scenegraph/sensors/detail/FormatTime.h"

#include <cmath>
#include <limits>

namespace texsplat::sg {

using detail::QueueLane;

/// Marks one processing pass: reads the clock once, numbers the pass and rejects reentry; at
/// the end (also when a callback throws) clears the processing flag and returns the sensors
/// that were scheduled again after running to their lanes.
class SensorQueue::Pass {
public:
    Pass(SensorQueue& queue, const char* function) : mQueue(queue) {
        if (queue.mIsProcessing) {
            throw DataError(std::string("SensorQueue::") + function +
                            "(): called from a sensor callback; processing is not reentrant");
        }
        queue.mPassTime = queue.readClock();
        queue.mIsProcessing = true;
        ++queue.mPass;
    }
    Pass(const Pass&) = delete;
    Pass& operator=(const Pass&) = delete;
    ~Pass() {
        mQueue.mIsProcessing = false;
        for (int i = 0; i < detail::kQueueLaneCount; ++i) {
            mQueue.mLanes[i].merge(mQueue.mWaiting[i]);
        }
    }

private:
    SensorQueue& mQueue;
};

SensorQueue::SensorQueue(const Clock& clock) : mClock(clock) {
    mTimeField.setValue(static_cast<float>(readClock()));
}

SensorQueue::~SensorQueue() {
    TEXSPLAT_ASSERT(!mIsProcessing, "SensorQueue::~SensorQueue(): destroyed by a sensor callback");
    // Detach first: queueDestroyed() may unregister observers, never touch this queue.
    for (Sensor* sensor : mSensors) {
        sensor->mIsScheduled = false;
        sensor->mQueue = nullptr;
    }
    for (Sensor* sensor : mSensors) {
        sensor->queueDestroyed();
    }
}

double SensorQueue::time() const { return mIsProcessing ? mPassTime : readClock(); }

double SensorQueue::readClock() const {
    // Checked once here so that trigger-time arithmetic never sees inf or nan.
    const double now = mClock.now();
    if (!std::isfinite(now)) {
        throw DataError("SensorQueue: the clock returned a non-finite time " +
                        detail::formatTime(now));
    }
    return now;
}

void SensorQueue::process() {
    const Pass pass(*this, "process");
    runTimers();
    runDelayed();
    runIdle();
}

void SensorQueue::processTimerQueue() {
    const Pass pass(*this, "processTimerQueue");
    runTimers();
}

void SensorQueue::processDelayQueue() {
    const Pass pass(*this, "processDelayQueue");
    runDelayed();
}

void SensorQueue::processIdleQueue() {
    const Pass pass(*this, "processIdleQueue");
    runIdle();
}

std::optional<double> SensorQueue::nextTimerTime() const {
    std::optional<double> earliest;
    for (const Lane* timers : {&lane(QueueLane::Timer), &waiting(QueueLane::Timer)}) {
        if (!timers->empty() && (!earliest || timers->begin()->key < *earliest)) {
            earliest = timers->begin()->key;
        }
    }
    return earliest;
}

void SensorQueue::attach(Sensor& sensor) { mSensors.insert(&sensor); }

void SensorQueue::detach(Sensor& sensor) {
    remove(sensor);
    mSensors.erase(&sensor);
}

void SensorQueue::insert(Sensor& sensor, double key) {
    remove(sensor);
    sensor.mKey = key;
    sensor.mOrder = ++mNextOrder;
    sensor.mIsScheduled = true;
    const bool hasRunInThisPass = mIsProcessing && sensor.mLastPass == mPass;
    Lane& target = hasRunInThisPass ? waiting(sensor.mLane) : lane(sensor.mLane);
    target.insert(Entry{key, sensor.mOrder, &sensor});
}

void SensorQueue::remove(Sensor& sensor) {
    if (!sensor.mIsScheduled) {
        return;
    }
    const Entry entry{sensor.mKey, sensor.mOrder, &sensor};
    if (lane(sensor.mLane).erase(entry) == 0) {
        waiting(sensor.mLane).erase(entry);
    }
    sensor.mIsScheduled = false;
}

void SensorQueue::runTimers() {
    const auto now = static_cast<float>(mPassTime);
    // Set only on change: every set notifies the engines and the scene connected to it.
    if (mTimeField.value() != now) {
        mTimeField.setValue(now);
    }
    while (Sensor* sensor = nextDue(QueueLane::Timer, mPassTime)) {
        run(*sensor);
    }
}

void SensorQueue::runDelayed() {
    while (Sensor* sensor = nextDue(QueueLane::Delay, std::numeric_limits<double>::infinity())) {
        run(*sensor);
    }
}

void SensorQueue::runIdle() {
    // Re-checked before each idle sensor: delay work an idle callback caused runs first.
    while (!hasDelaySensors()) {
        Sensor* sensor = nextDue(QueueLane::Idle, std::numeric_limits<double>::infinity());
        if (sensor == nullptr) {
            return;
        }
        run(*sensor);
    }
}

Sensor* SensorQueue::nextDue(QueueLane which, double maxKey) const {
    const Lane& due = lane(which);
    return !due.empty() && due.begin()->key <= maxKey ? due.begin()->sensor : nullptr;
}

void SensorQueue::run(Sensor& sensor) {
    remove(sensor);
    sensor.mLastPass = mPass;
    // The sensor may be destroyed by its own callback: nothing may touch it after this call.
    sensor.trigger();
}

} // namespace texsplat::sg
