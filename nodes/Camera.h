#pragma once

#include "scenegraph/Box3.h"
#include "scenegraph/Declare.h"
#include "scenegraph/EnumNames.h"
#include "scenegraph/Node.h"
#include "scenegraph/fields/Fields.h"
#include "scenegraph/fields/SFEnum.h"

#include <glm/glm.hpp>

namespace texsplat::nodes {

/// @brief How Inventor fits a camera's view volume to a viewport of another aspect ratio
/// (SoCamera::ViewportMapping).
enum class ViewportMapping {
    CropViewportFillFrame, ///< crop the viewport to the camera's aspect, fill the rest
    CropViewportLineFrame, ///< crop the viewport, draw a frame around it
    CropViewportNoFrame,   ///< crop the viewport
    AdjustCamera,          ///< widen the view volume to the viewport (Inventor's default)
    LeaveAlone,            ///< stretch the image to the viewport
};

/// @brief Scene-file names of ViewportMapping.
inline const sg::EnumNames kViewportMappingNames{
    {"CROP_VIEWPORT_FILL_FRAME", ViewportMapping::CropViewportFillFrame},
    {"CROP_VIEWPORT_LINE_FRAME", ViewportMapping::CropViewportLineFrame},
    {"CROP_VIEWPORT_NO_FRAME", ViewportMapping::CropViewportNoFrame},
    {"ADJUST_CAMERA", ViewportMapping::AdjustCamera},
    {"LEAVE_ALONE", ViewportMapping::LeaveAlone}};

/// @brief Near and far clipping distances along the viewing direction.
struct DepthRange {
    /// @brief Distance of the near plane (positive for a perspective camera).
    float nearDistance = 1.0f;
    /// @brief Distance of the far plane (> nearDistance).
    float farDistance = 10.0f;
};

/// @brief Base of the cameras, as Inventor's SoCamera: a viewpoint at `position` looking along
/// the local -z axis turned by `orientation` (local +y is up).
///
/// During any traversal a camera puts itself, with the model matrix in effect where it stands,
/// into CameraElement (so a Transform above a camera moves it, as in Inventor). The render action
/// uses the last camera met.
///
/// `viewportMapping` and `aspectRatio` (width / height) are read and written, so Inventor files
/// pass through unchanged, but not used by texsplat's renderer: it passes the viewport's aspect
/// to projectionMatrix(), which keeps the vertical opening and fits the width to the viewport
/// (Inventor's ADJUST_CAMERA does the same for viewports wider than tall).
/// `focalDistance` is the distance to the point of interest (what a viewer orbits around);
/// viewAll() sets it to the bounding sphere's centre. The fields come in Inventor's order.
///
/// File format (fields common to both cameras):
/// @code
/// viewportMapping  ADJUST_CAMERA   # SFEnum (ViewportMapping), not used
/// position         0 0 1
/// orientation      0 0 1 0
/// nearDistance     1
/// farDistance      10
/// aspectRatio      1               # not used
/// focalDistance    5
/// @endcode
class Camera : public sg::Declare<Camera, sg::Node> {
public:
    /// @brief The abstract type's name.
    static constexpr const char* kTypeName = "Camera";

    sg::SFEnum viewportMapping; ///< ViewportMapping; read and written, not used
    sg::SFVec3f position;       ///< viewpoint, in the camera's local space
    sg::SFRotation orientation; ///< rotation of the default view direction (0,0,-1)
    sg::SFFloat nearDistance;   ///< distance of the near clipping plane
    sg::SFFloat farDistance;    ///< distance of the far clipping plane
    sg::SFFloat aspectRatio;    ///< width / height the camera was set up for; not used
    sg::SFFloat focalDistance;  ///< distance to the point of interest

    /// @brief The world-to-camera matrix (column vectors): the inverse of the camera's
    /// placement, translation `position` after rotation `orientation`.
    glm::mat4 viewMatrix() const;

    /// @brief The camera-to-clip matrix for a viewport of aspect `aspect` (width / height),
    /// with the near and far distances of the fields. OpenGL clip conventions (z in [-1, 1]).
    /// @throws DataError when `aspect` is not finite and positive or the fields do not describe
    /// a usable projection (a message naming the field).
    glm::mat4 projectionMatrix(float aspect) const;

    /// @brief As projectionMatrix(float), with near and far distances given (e.g. from
    /// depthRangeFor()).
    glm::mat4 projectionMatrix(float aspect, const DepthRange& range) const;

    /// @brief The tightest near/far distances that keep all of `worldBox` (given in the space the
    /// camera's fields are in) between the clipping planes, with a small margin; for a
    /// perspective camera the near distance stays positive (at least farDistance / 1000, so the
    /// depth buffer keeps its precision when the camera sits inside the box).
    /// @throws DataError when the box is empty.
    DepthRange depthRangeFor(const sg::Box3& worldBox) const;

    /// @brief Inventor's viewAll: keeps `orientation` and moves the camera back along its view
    /// direction until the bounding sphere of `box` fills the view of a viewport of aspect
    /// `aspect`; sets near and far to enclose the sphere and focalDistance to its centre. A box of
    /// zero size is framed as a sphere of radius 1.
    /// @throws DataError when the box is empty or `aspect` is not finite and positive.
    void viewAll(const sg::Box3& box, float aspect);

    /// @brief Unit view direction: orientation applied to (0,0,-1).
    glm::vec3 viewDirection() const;

    /// @brief Puts this camera into CameraElement.
    void doAction(sg::Action& action) override;

protected:
    Camera();

    /// @brief The projection of the concrete camera, once aspect and range are checked.
    virtual glm::mat4 projection(float aspect, const DepthRange& range) const = 0;

    /// @brief Sets the camera's size field (height angle or height) so that a sphere of `radius`
    /// fits a viewport of `aspect`, and answers the distance from the camera to the sphere's
    /// centre.
    virtual float frameSphere(float radius, float aspect) = 0;

    /// @brief The smallest near distance this camera allows for a range reaching `rangeFar`.
    virtual float minimumNearDistance(float rangeFar) const = 0;
};

} // namespace texsplat::nodes
