#pragma once

#include <glm/glm.hpp>

namespace texsplat::sg {

/// @brief State element: the matrix from the current node's local space to the space of the
/// node the action was applied to (column vectors: `world = matrix * local`). Transform-like
/// nodes post-multiply it in their `doAction()`.
struct ModelMatrixElement {
    /// @brief Local-to-root matrix; identity at the start of a traversal.
    glm::mat4 matrix{1.0f};
};

} // namespace texsplat::sg
