#pragma once

#include "scenegraph/Box3.h"
#include "scenegraph/actions/Action.h"

#include <glm/glm.hpp>

namespace texsplat::sg {

/// @brief Computes the box around the geometry under a node, in that node's space.
///
/// Shape nodes override `Node::getBoundingBox()` and call `extendBy()` with their local box;
/// transform nodes change ModelMatrixElement in `doAction()`, which this action honours.
class BoundingBoxAction : public Action {
public:
    BoundingBoxAction();

    /// @brief The table of this action: `Node` → `Node::getBoundingBox()`.
    static MethodTable& methods();

    /// @brief The box of the last apply() (empty if nothing has geometry).
    const Box3& boundingBox() const { return mBox; }

    /// @brief Adds a box given in the current node's local space.
    void extendBy(const Box3& localBox);

    /// @brief Adds a point given in the current node's local space.
    void extendBy(const glm::vec3& localPoint);

protected:
    /// @brief Empties the box.
    void beginTraversal(Node& root) override;

private:
    Box3 mBox;
};

} // namespace texsplat::sg
