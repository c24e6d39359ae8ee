#include "nodes/render/SplatView.h"

#include "scenegraph/Error.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <cmath>
#include <sstream>

namespace texsplat::render {
namespace {

bool isFinite(const glm::mat4& matrix) {
    for (int column = 0; column < 4; ++column) {
        for (int row = 0; row < 4; ++row) {
            if (!std::isfinite(matrix[column][row])) {
                return false;
            }
        }
    }
    return true;
}

} // namespace

SplatView SplatView::fromMatrices(const glm::mat4& model, const glm::mat4& view,
                                  const glm::mat4& projection, const glm::vec3& spacing) {
    for (int axis = 0; axis < 3; ++axis) {
        if (!std::isfinite(spacing[axis]) || !(spacing[axis] > 0.0f)) {
            std::ostringstream message;
            message << "splat view: voxel spacing (" << spacing.x << ", " << spacing.y << ", "
                    << spacing.z << ") must be finite and positive";
            throw DataError(message.str());
        }
    }
    const glm::mat4 modelView = view * model;
    if (!isFinite(modelView) || !isFinite(projection) ||
        !(std::abs(glm::determinant(modelView)) > 0.0f)) {
        throw DataError("splat view: the model-view matrix is singular or not finite");
    }
    const glm::mat4 cameraToLocal = glm::inverse(modelView);
    SplatView result;
    result.localToClip = projection * modelView;
    result.isPerspective = projection[3][3] == 0.0f;
    result.eye = glm::vec3(cameraToLocal * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    result.direction = glm::normalize(glm::vec3(cameraToLocal * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f)));
    result.spacing = spacing;
    return result;
}

octree::View SplatView::octreeView() const {
    return isPerspective ? octree::View::perspective(eye, direction)
                         : octree::View::orthographic(direction);
}

} // namespace texsplat::render
