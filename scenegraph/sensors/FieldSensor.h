#pragma once

#include "scenegraph/sensors/DataSensor.h"

namespace texsplat::sg {

/// @brief Runs its callback after a field changed (Inventor's SoFieldSensor).
///
/// @code
/// sg::FieldSensor sensor(queue, [&] { rebuild(splat->size.value()); });
/// sensor.attach(splat->size);
/// splat->size = 2.0f;     // schedules the sensor
/// splat->size = 3.0f;     // already scheduled: coalesced
/// queue.process();        // rebuild(3) runs once
/// @endcode
/// Any set or touch of the field counts as a change, also through a connection. When the node
/// owning the field dies the sensor detaches (see DataSensor).
class FieldSensor final : public DataSensor {
public:
    /// @brief An unattached sensor of `queue` running `callback`.
    explicit FieldSensor(SensorQueue& queue, Callback callback = {});

    /// @brief Watches `field` (detaching from the previous one). Throws DataError when the
    /// queue no longer exists.
    void attach(Field& field);

    /// @brief The watched field, or nullptr.
    Field* attachedField() const;
};

} // namespace texsplat::sg
