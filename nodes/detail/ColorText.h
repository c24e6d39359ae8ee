#pragma once

#include "scenegraph/fields/ValueFormat.h"

#include <glm/glm.hpp>

#include <cmath>
#include <string>

namespace texsplat::nodes::detail {

/// @brief Whether every channel of `color` is finite (the nodes' checks on color fields).
inline bool isFiniteColor(const glm::vec3& color) {
    return std::isfinite(color.r) && std::isfinite(color.g) && std::isfinite(color.b);
}

/// @brief `color` as a scene file writes it ("1 0.5 nan"), for error messages.
inline std::string formatColor(const glm::vec3& color) {
    return sg::formatFloat(color.r) + " " + sg::formatFloat(color.g) + " " +
           sg::formatFloat(color.b);
}

} // namespace texsplat::nodes::detail
