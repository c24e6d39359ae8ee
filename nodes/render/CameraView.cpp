#include "nodes/render/CameraView.h"

#include "nodes/Camera.h"
#include "nodes/detail/NodeContext.h"
#include "nodes/elements/CameraElement.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/State.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_inverse.hpp>

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

} // namespace texsplat::render
