#pragma once

#include <glm/glm.hpp>

#include <vector>

namespace texsplat::nodes {

/// @brief One directional light as the render action needs it: in the space of the traversal's
/// root (the light's direction already mapped by the model matrix where the light stands).
struct DirectionalLightSource {
    /// @brief Unit direction the light travels in, root space.
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
    /// @brief Colour times intensity.
    glm::vec3 color{1.0f};
};

/// @brief State element: the lights that are on. As in Inventor, a light shines on what follows
/// it within its Separator; lights accumulate.
struct LightElement {
    /// @brief The lights met so far, in traversal order.
    std::vector<DirectionalLightSource> lights;
};

} // namespace texsplat::nodes
