#pragma once

#include "scenegraph/Box3.h"
#include "scenegraph/Rotation.h"

#include <glm/vec2.hpp>

namespace texsplat::nodes {
class Camera;
} // namespace texsplat::nodes

namespace texsplat::apps {

/// @brief Turns mouse gestures into camera moves around a point of interest, as Inventor's
/// examiner viewer does: orbit about the focal point, zoom towards it, pan across the view.
///
/// The controller edits the camera's fields (position, orientation, focalDistance, and the
/// near/far distances so the scene's box stays between the clipping planes), so the scene graph
/// notices the change like any other edit and a sensor on it can ask for a redraw.
class OrbitController {
public:
    /// @brief Controls `camera` for a scene whose world bounding box is `sceneBox`. Remembers
    /// the camera's current placement for reset().
    OrbitController(nodes::Camera& camera, const sg::Box3& sceneBox);

    /// @brief Rotates about the focal point by a drag of `pixels` in a viewport `viewportHeight`
    /// pixels high (a drag across the whole height turns by about half a turn).
    void orbit(const glm::vec2& pixels, float viewportHeight);

    /// @brief Moves the camera and its focal point across the view so the scene follows a drag of
    /// `pixels`.
    void pan(const glm::vec2& pixels, float viewportHeight);

    /// @brief Moves towards the focal point (steps > 0) or away from it; each step is 10 %.
    void zoom(float steps);

    /// @brief Back to the placement the controller started with.
    void reset();

private:
    void fitClippingPlanes();

    nodes::Camera& mCamera;
    sg::Box3 mSceneBox;
    struct Placement {
        glm::vec3 position;
        sg::Rotation orientation;
        float focalDistance;
        float nearDistance;
        float farDistance;
        float orthographicHeight; // OrthographicCamera's height (zoom scales it); 0 otherwise
    };
    Placement placement() const;

    Placement mStart;
};

} // namespace texsplat::apps
