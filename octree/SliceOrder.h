#pragma once

#include "octree/ClassifiedGrid.h"
#include "octree/View.h"

#include <array>
#include <cstdint>
#include <vector>

namespace texsplat::octree {

/// @brief Back-to-front order of every voxel of a full-resolution grid for a view, without
/// sorting: slice by slice along the axis most parallel to the view direction (Westover 1989),
/// and within a slice row by row, each axis walked from its far end(s) toward the eye.
///
/// Per axis, an orthographic view walks from the end the direction points to; a perspective
/// view walks from both ends toward the slice holding the eye, that slice last (for an eye
/// outside the grid, one end is empty). Along any ray from the eye every cell coordinate moves
/// away from the eye's, so this nested order puts every cell before the cells in front of it
/// on a common ray (docs/octree.md). Indices are 64-bit linear grid indices.
class SliceOrder {
public:
    /// @brief The order of @p grid's voxels for @p view.
    SliceOrder(const ClassifiedGrid& grid, const View& view);

    /// @brief The slicing axis: the one with the largest direction component (0, 1 or 2).
    [[nodiscard]] int sliceAxis() const { return mAxes[0]; }

    /// @brief The voxel coordinates along @p axis in the order they are walked.
    [[nodiscard]] const std::vector<std::uint64_t>& axisOrder(int axis) const {
        return mOrder[static_cast<std::size_t>(axis)];
    }

    /// @brief Calls `visit(std::uint64_t index, glm::u64vec3 voxel)` with the linear index and
    /// the coordinates of every voxel, back to front.
    template <typename Visit> void forEach(Visit&& visit) const {
        const glm::u64vec3 stride(1, mDims.x, mDims.x * mDims.y);
        const auto outer = static_cast<std::size_t>(mAxes[0]);
        const auto middle = static_cast<std::size_t>(mAxes[1]);
        const auto inner = static_cast<std::size_t>(mAxes[2]);
        glm::u64vec3 voxel(0);
        for (const std::uint64_t a : mOrder[outer]) {
            voxel[mAxes[0]] = a;
            for (const std::uint64_t b : mOrder[middle]) {
                voxel[mAxes[1]] = b;
                const std::uint64_t base = a * stride[mAxes[0]] + b * stride[mAxes[1]];
                for (const std::uint64_t c : mOrder[inner]) {
                    voxel[mAxes[2]] = c;
                    visit(base + c * stride[mAxes[2]], voxel);
                }
            }
        }
    }

private:
    glm::u64vec3 mDims;
    std::array<int, 3> mAxes;
    std::array<std::vector<std::uint64_t>, 3> mOrder;
};

} // namespace texsplat::octree
