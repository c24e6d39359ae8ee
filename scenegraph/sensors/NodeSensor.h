#pragma once

#include "scenegraph/sensors/DataSensor.h"

namespace texsplat::sg {

/// @brief Runs its callback after a node or anything below it changed (Inventor's
/// SoNodeSensor): a field of the node or of a descendant, children added or removed.
///
/// A viewer attaches one to the root to redraw after any change; many changes before the next
/// processing make one redraw. When the node dies the sensor detaches (see DataSensor).
class NodeSensor final : public DataSensor {
public:
    /// @brief An unattached sensor of `queue` running `callback`.
    explicit NodeSensor(SensorQueue& queue, Callback callback = {});

    /// @brief Watches `node` and its descendants (detaching from the previous node). Throws
    /// DataError when the queue no longer exists.
    void attach(Node& node);

    /// @brief The watched node, or nullptr.
    Node* attachedNode() const;
};

} // namespace texsplat::sg
