#pragma once

#include "nodes/Camera.h"
#include "scenegraph/Node.h"
#include "scenegraph/WorkProgress.h"

#include <glm/vec3.hpp>

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

} // namespace texsplat::render
