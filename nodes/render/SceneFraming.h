#pragma once

#include "nodes/Camera.h"
#include "scenegraph/Node.h"
#include "scenegraph/WorkProgress.h"

#include <glm/vec3.hpp>

#include <optional>
#include <string>

namespace texsplat::render {

/// @brief The kind of camera framedScene() adds to a scene without one.
enum class FramingCamera {
    Perspective,  ///< nodes::PerspectiveCamera opening kFramingHeightAngle
    Orthographic, ///< nodes::OrthographicCamera
};

/// @brief The vertical opening angle of the perspective camera that framedScene() adds: 30
/// degrees (ParaView's default view angle), narrower than Inventor's 45, so the camera stands
/// further back and a box keeps its shape (its near faces are less than a fifth larger than its
/// far ones, where 45 degrees makes them a third larger).
inline constexpr float kFramingHeightAngle = 0.5235988f;

/// @brief How framedScene() frames a scene without a camera.
struct Framing {
    FramingCamera camera = FramingCamera::Perspective; ///< the kind of camera added
    glm::vec3 direction{0.0f, 0.0f, -1.0f};            ///< the viewing direction, not zero
    /// @brief What is up in the image (rotationLookingAlong(direction, up)); none: the
    /// smallest turn from the default view (along -z, +y up) to `direction`.
    std::optional<glm::vec3> up;
    std::string name = "scene"; ///< what messages call the scene (a file name, say)
    /// @brief Told how loading the volumes for the bounding box goes, and may cancel it
    /// (VolumeData::load()); empty: nothing is told.
    sg::WorkProgress progress;
};

/// @brief How to turn and magnify the camera a scene is seen through, about the camera's focal
/// point: the --direction, --up, --azimuth, --elevation and --zoom of `texsplat render` and
/// `view`, and the Python module's `azimuth`, `elevation` and `zoom`.
struct ViewChange {
    std::optional<glm::vec3> direction; ///< look along it (finite, not zero); none: as it looks
    /// @brief What is up in the image (finite, not zero, across the view); none: the smallest
    /// turn to `direction`, or the camera's own up.
    std::optional<glm::vec3> up;
    float azimuth = 0.0f;   ///< degrees about the camera's up axis (ParaView's and the viewer's orbit)
    float elevation = 0.0f; ///< degrees about its right axis, after the azimuth
    float zoom = 1.0f;      ///< magnification > 0 (2: things look twice as large)
};

/// @brief Turns and magnifies `camera` as `change` says: `direction` turns it to look along that
/// direction at its focal point, `up` rolls it so that `up` is up in the image, `azimuth` and
/// `elevation` orbit it about the focal point, `zoom` narrows its opening angle (or its
/// orthographic height).
/// @throws DataError naming the value ("zoom: expected a magnification > 0, got 0") for a zoom
/// that is not finite and > 0, angles that are not finite, a zero or non-finite direction or up,
/// or an up along the view ("up: the up direction is parallel to the viewing direction: ...").
void changeView(nodes::Camera& camera, const ViewChange& change);

/// @brief The first camera of `scene` in traversal order, or nullptr.
nodes::Camera* findCamera(sg::Node& scene);

/// @brief The scene as drawn: `scene` itself when it has a camera, else a Separator holding a new
/// camera that frames the scene's bounding box (Camera::viewAll()) for a viewport of `aspect`
/// (width over height), looking along `framing.direction` with `framing.up` up, then the scene.
/// This is what `texsplat render` does for a scene file without a camera. Framing takes the
/// scene's bounding box, which loads (or generates) its volumes, reporting to
/// `framing.progress`.
/// @throws DataError for a zero direction, an up along it, or a scene with neither geometry nor
/// camera; sg::Cancelled when `framing.progress` cancelled a load.
sg::Node::Ptr framedScene(const sg::Node::Ptr& scene, float aspect, const Framing& framing = {});

/// @brief A camera of kind `kind` that sees what `camera` sees at its focal distance: the same
/// position, orientation, near, far and focal distance; an orthographic view as high as the
/// perspective one is at the focal distance (2 d tan(heightAngle / 2)), and the other way round
/// (ParaView's switch to and from parallel projection). A copy when `camera` is of that kind.
nodes::Camera::Ptr cameraOfKind(const nodes::Camera& camera, FramingCamera kind);

/// @brief Puts `replacement` wherever `scene` holds `camera` (every group that has it as a
/// child); answers how many places that was.
int replaceCamera(sg::Node& scene, const nodes::Camera& camera,
                  const nodes::Camera::Ptr& replacement);

/// @brief The scene as drawn with a changed view, as `texsplat render` draws a scene file: when
/// `scene` has a camera, that camera changed by changeView() (a `direction` turns it, an `up`
/// rolls it), and `scene` itself; else framedScene() looking along `change.direction` (when
/// given, else `framing.direction`) with `change.up` up (when given, else `framing.up`), its new
/// camera then orbited and magnified by changeView().
/// @throws what framedScene() and changeView() throw.
sg::Node::Ptr viewedScene(const sg::Node::Ptr& scene, float aspect, Framing framing,
                          const ViewChange& change);

} // namespace texsplat::render
