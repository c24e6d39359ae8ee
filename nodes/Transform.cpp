#include "nodes/Transform.h"

#include "nodes/detail/Finite.h"
#include "nodes/detail/NodeContext.h"
#include "scenegraph/Error.h"

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

void Transform::checkFields() const {
    detail::requireFinite(*this, translation);
    detail::requireFinite(*this, rotation);
    detail::requireFinite(*this, scaleFactor);
    detail::requireFinite(*this, scaleOrientation);
    detail::requireFinite(*this, center);
    const glm::vec3 scale = scaleFactor.value();
    if (scale.x == 0.0f || scale.y == 0.0f || scale.z == 0.0f) {
        throw DataError(detail::nodeContext(*this) +
                        ": scaleFactor must be non-zero on every axis (a zero scale is singular: "
                        "it flattens what follows, which splats and rays cannot invert), got " +
                        scaleFactor.valueText());
    }
}

void Transform::doAction(sg::Action& action) {
    checkFields();
    glm::mat4& model = action.state().modify<sg::ModelMatrixElement>().matrix;
    const glm::mat4 product = model * matrix();
    if (!detail::isFinite(product)) {
        throw DataError(detail::nodeContext(*this) +
                        ": the transformation overflows: with the transformations above it, "
                        "the model matrix is not finite (translation " +
                        translation.valueText() + ", scaleFactor " + scaleFactor.valueText() +
                        ")");
    }
    model = product;
}

} // namespace texsplat::nodes
