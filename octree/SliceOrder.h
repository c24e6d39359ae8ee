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
/// on a common ray (docs/octree.md). The order refers to the grid, which must outlive it.
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

    /// @brief Calls `visit(glm::u64vec3 voxel, ClassifiedGrid::StorageIndex stored)` for every
    /// voxel of the grid's allocated blocks, back to front: the voxels of the whole box in this
    /// order, less those of unallocated blocks (which are empty) and, for a view with sides
    /// (View::seeingOnly()), of blocks whose voxels' splats are all out of sight. The walk skips
    /// a row of blocks that holds none of the rest at once and any other block within a row at
    /// once, so its time follows the blocks walked, plus one step per row of the box and per
    /// block of a row that holds blocks.
    template <typename Visit> void forEach(Visit&& visit) const {
        for (std::size_t slice = 0; slice < sliceCount(); ++slice) {
            forEachInSlice(slice, visit);
        }
    }

    /// @brief Slices of the walk: planes across the slicing axis, back to front. No voxel of
    /// a slice is in front of a later slice's, so slices can be walked apart (in parallel) and
    /// their splats laid end to end.
    [[nodiscard]] std::size_t sliceCount() const {
        return mOrder[static_cast<std::size_t>(mAxes[0])].size();
    }

    /// @brief forEach() over slice `slice` (< sliceCount()) only.
    template <typename Visit> void forEachInSlice(std::size_t slice, Visit&& visit) const {
        const auto middle = static_cast<std::size_t>(mAxes[1]);
        const auto inner = static_cast<std::size_t>(mAxes[2]);
        constexpr std::uint64_t kSize = ClassifiedGrid::kBlockSize;
        const glm::u64vec3 blockDims = mGrid->blockDims();
        glm::u64vec3 voxel(0);
        const std::uint64_t a = mOrder[static_cast<std::size_t>(mAxes[0])][slice];
        voxel[mAxes[0]] = a;
        for (const std::uint64_t b : mOrder[middle]) {
            voxel[mAxes[1]] = b;
            if (!mRowHasBlocks[static_cast<std::size_t>(a / kSize +
                                                        blockDims[mAxes[0]] * (b / kSize))]) {
                continue;
            }
            for (const Segment& segment : mSegments) {
                voxel[mAxes[2]] = segment.block * kSize;
                const ClassifiedGrid::StorageIndex first = mGrid->blockStorage(voxel / kSize);
                if (first == ClassifiedGrid::kNoStorage ||
                    (!mOutOfSight.empty() &&
                     mOutOfSight[static_cast<std::size_t>(first / ClassifiedGrid::kBlockVoxels)])) {
                    continue;
                }
                for (std::uint64_t step = segment.begin; step < segment.end; ++step) {
                    voxel[mAxes[2]] = mOrder[inner][step];
                    visit(voxel, first + ClassifiedGrid::offsetInBlock(voxel));
                }
            }
        }
    }

private:
    // A run of the inner axis' order that stays in one block: steps [begin, end) of it.
    struct Segment {
        std::uint64_t block;
        std::uint64_t begin;
        std::uint64_t end;
    };

    const ClassifiedGrid* mGrid;
    std::array<int, 3> mAxes;
    std::array<std::vector<std::uint64_t>, 3> mOrder;
    std::vector<Segment> mSegments;
    // Per block of the outer and middle axes (outer fastest): whether the row of blocks along
    // the inner axis holds an allocated block in sight.
    std::vector<bool> mRowHasBlocks;
    // Per allocated block (slot): whether its voxels' splats are all out of the view's sight;
    // empty for a view without sides.
    std::vector<bool> mOutOfSight;
};

} // namespace texsplat::octree
