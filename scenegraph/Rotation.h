#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace texsplat::sg {

/// @brief A rotation as Inventor writes it: a unit axis and an angle in radians.
///
/// Stored as axis + angle (not as a quaternion) so that a value read from a file is written back
/// exactly as it was read.
class Rotation {
public:
    /// @brief The identity: axis (0,0,1), angle 0.
    Rotation() = default;

    /// @brief `angle` radians about `axis` (any length; a zero axis means no rotation).
    Rotation(const glm::vec3& axis, float angle) : mAxis(axis), mAngle(angle) {}

    /// @brief The axis as given.
    const glm::vec3& axis() const { return mAxis; }

    /// @brief The angle in radians.
    float angle() const { return mAngle; }

    /// @brief The unit quaternion (identity for a zero axis).
    glm::quat quaternion() const;

    /// @brief The 4x4 rotation matrix (column vectors, as glm).
    glm::mat4 matrix() const;

    /// @brief Equal axis and angle.
    bool operator==(const Rotation& other) const {
        return mAxis == other.mAxis && mAngle == other.mAngle;
    }

    /// @brief Not operator==.
    bool operator!=(const Rotation& other) const { return !(*this == other); }

private:
    glm::vec3 mAxis{0.0f, 0.0f, 1.0f};
    float mAngle = 0.0f;
};

} // namespace texsplat::sg
