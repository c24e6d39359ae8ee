#include "scenegraph/sensors/FieldSensor.h"

#include "scenegraph/fields/Field.h"

namespace texsplat::sg {

FieldSensor::FieldSensor(SensorQueue& queue, Callback callback)
    : DataSensor(queue, std::move(callback)) {}

void FieldSensor::attach(Field& field) { attachTo(field); }

Field* FieldSensor::attachedField() const { return static_cast<Field*>(subject()); }

} // namespace texsplat::sg
