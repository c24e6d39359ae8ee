#include "scenegraph/actions/BoundingBoxAction.h"

#include "scenegraph/actions/ModelMatrixElement.h"

namespace texsplat::sg {

BoundingBoxAction::BoundingBoxAction() : Action(methods()) {}

MethodTable& BoundingBoxAction::methods() {
    static MethodTable table = [] {
        MethodTable initial;
        initial.add<&Node::getBoundingBox>();
        return initial;
    }();
    return table;
}

void BoundingBoxAction::extendBy(const Box3& localBox) {
    mBox.extendBy(localBox.transformed(state().get<ModelMatrixElement>().matrix));
}

void BoundingBoxAction::extendBy(const glm::vec3& localPoint) {
    const glm::mat4& matrix = state().get<ModelMatrixElement>().matrix;
    mBox.extendBy(glm::vec3(matrix * glm::vec4(localPoint, 1.0f)));
}

void BoundingBoxAction::beginTraversal(Node& /*root*/) { mBox = Box3(); }

} // namespace texsplat::sg
