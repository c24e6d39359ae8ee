#pragma once

#include "scenegraph/Declare.h"
#include "scenegraph/Node.h"
#include "scenegraph/fields/Fields.h"

namespace texsplat::nodes {

/// @brief A light from infinitely far away (Inventor's DirectionalLight) that lights the polygon
/// geometry after it within its Separator: when `on`, adds itself to LightElement with its
/// direction mapped by the current model matrix. Splats emit (paper, section 2) and are lit only
/// where their TransferFunction shades (`shade`: render::VolumeLighting); vector marks never are.
///
/// File format:
/// @code
/// DirectionalLight {
///     on         TRUE
///     intensity  1
///     color      1 1 1
///     direction  0 0 -1
/// }
/// @endcode
class DirectionalLight : public sg::Declare<DirectionalLight, sg::Node> {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "DirectionalLight";

    sg::SFBool on;         ///< whether the light shines
    sg::SFFloat intensity; ///< brightness factor, 0 … 1 in Inventor (larger values allowed)
    sg::SFColor color;     ///< light colour
    sg::SFVec3f direction; ///< direction the light travels in, local space

    /// @brief Adds the light to LightElement when it is on.
    /// @throws DataError for a zero or non-finite direction, or a negative or non-finite
    /// intensity.
    void doAction(sg::Action& action) override;

protected:
    DirectionalLight();
};

} // namespace texsplat::nodes
