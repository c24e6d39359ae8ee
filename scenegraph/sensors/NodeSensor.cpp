#include "scenegraph/sensors/NodeSensor.h"

#include "scenegraph/Node.h"

namespace texsplat::sg {

NodeSensor::NodeSensor(SensorQueue& queue, Callback callback)
    : DataSensor(queue, std::move(callback)) {}

void NodeSensor::attach(Node& node) { attachTo(node); }

Node* NodeSensor::attachedNode() const { return static_cast<Node*>(subject()); }

} // namespace texsplat::sg
