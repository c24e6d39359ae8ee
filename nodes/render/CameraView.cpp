#include "nodes/render/CameraView.h"

#include "nodes/Camera.h"
#include "nodes/detail/NodeContext.h"
#include "nodes/elements/CameraElement.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/State.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace texsplat::render {

CameraView CameraView::current(sg::State& state, const sg::Node& node, float aspectRatio) {
    const nodes::CameraElement& element = state.get<nodes::CameraElement>();
    if (!element.camera) {
        throw DataError(nodes::detail::nodeContext(node) + ": no camera before this node");
    }
    CameraView result;
    result.view = element.camera->viewMatrix() * glm::inverse(element.modelMatrix);
    result.projection = element.camera->projectionMatrix(aspectRatio);
    result.viewDirection =
        glm::normalize(glm::vec3(element.modelMatrix * glm::vec4(element.camera->viewDirection(), 0.0f)));
    return result;
}

sg::Rotation rotationLookingAlong(const glm::vec3& direction) {
    const glm::vec3 from(0.0f, 0.0f, -1.0f);
    const glm::vec3 to = glm::normalize(direction);
    const glm::vec3 axis = glm::cross(from, to);
    const float cosine = glm::dot(from, to);
    if (glm::length(axis) < 1e-6f) {
        return cosine > 0.0f ? sg::Rotation() : sg::Rotation({0.0f, 1.0f, 0.0f}, glm::pi<float>());
    }
    return sg::Rotation(glm::normalize(axis), std::acos(std::clamp(cosine, -1.0f, 1.0f)));
}

sg::Rotation rotationLookingAlong(const glm::vec3& direction, const glm::vec3& up) {
    const auto usable = [](const glm::vec3& v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) &&
               v != glm::vec3(0.0f);
    };
    if (!usable(direction) || !usable(up)) {
        throw DataError("the viewing direction and the up direction must be finite and not zero");
    }
    // The camera's axes: +z points back, towards the eye; +y up; +x right.
    const glm::dvec3 back = -glm::normalize(glm::dvec3(direction));
    const glm::dvec3 right = glm::cross(glm::dvec3(up), back);
    if (glm::length(right) < 1e-6 * glm::length(glm::dvec3(up))) {
        throw DataError("the up direction is parallel to the viewing direction: no up can be "
                        "seen; give one across the view");
    }
    const glm::dvec3 x = glm::normalize(right);
    const glm::dvec3 y = glm::cross(back, x);
    const glm::quat turn = glm::quat_cast(glm::mat3(glm::dmat3(x, y, back)));
    const float angle = glm::angle(turn);
    const glm::vec3 axis = glm::axis(turn);
    return angle == 0.0f ? sg::Rotation() : sg::Rotation(glm::normalize(axis), angle);
}

} // namespace texsplat::render
