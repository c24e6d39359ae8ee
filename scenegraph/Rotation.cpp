#include "scenegraph/Rotation.h"

#include <glm/gtc/matrix_transform.hpp>

namespace texsplat::sg {

glm::quat Rotation::quaternion() const {
    const float length = glm::length(mAxis);
    if (length == 0.0f) {
        return glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
    }
    return glm::angleAxis(mAngle, mAxis / length);
}

glm::mat4 Rotation::matrix() const { return glm::mat4_cast(quaternion()); }

} // namespace texsplat::sg
