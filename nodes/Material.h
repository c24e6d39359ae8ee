#pragma once

#include "scenegraph/Declare.h"
#include "scenegraph/Node.h"
#include "scenegraph/fields/Fields.h"

namespace texsplat::nodes {

/// @brief The surface material of the polygon geometry that follows (Inventor's Material):
/// sets MaterialElement.
///
/// Inventor's Material holds lists (MF fields) for per-part materials; texsplat's meshes take one
/// material, so these fields are single-valued (SF): a file with one value per field reads the
/// same in Coin and here. Material does not affect splats; their colours come from the
/// TransferFunction.
///
/// File format:
/// @code
/// Material {
///     diffuseColor   0.8 0.8 0.8
///     emissiveColor  0 0 0
///     transparency   0
/// }
/// @endcode
class Material : public sg::Declare<Material, sg::Node> {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "Material";

    sg::SFColor diffuseColor;  ///< reflected colour under light
    sg::SFColor emissiveColor; ///< colour emitted regardless of light
    sg::SFFloat transparency;  ///< 0 opaque … 1 invisible

    /// @brief Sets MaterialElement from the fields.
    /// @throws DataError when transparency lies outside [0, 1] or a colour is not finite.
    void doAction(sg::Action& action) override;

protected:
    Material();
};

} // namespace texsplat::nodes
