#pragma once

#include "scenegraph/Declare.h"
#include "scenegraph/Node.h"
#include "scenegraph/fields/Fields.h"

namespace texsplat::nodes {

/// @brief The surface material of the polygon geometry that follows (Inventor's Material):
/// sets MaterialElement.
///
/// The fields are Inventor's, lists included: in Inventor each value belongs to one part or
/// vertex of the shapes (chosen by a MaterialBinding node). texsplat's meshes take one material,
/// so the renderer uses the first value of `diffuseColor`, `emissiveColor` and `transparency`;
/// a list left empty keeps the value of the Material before this one, as in Coin.
/// `ambientColor`, `specularColor` and `shininess` are read and written, so files pass through
/// texsplat and Coin unchanged, but not used by texsplat's renderer (its lighting is diffuse and
/// emissive only). Material does not affect splats; their colours come from the
/// TransferFunction.
///
/// File format:
/// @code
/// Material {
///     ambientColor   0.2 0.2 0.2   # MFColor, not used
///     diffuseColor   0.8 0.8 0.8   # MFColor
///     specularColor  0 0 0         # MFColor, not used
///     emissiveColor  0 0 0         # MFColor
///     shininess      0.2           # MFFloat, not used
///     transparency   0             # MFFloat, 0 … 1
/// }
/// @endcode
class Material : public sg::Declare<Material, sg::Node> {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "Material";

    sg::MFColor ambientColor;  ///< reflected ambient light; read and written, not used
    sg::MFColor diffuseColor;  ///< reflected colour under light (the first is used)
    sg::MFColor specularColor; ///< highlight colour; read and written, not used
    sg::MFColor emissiveColor; ///< colour emitted regardless of light (the first is used)
    sg::MFFloat shininess;     ///< 0 … 1, sharpness of highlights; read and written, not used
    sg::MFFloat transparency;  ///< 0 opaque … 1 invisible (the first is used)

    /// @brief Sets MaterialElement from the first value of each field it uses.
    /// @throws DataError when the first transparency lies outside [0, 1] or the first diffuse
    /// or emissive colour is not finite.
    void doAction(sg::Action& action) override;

protected:
    Material();
};

} // namespace texsplat::nodes
