#pragma once

#include "scenegraph/Node.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <functional>
#include <string>
#include <vector>

namespace texsplat::annotation {

/// @brief What one colour bar of a ColorLegend shows: a colour map S(t) over t in [0, 1], the
/// values of t = 0 and t = 1, and a title that says what the values are.
struct ColorBar {
    /// @brief The colour map S(t), t in [0, 1].
    using ColorMap = std::function<glm::vec3(float t)>;

    ColorMap colorMap;    ///< the colours, as the splats take them from the transfer function
    glm::vec2 range{0.0f, 1.0f}; ///< the values at t = 0 and t = 1
    std::string title;    ///< "Temperature (K)"; empty: none

    /// @brief One bar per distinct colour scale the scene's splat nodes draw with, in traversal
    /// order (splat nodes that share a transfer function and the quantity it colours share a
    /// bar). What a splat node's colours mean:
    /// - a scalar medium (TextureSplat, GaussianSplat, CombinedSplat): the values of its
    ///   VolumeData's scalar field over the range its TransferFunction uses for them
    ///   (TransferFunction::dataScale());
    /// - VectorSplat by `colorMode`: MAGNITUDE the vector magnitudes, SCALAR the values of
    ///   `colorData`, POSITION the world coordinate `positionAxis` over `positionRange`;
    ///   CONSTANT colours by nothing and has no bar.
    /// The title is the transfer function's (titleOf() its `title` and `units`); without one,
    /// what the colour stands for where the splat node says more than the values: "magnitude",
    /// the `colorData` node's name, the axis ("z"). A scene without splat nodes gets its first
    /// TransferFunction over its first VolumeData's data (or over its `range` without one).
    /// @throws DataError when the scene has no TransferFunction; what reading a volume throws.
    static std::vector<ColorBar> ofScene(sg::Node& root);

    /// @brief A transfer function's title for the bar: `title (units)`, the title alone, or the
    /// units alone; "" when both are empty.
    static std::string titleOf(const std::string& title, const std::string& units);
};

} // namespace texsplat::annotation
