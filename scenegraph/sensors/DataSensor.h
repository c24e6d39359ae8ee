#pragma once

#include "scenegraph/Observer.h"
#include "scenegraph/sensors/DelaySensor.h"

namespace texsplat::sg {

/// @brief Base of the sensors that schedule themselves when something they watch changes
/// (Inventor's SoDataSensor): FieldSensor and NodeSensor.
///
/// A change schedules the sensor in the delay queue; the callback runs at the next processing,
/// once however many changes came before it. When the watched object is destroyed the sensor
/// detaches itself, is unscheduled (a pending callback does not run) and runs its detach
/// callback, if any. Detaching, or destroying the sensor, stops the watching.
class DataSensor : public DelaySensor, private Observer {
public:
    /// @brief Stops watching.
    ~DataSensor() override;

    /// @brief Stops watching and unschedules. No-op when not attached.
    void detach();

    /// @brief True while watching something.
    bool isAttached() const { return mSubject != nullptr; }

    /// @brief Runs when the watched object is destroyed, from inside its destruction: it must
    /// not use that object (Inventor's delete callback).
    void setDetachCallback(Callback callback) { mDetachCallback = std::move(callback); }

protected:
    /// @brief An unattached sensor of `queue` running `callback`.
    DataSensor(SensorQueue& queue, Callback callback);

    /// @brief Watches `subject` from now on (after detaching from the previous one). Throws
    /// DataError when the queue no longer exists.
    void attachTo(Notifier& subject);

    /// @brief The watched object, or nullptr.
    Notifier* subject() const { return mSubject; }

private:
    void changed(Notifier& subject, const Field* source) override;
    void subjectDestroyed(Notifier& subject) override;
    void queueDestroyed() override;

    Notifier* mSubject = nullptr;
    Callback mDetachCallback;
};

} // namespace texsplat::sg
