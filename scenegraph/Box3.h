#pragma once

#include <glm/glm.hpp>

namespace texsplat::sg {

/// @brief An axis-aligned box, possibly empty (the result of bounding nothing).
class Box3 {
public:
    /// @brief The empty box.
    Box3();

    /// @brief The box from `min` to `max` (componentwise min <= max).
    Box3(const glm::vec3& min, const glm::vec3& max);

    /// @brief True when nothing has been added.
    bool isEmpty() const { return mMin.x > mMax.x; }

    /// @brief Lower corner (undefined when empty).
    const glm::vec3& min() const { return mMin; }

    /// @brief Upper corner (undefined when empty).
    const glm::vec3& max() const { return mMax; }

    /// @brief Midpoint (undefined when empty).
    glm::vec3 center() const { return 0.5f * (mMin + mMax); }

    /// @brief Corner `index` of the eight (0 to 7): bit 0 picks max().x over min().x, bit 1 the
    /// y, bit 2 the z (undefined when empty).
    glm::vec3 corner(int index) const;

    /// @brief Extent per axis; zero when empty.
    glm::vec3 size() const;

    /// @brief Grows to contain `point`.
    void extendBy(const glm::vec3& point);

    /// @brief Grows to contain `box`.
    void extendBy(const Box3& box);

    /// @brief The axis-aligned box around this box's eight corners mapped by `matrix`
    /// (column vectors, as glm). Empty stays empty.
    Box3 transformed(const glm::mat4& matrix) const;

    /// @brief Same corners (two empty boxes are equal).
    bool operator==(const Box3& other) const;

    /// @brief Not operator==.
    bool operator!=(const Box3& other) const { return !(*this == other); }

private:
    glm::vec3 mMin;
    glm::vec3 mMax;
};

} // namespace texsplat::sg
