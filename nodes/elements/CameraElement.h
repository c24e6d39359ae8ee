#pragma once

#include <glm/glm.hpp>

namespace texsplat::nodes {

class Camera;

/// @brief State element: the camera met last in the traversal (Inventor: the active camera),
/// and the model matrix in effect where it stands, so that a Transform above a camera places
/// it. The world-to-camera matrix is `camera->viewMatrix() * inverse(modelMatrix)`.
struct CameraElement {
    /// @brief The camera, or nullptr before any camera (non-owning: valid during the traversal).
    const Camera* camera = nullptr;
    /// @brief Local-to-root matrix at the camera.
    glm::mat4 modelMatrix{1.0f};
};

} // namespace texsplat::nodes
