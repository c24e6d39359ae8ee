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
    Perspective,  ///< nodes::PerspectiveCamera (Inventor's default opening angle)
    Orthographic, ///< nodes::OrthographicCamera
};

/// @brief How framedScene() frames a scene without a camera.
struct Framing {
    FramingCamera camera = FramingCamera::Perspective; ///< the kind of camera added
    glm::vec3 direction{0.0f, 0.0f, -1.0f};            ///< the viewing direction, not zero
    std::string name = "scene"; ///< what messages call the scene (a file name, say)
    /// @brief Told how loading the volumes for the bounding box goes, and may cancel it
    /// (VolumeData::load()); empty: nothing is told.
    sg::WorkProgress progress;
};

/// @brief How to turn and magnify the camera a scene is seen through, about the camera's focal
/// point: the --direction, --azimuth, --elevation and --zoom of `texsplat render` and `view`, and
/// the Python module's `azimuth`, `elevation` and `zoom`.
struct ViewChange {
    std::optional<glm::vec3> direction; ///< look along it (finite, not zero); none: as it looks
    float azimuth = 0.0f;   ///< degrees about the camera's up axis (ParaView's and the viewer's orbit)
    float elevation = 0.0f; ///< degrees about its right axis, after the azimuth
    float zoom = 1.0f;      ///< magnification > 0 (2: things look twice as large)
};

/// @brief Turns and magnifies `camera` as `change` says: `direction` turns it to look along that
/// direction at its focal point, `azimuth` and `elevation` orbit it about the focal point, `zoom`
/// narrows its opening angle (or its orthographic height).
/// @throws DataError naming the value ("zoom: expected a magnification > 0, got 0") for a zoom
/// that is not finite and > 0, angles that are not finite, or a zero or non-finite direction.
void changeView(nodes::Camera& camera, const ViewChange& change);

/// @brief The first camera of `scene` in traversal order, or nullptr.
nodes::Camera* findCamera(sg::Node& scene);

/// @brief The scene as drawn: `scene` itself when it has a camera, else a Separator holding a new
/// camera that frames the scene's bounding box (Camera::viewAll()) for a viewport of `aspect`
/// (width over height), looking along `framing.direction`, then the scene. This is what
/// `texsplat render` does for a scene file without a camera. Framing takes the scene's bounding
/// box, which loads (or generates) its volumes, reporting to `framing.progress`.
/// @throws DataError for a zero direction or a scene with neither geometry nor camera;
/// sg::Cancelled when `framing.progress` cancelled a load.
sg::Node::Ptr framedScene(const sg::Node::Ptr& scene, float aspect, const Framing& framing = {});

/// @brief The scene as drawn with a changed view, as `texsplat render` draws a scene file: when
/// `scene` has a camera, that camera changed by changeView() (a `direction` turns it), and
/// `scene` itself; else framedScene() looking along `change.direction` (when given, else
/// `framing.direction`), its new camera then orbited and magnified by changeView().
/// @throws what framedScene() and changeView() throw.
sg::Node::Ptr viewedScene(const sg::Node::Ptr& scene, float aspect, Framing framing,
                          const ViewChange& change);

} // namespace texsplat::render
