#include "nodes/PerspectiveCamera.h"

#include "nodes/detail/NodeContext.h"
#include "scenegraph/Error.h"
#include "scenegraph/fields/ValueFormat.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace texsplat::nodes {

namespace {
// A perspective near plane closer than far / kDepthRatio wastes the depth buffer's precision.
constexpr float kDepthRatio = 1000.0f;
} // namespace

PerspectiveCamera::PerspectiveCamera() {
    // Inventor's default: 45 degrees.
    addField(heightAngle, "heightAngle", glm::quarter_pi<float>(),
             "Full vertical opening angle in radians, between 0 and pi");
}

void PerspectiveCamera::checkHeightAngle() const {
    const float angle = heightAngle.value();
    if (!std::isfinite(angle) || angle <= 0.0f || angle >= glm::pi<float>()) {
        throw DataError(detail::nodeContext(*this) +
                        ": heightAngle must lie strictly between 0 and pi radians, got " +
                        sg::formatFloat(angle));
    }
}

glm::mat4 PerspectiveCamera::projection(float aspect, const DepthRange& range) const {
    checkHeightAngle();
    if (range.nearDistance <= 0.0f) {
        throw DataError(detail::nodeContext(*this) +
                        ": nearDistance must be positive for a perspective projection, got " +
                        sg::formatFloat(range.nearDistance));
    }
    return glm::perspective(heightAngle.value(), aspect, range.nearDistance, range.farDistance);
}

float PerspectiveCamera::frameSphere(float radius, float aspect) {
    checkHeightAngle();
    float halfAngle = 0.5f * heightAngle.value();
    if (aspect < 1.0f) {
        // A viewport taller than wide: the horizontal opening is the narrower one.
        halfAngle = std::atan(std::tan(halfAngle) * aspect);
    }
    return radius / std::sin(halfAngle);
}

float PerspectiveCamera::minimumNearDistance(float rangeFar) const {
    return rangeFar / kDepthRatio;
}

} // namespace texsplat::nodes
