#include "nodes/render/SplatView.h"

#include "nodes/detail/Finite.h"
#include "scenegraph/Error.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace texsplat::render {

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
    // In double: a volume scaled by 1e-20 has a determinant of 1e-60, which float rounds to 0.
    const glm::dmat4 exactModelView = glm::dmat4(view) * glm::dmat4(model);
    if (!nodes::detail::isFinite(modelView) || !nodes::detail::isFinite(projection) ||
        !(std::abs(glm::determinant(exactModelView)) > 0.0)) {
        throw DataError("splat view: the model-view matrix is singular or not finite");
    }
    // The eye and direction in double too: under a scale of 1e-20 the direction is 1e20 long,
    // whose square overflows a float's normalization.
    const glm::dmat4 cameraToLocal = glm::inverse(exactModelView);
    SplatView result;
    result.localToClip = projection * modelView;
    result.isPerspective = projection[3][3] == 0.0f;
    result.eye = glm::vec3(cameraToLocal * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    result.direction =
        glm::vec3(glm::normalize(glm::dvec3(cameraToLocal * glm::dvec4(0.0, 0.0, -1.0, 0.0))));
    result.spacing = spacing;
    return result;
}

octree::View SplatView::octreeView() const {
    return isPerspective ? octree::View::perspective(eye, direction)
                         : octree::View::orthographic(direction);
}

octree::View SplatView::refinementView(double reach) const {
    // A point is inside where -w <= x <= w and -w <= y <= w in clip space: rows 3 ± 0, 3 ± 1
    // of the local-to-clip matrix (glm is column-major: m[column][row]).
    const glm::dmat4 m(localToClip);
    const auto row = [&m](int index) {
        return glm::dvec4(m[0][index], m[1][index], m[2][index], m[3][index]);
    };
    const octree::View::Sides sides{row(3) + row(0), row(3) - row(0), row(3) + row(1),
                                    row(3) - row(1)};
    // A splat draws within `reach` sizes of its centre; a node's size is its largest edge in
    // voxels, at most its largest world edge over the finest spacing voxels, each at most the
    // coarsest spacing long.
    const double finest = std::min({spacing.x, spacing.y, spacing.z});
    const double coarsest = std::max({spacing.x, spacing.y, spacing.z});
    return octreeView().seeingOnly(sides, reach * coarsest / finest);
}

} // namespace texsplat::render
