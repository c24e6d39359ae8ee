#include "nodes/Camera.h"

#include "nodes/detail/Finite.h"
#include "nodes/detail/NodeContext.h"
#include "nodes/elements/CameraElement.h"
#include "scenegraph/Error.h"
#include "scenegraph/Rotation.h"
#include "scenegraph/actions/Action.h"
#include "scenegraph/actions/ModelMatrixElement.h"
#include "scenegraph/fields/ValueFormat.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace texsplat::nodes {

Camera::Camera() {
    addField(viewportMapping, "viewportMapping", ViewportMapping::AdjustCamera,
             kViewportMappingNames,
             "Inventor's fit of the view volume to the viewport; read and written back, not "
             "used (texsplat keeps the vertical opening and fits the width)");
    addField(position, "position", glm::vec3(0.0f, 0.0f, 1.0f),
             "Viewpoint, in the camera's local space");
    addField(orientation, "orientation", sg::Rotation(),
             "Rotation of the default view along -z with +y up (axis x y z, angle in radians)");
    addField(nearDistance, "nearDistance", 1.0f,
             "Distance from the viewpoint to the near clipping plane, world units");
    addField(farDistance, "farDistance", 10.0f,
             "Distance from the viewpoint to the far clipping plane, world units, > nearDistance");
    addField(aspectRatio, "aspectRatio", 1.0f,
             "Width over height the camera was set up for; read and written back, not used (the "
             "image's aspect is)");
    addField(focalDistance, "focalDistance", 5.0f,
             "Distance from the viewpoint to the point of interest, which the viewer orbits");
}

glm::mat4 Camera::viewMatrix() const {
    // Inverse of translate(position) * rotate(orientation): the transposed rotation after the
    // negated translation.
    const glm::mat4 inverseRotation = glm::transpose(orientation.value().matrix());
    return glm::translate(inverseRotation, -position.value());
}

glm::vec3 Camera::viewDirection() const {
    return glm::normalize(orientation.value().quaternion() * glm::vec3(0.0f, 0.0f, -1.0f));
}

glm::mat4 Camera::projectionMatrix(float aspect) const {
    return projectionMatrix(aspect, {nearDistance.value(), farDistance.value()});
}

namespace {

void checkAspect(const Camera& camera, float aspect) {
    if (!std::isfinite(aspect) || aspect <= 0.0f) {
        throw DataError(detail::nodeContext(camera) +
                        ": the viewport aspect ratio must be finite and positive, got " +
                        sg::formatFloat(aspect));
    }
}

void checkBox(const Camera& camera, const sg::Box3& box, const char* what) {
    if (box.isEmpty()) {
        throw DataError(detail::nodeContext(camera) + ": " + what +
                        ": the bounding box is empty (there is nothing to frame)");
    }
}

} // namespace

glm::mat4 Camera::projectionMatrix(float aspect, const DepthRange& range) const {
    checkAspect(*this, aspect);
    if (!std::isfinite(range.nearDistance) || !std::isfinite(range.farDistance) ||
        range.farDistance <= range.nearDistance) {
        throw DataError(detail::nodeContext(*this) +
                        ": farDistance must be finite and greater than nearDistance, got "
                        "nearDistance " +
                        sg::formatFloat(range.nearDistance) + ", farDistance " +
                        sg::formatFloat(range.farDistance));
    }
    const glm::mat4 result = projection(aspect, range);
    if (!detail::isFinite(result)) {
        throw DataError(detail::nodeContext(*this) + ": nearDistance " +
                        sg::formatFloat(range.nearDistance) + " and farDistance " +
                        sg::formatFloat(range.farDistance) +
                        " make a projection that is not finite in single precision (their "
                        "product overflows); use smaller distances");
    }
    return result;
}

DepthRange Camera::depthRangeFor(const sg::Box3& worldBox) const {
    checkBox(*this, worldBox, "depthRangeFor()");
    const glm::mat4 view = viewMatrix();
    float nearest = std::numeric_limits<float>::max();
    float farthest = std::numeric_limits<float>::lowest();
    for (int corner = 0; corner < 8; ++corner) {
        // The camera looks along -z in its own space: depth is -z.
        const float depth = -(view * glm::vec4(worldBox.corner(corner), 1.0f)).z;
        nearest = std::min(nearest, depth);
        farthest = std::max(farthest, depth);
    }
    // A margin keeps the box's own faces off the clipping planes (depth rounding).
    const float margin = 0.01f * (farthest - nearest) +
                         1e-5f * std::max({1.0f, std::abs(nearest), std::abs(farthest)});
    DepthRange range{nearest - margin, farthest + margin};
    if (range.farDistance <= minimumNearDistance(range.farDistance)) {
        // The whole box lies behind a perspective camera: nothing of it can be seen, so any
        // valid range will do; keep the camera's own.
        return {nearDistance.value(), farDistance.value()};
    }
    range.nearDistance = std::max(range.nearDistance, minimumNearDistance(range.farDistance));
    return range;
}

void Camera::viewAll(const sg::Box3& box, float aspect) {
    checkBox(*this, box, "viewAll()");
    checkAspect(*this, aspect);
    float radius = 0.5f * glm::length(box.size());
    if (radius == 0.0f) {
        radius = 1.0f;
    }
    const float distance = frameSphere(radius, aspect);
    position = box.center() - viewDirection() * distance;
    nearDistance = std::max(distance - radius, minimumNearDistance(distance + radius));
    farDistance = distance + radius;
    focalDistance = distance;
}

void Camera::doAction(sg::Action& action) {
    detail::requireFinite(*this, position);
    detail::requireFinite(*this, orientation);
    sg::State& state = action.state();
    const glm::mat4 modelMatrix = state.get<sg::ModelMatrixElement>().matrix;
    state.modify<CameraElement>() = CameraElement{this, modelMatrix};
}

} // namespace texsplat::nodes
