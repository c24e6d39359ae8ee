#include "nodes/Transform.h"

#include "scenegraph/Rotation.h"
#include "scenegraph/actions/Action.h"
#include "scenegraph/actions/ModelMatrixElement.h"

#include <glm/gtc/matrix_transform.hpp>

namespace texsplat::nodes {

Transform::Transform() {
    addField(translation, "translation", glm::vec3(0.0f),
             "Offset of the children's space, applied after scale and rotation");
    addField(rotation, "rotation", sg::Rotation(),
             "Rotation about center (axis x y z, angle in radians)");
    addField(scaleFactor, "scaleFactor", glm::vec3(1.0f),
             "Scale along the axes of scaleOrientation, about center");
    addField(scaleOrientation, "scaleOrientation", sg::Rotation(),
             "Rotation of the axes that scaleFactor scales along");
    addField(center, "center", glm::vec3(0.0f),
             "Fixed point of rotation and scale, in the children's space");
}

glm::mat4 Transform::matrix() const {
    const glm::mat4 scaleAxes = scaleOrientation.value().matrix();
    glm::mat4 result = glm::translate(glm::mat4(1.0f), translation.value() + center.value());
    result *= rotation.value().matrix() * scaleAxes;
    result = glm::scale(result, scaleFactor.value());
    result *= glm::transpose(scaleAxes); // the inverse of a rotation
    return glm::translate(result, -center.value());
}

void Transform::doAction(sg::Action& action) {
    glm::mat4& model = action.state().modify<sg::ModelMatrixElement>().matrix;
    model *= matrix();
}

} // namespace texsplat::nodes
