#pragma once

#include "scenegraph/Fwd.h"
#include "scenegraph/Rotation.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace texsplat::render {

/// @brief The active camera of a render traversal as matrices in the traversal root's space.
struct CameraView {
    /// @brief Root space to camera space (the camera's view matrix after the inverse of the
    /// model matrix where the camera stands, so a Transform above a camera places it).
    glm::mat4 view{1.0f};
    /// @brief Camera space to clip space for the action's framebuffer aspect.
    glm::mat4 projection{1.0f};
    /// @brief Unit viewing direction, root space.
    glm::vec3 viewDirection{0.0f, 0.0f, -1.0f};

    /// @brief The camera of `state` (the last one met, Inventor's rule) for an image of
    /// `aspectRatio` (width over height): what any action sees, so that sg::RayCastAction sees
    /// the same rays as FrameAction's backends.
    /// @throws DataError "<node>: no camera before this node" when there is none, or what the
    /// camera throws for unusable fields.
    static CameraView current(sg::State& state, const sg::Node& node, float aspectRatio);
};

/// @brief The camera orientation that turns the default view direction (0, 0, −1) to
/// `direction` by the smallest rotation (a half turn about y for (0, 0, 1)). `direction` must
/// not be zero.
sg::Rotation rotationLookingAlong(const glm::vec3& direction);

/// @brief The camera orientation that looks along `direction` with `up` pointing up in the
/// image as far as it can: the image's up is `up` less its part along `direction`.
/// @throws DataError when `direction` or `up` is zero or not finite, or `up` is parallel to
/// `direction` (no up can be seen).
sg::Rotation rotationLookingAlong(const glm::vec3& direction, const glm::vec3& up);

} // namespace texsplat::render
