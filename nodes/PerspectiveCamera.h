#pragma once

#include "nodes/Camera.h"

namespace texsplat::nodes {

/// @brief A camera with perspective projection (Inventor's PerspectiveCamera): the view volume
/// is a frustum whose vertical opening is `heightAngle` (radians, the full angle).
///
/// viewAll() puts the camera at distance r / sin(heightAngle / 2) from the centre of the bounding
/// sphere of radius r (with the horizontal angle instead when the viewport is taller than wide),
/// so the sphere touches the frustum's sides.
///
/// File format:
/// @code
/// PerspectiveCamera {
///     viewportMapping  ADJUST_CAMERA
///     position         0 0 1
///     orientation      0 0 1 0
///     nearDistance     1
///     farDistance      10
///     aspectRatio      1
///     focalDistance    5
///     heightAngle      0.7853982   # pi / 4
/// }
/// @endcode
class PerspectiveCamera : public sg::Declare<PerspectiveCamera, Camera> {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "PerspectiveCamera";

    sg::SFFloat heightAngle; ///< full vertical opening angle, radians, in (0, pi)

    /// @brief Refuses a heightAngle outside (0, pi): what every projection asks, and what code
    /// that changes the angle (a zoom) asks first, since its arithmetic would wrap such an angle
    /// into the range.
    /// @throws DataError "PerspectiveCamera: heightAngle must lie strictly between 0 and pi
    /// radians, got 7".
    void checkHeightAngle() const;

protected:
    PerspectiveCamera();

    glm::mat4 projection(float aspect, const DepthRange& range) const override;
    float frameSphere(float radius, float aspect) override;
    float minimumNearDistance(float rangeFar) const override;
};

} // namespace texsplat::nodes
