#pragma once

#include "nodes/volume/GridGeometry.h"

#include <glm/glm.hpp>
#include <glm/gtc/type_precision.hpp>

#include <cstdint>
#include <string>

namespace texsplat::volume {

/// @brief A box of voxel indices of a grid: voxels `lo` (included) to `hi` (excluded) along each
/// axis, the part of a grid that a brick holds (distributed rendering, docs/distributed.md).
struct IndexBox {
    glm::i64vec3 lo{0}; ///< first voxel along x, y, z
    glm::i64vec3 hi{0}; ///< one past the last voxel along x, y, z

    /// @brief The box of every voxel of `geometry`.
    static IndexBox of(const GridGeometry& geometry) { return {glm::i64vec3(0), geometry.dims()}; }

    /// @brief Voxels along x, y, z (0 where the box is empty along that axis).
    glm::i64vec3 dims() const { return glm::max(hi - lo, glm::i64vec3(0)); }
    /// @brief The number of voxels.
    std::int64_t voxelCount() const {
        const glm::i64vec3 d = dims();
        return d.x * d.y * d.z;
    }
    /// @brief Whether the box holds no voxel.
    bool isEmpty() const { return voxelCount() == 0; }
    /// @brief Whether voxel `index` lies in the box.
    bool contains(const glm::i64vec3& index) const {
        return glm::all(glm::greaterThanEqual(index, lo)) && glm::all(glm::lessThan(index, hi));
    }
    /// @brief The voxels in both boxes (empty when they do not meet).
    IndexBox intersection(const IndexBox& other) const {
        return {glm::max(lo, other.lo), glm::max(glm::max(lo, other.lo), glm::min(hi, other.hi))};
    }
    /// @brief Same voxels (empty boxes compare by their corners too).
    bool operator==(const IndexBox& other) const { return lo == other.lo && hi == other.hi; }
    /// @brief Not operator==.
    bool operator!=(const IndexBox& other) const { return !(*this == other); }
    /// @brief "[lo.x, hi.x) x [lo.y, hi.y) x [lo.z, hi.z)", the form boxes take in messages.
    std::string text() const {
        std::string result;
        for (int axis = 0; axis < 3; ++axis) {
            result += (axis == 0 ? "[" : " x [") + std::to_string(lo[axis]) + ", " +
                      std::to_string(hi[axis]) + ")";
        }
        return result;
    }
};

/// @brief The geometry of the voxels of `box` (not empty) of a grid of `whole` geometry: the
/// box's dimensions, the world position of its first voxel, the same spacing.
inline GridGeometry boxGeometry(const GridGeometry& whole, const IndexBox& box) {
    return GridGeometry(box.dims(), whole.indexToWorld(glm::dvec3(box.lo)), whole.spacing());
}

} // namespace texsplat::volume
