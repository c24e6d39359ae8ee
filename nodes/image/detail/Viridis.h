#pragma once

#include <glm/vec3.hpp>

namespace texsplat::image::detail {

/// @brief The viridis colormap (van der Walt & Smith, matplotlib's default; perceptually
/// uniform, readable in gray and by color-blind viewers) at t ∈ [0, 1] (clamped; NaN gives
/// t = 0), as display (sRGB) values: dark blue-violet at 0, green at 0.5, yellow at 1.
glm::vec3 viridis(float t);

} // namespace texsplat::image::detail
