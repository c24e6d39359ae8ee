#pragma once

#include "scenegraph/Declare.h"
#include "scenegraph/Node.h"
#include "scenegraph/fields/Fields.h"

#include <glm/glm.hpp>

namespace texsplat::nodes {

/// @brief A general transformation (Inventor's Transform): scale about `center` along axes
/// turned by `scaleOrientation`, then rotate about `center`, then translate.
///
/// As a column-vector matrix (what matrix() answers):
/// M = T(translation) · T(center) · R(rotation) · R(scaleOrientation) · S(scaleFactor) ·
///     R(scaleOrientation)⁻¹ · T(center)⁻¹.
/// Every action post-multiplies sg::ModelMatrixElement by M, so the nodes that follow, and the
/// bounding boxes BoundingBoxAction collects from them, are transformed.
///
/// File format:
/// @code
/// Transform {
///     translation       0 0 0
///     rotation          0 0 1 0
///     scaleFactor       1 1 1
///     scaleOrientation  0 0 1 0
///     center            0 0 0
/// }
/// @endcode
class Transform : public sg::Declare<Transform, sg::Node> {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "Transform";

    sg::SFVec3f translation;       ///< applied last
    sg::SFRotation rotation;       ///< about `center`
    sg::SFVec3f scaleFactor;       ///< along the axes of `scaleOrientation`, about `center`
    sg::SFRotation scaleOrientation; ///< orientation of the scale axes
    sg::SFVec3f center;            ///< fixed point of rotation and scale

    /// @brief The local matrix M above (column vectors).
    glm::mat4 matrix() const;

    /// @brief Post-multiplies sg::ModelMatrixElement by matrix().
    /// @throws DataError (located at this node) when a field is not finite, a scale is zero, or
    /// the product overflows, so that a wrong transformation is blamed here rather than on the
    /// splat node or framing that would trip over it.
    void doAction(sg::Action& action) override;

protected:
    Transform();

private:
    void checkFields() const;
};

} // namespace texsplat::nodes
