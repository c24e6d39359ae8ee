#pragma once

/// @file
/// @brief The value field types, as Inventor names them. SFEnum, SFNode, MFNode and SFTrigger
/// have their own headers (they need more than a value, or have none).
///
/// | type       | C++ value        | ASCII                                  | zero value   |
/// |------------|------------------|----------------------------------------|--------------|
/// | SFBool     | bool             | `TRUE` / `FALSE` (reads 1/0 too)       | FALSE        |
/// | SFInt32    | std::int32_t     | `-3`                                   | 0            |
/// | SFFloat    | float            | `1.6` (shortest round-trip)            | 0            |
/// | SFString   | std::string      | `"text \"quoted\""`                    | ""           |
/// | SFVec2f    | glm::vec2        | `x y`                                  | 0 0          |
/// | SFVec3f    | glm::vec3        | `x y z`                                | 0 0 0        |
/// | SFColor    | glm::vec3 (rgb)  | `r g b`                                | 0 0 0        |
/// | SFRotation | Rotation         | `axisX axisY axisZ angleRadians`       | 0 0 1 0      |
/// | SFMatrix   | glm::mat4        | 16 numbers, Inventor row order         | identity     |
///
/// SFMatrix: Inventor writes row vectors with the translation in the last row; glm keeps
/// column vectors with the translation in the last column. Both store the same 16 numbers in
/// the same order, so the text is glm's memory order (`m[0][0] m[0][1] ... m[3][3]`).

#include "scenegraph/fields/MField.h"
#include "scenegraph/fields/SField.h"
#include "scenegraph/fields/detail/ValueTraits.h"

namespace texsplat::sg {

/// @brief TRUE or FALSE.
using SFBool = SField<detail::BoolTraits>;
/// @brief A 32-bit signed integer.
using SFInt32 = SField<detail::Int32Traits>;
/// @brief A float.
using SFFloat = SField<detail::FloatTraits>;
/// @brief A UTF-8 string.
using SFString = SField<detail::StringTraits>;
/// @brief A 2D vector.
using SFVec2f = SField<detail::Vec2fTraits>;
/// @brief A 3D vector.
using SFVec3f = SField<detail::Vec3fTraits>;
/// @brief An RGB color.
using SFColor = SField<detail::ColorTraits>;
/// @brief A rotation (axis and angle).
using SFRotation = SField<detail::RotationTraits>;
/// @brief A 4x4 matrix.
using SFMatrix = SField<detail::MatrixTraits>;

/// @brief Booleans.
using MFBool = MField<detail::BoolTraits>;
/// @brief Integers.
using MFInt32 = MField<detail::Int32Traits>;
/// @brief Floats.
using MFFloat = MField<detail::FloatTraits>;
/// @brief 2D vectors.
using MFVec2f = MField<detail::Vec2fTraits>;
/// @brief 3D vectors.
using MFVec3f = MField<detail::Vec3fTraits>;
/// @brief RGB colors.
using MFColor = MField<detail::ColorTraits>;
/// @brief Strings.
using MFString = MField<detail::StringTraits>;
/// @brief Rotations.
using MFRotation = MField<detail::RotationTraits>;
/// @brief 4x4 matrices.
using MFMatrix = MField<detail::MatrixTraits>;

} // namespace texsplat::sg
