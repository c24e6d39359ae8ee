#pragma once

#include "nodes/Camera.h"

namespace texsplat::nodes {

/// @brief A camera with parallel projection (Inventor's OrthographicCamera): the view volume is
/// a box `height` high and `height * aspect` wide.
///
/// viewAll() sets `height` to the bounding sphere's diameter (divided by the aspect when the
/// viewport is taller than wide) and puts the camera at twice the sphere's radius from its centre,
/// so the near plane (at one radius) stays in front of the camera.
///
/// File format:
/// @code
/// OrthographicCamera {
///     viewportMapping  ADJUST_CAMERA
///     position         0 0 1
///     orientation      0 0 1 0
///     nearDistance     1
///     farDistance      10
///     aspectRatio      1
///     focalDistance    5
///     height           2
/// }
/// @endcode
class OrthographicCamera : public sg::Declare<OrthographicCamera, Camera> {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "OrthographicCamera";

    sg::SFFloat height; ///< height of the view volume, world units, > 0

protected:
    OrthographicCamera();

    glm::mat4 projection(float aspect, const DepthRange& range) const override;
    float frameSphere(float radius, float aspect) override;
    float minimumNearDistance(float rangeFar) const override;
};

} // namespace texsplat::nodes
