#pragma once

#include <glm/glm.hpp>

namespace texsplat::nodes {

/// @brief State element: the current surface material (set by Material), used by the polygon
/// geometry (meshes, fibers). The defaults are Inventor's.
struct MaterialElement {
    /// @brief Reflected colour under light.
    glm::vec3 diffuseColor{0.8f};
    /// @brief Colour emitted regardless of light.
    glm::vec3 emissiveColor{0.0f};
    /// @brief 0 opaque … 1 invisible.
    float transparency = 0.0f;
};

} // namespace texsplat::nodes
