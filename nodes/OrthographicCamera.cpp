#include "nodes/OrthographicCamera.h"

#include "nodes/detail/NodeContext.h"
#include "scenegraph/Error.h"
#include "scenegraph/fields/ValueFormat.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>

namespace texsplat::nodes {

OrthographicCamera::OrthographicCamera() {
    addField(height, "height", 2.0f, "Height of the view volume in world units, > 0");
}

glm::mat4 OrthographicCamera::projection(float aspect, const DepthRange& range) const {
    const float h = height.value();
    if (!std::isfinite(h) || h <= 0.0f) {
        throw DataError(detail::nodeContext(*this) + ": height must be finite and positive, got " +
                        sg::formatFloat(h));
    }
    const float halfHeight = 0.5f * h;
    const float halfWidth = halfHeight * aspect;
    return glm::ortho(-halfWidth, halfWidth, -halfHeight, halfHeight, range.nearDistance,
                      range.farDistance);
}

float OrthographicCamera::frameSphere(float radius, float aspect) {
    height = aspect < 1.0f ? 2.0f * radius / aspect : 2.0f * radius;
    return 2.0f * radius;
}

float OrthographicCamera::minimumNearDistance(float /*rangeFar*/) const {
    // A parallel projection has no singularity at the eye: the near plane may even lie behind it.
    return std::numeric_limits<float>::lowest();
}

} // namespace texsplat::nodes
