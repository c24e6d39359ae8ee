#pragma once

#include "octree/ClassifiedGrid.h"
#include "octree/View.h"

#include <array>
#include <cstdint>
#include <utility>
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
        const std::uint64_t all = mGrid->dims()[mAxes[2]];
        forEachInSliceRows(
            slice, [all](std::uint64_t) { return std::pair<std::uint64_t, std::uint64_t>(0, all); },
            visit);
    }

    /// @brief forEachInSlice() of the voxels whose inner-axis coordinate lies in
    /// `innerRange(middle)` = [begin, end) (a pair), asked once per row of the slice, `middle`
    /// being the row's middle-axis coordinate: a row's voxels that a caller knows it needs
    /// (those whose splats reach a band of the image, say) without the steps to the others'
    /// blocks.
    template <typename InnerRange, typename Visit>
    void forEachInSliceRows(std::size_t slice, InnerRange&& innerRange, Visit&& visit) const {
        const int inner = mAxes[2];
        forEachSegmentInSlice(slice, innerRange,
                              [&](glm::u64vec3 voxel, ClassifiedGrid::StorageIndex first,
                                  const std::uint64_t* coordinates, std::size_t count) {
                                  for (std::size_t i = 0; i < count; ++i) {
                                      voxel[inner] = coordinates[i];
                                      visit(voxel, first + ClassifiedGrid::offsetInBlock(voxel));
                                  }
                              });
    }

    /// @brief forEachInSliceRows() a run of a row within one block at a time: calls
    /// `visit(glm::u64vec3 voxel, ClassifiedGrid::StorageIndex first, const std::uint64_t*
    /// coordinates, std::size_t count)` with the block's storage index (as forEachBlock()
    /// gives it), the row's voxel whose inner coordinate is the block's first, and the `count`
    /// inner coordinates of the run, in order, all within the block and `innerRange`: a caller's
    /// loop over a run reads one block.
    template <typename InnerRange, typename Visit>
    void forEachSegmentInSlice(std::size_t slice, InnerRange&& innerRange, Visit&& visit) const {
        const auto middle = static_cast<std::size_t>(mAxes[1]);
        const auto inner = static_cast<std::size_t>(mAxes[2]);
        constexpr std::uint64_t kSize = ClassifiedGrid::kBlockSize;
        const glm::u64vec3 blockDims = mGrid->blockDims();
        const std::uint64_t* order = mOrder[inner].data();
        glm::u64vec3 voxel(0);
        const std::uint64_t a = mOrder[static_cast<std::size_t>(mAxes[0])][slice];
        voxel[mAxes[0]] = a;
        for (const std::uint64_t b : mOrder[middle]) {
            voxel[mAxes[1]] = b;
            if (!mRowHasBlocks[static_cast<std::size_t>(a / kSize +
                                                        blockDims[mAxes[0]] * (b / kSize))]) {
                continue;
            }
            const std::pair<std::uint64_t, std::uint64_t> range = innerRange(b);
            if (range.first >= range.second) {
                continue;
            }
            for (const Segment& segment : mSegments) {
                if ((segment.block + 1) * kSize <= range.first ||
                    segment.block * kSize >= range.second) {
                    continue;
                }
                voxel[mAxes[2]] = segment.block * kSize;
                const ClassifiedGrid::StorageIndex first = mGrid->blockStorage(voxel / kSize);
                if (first == ClassifiedGrid::kNoStorage ||
                    (!mOutOfSight.empty() &&
                     mOutOfSight[static_cast<std::size_t>(first / ClassifiedGrid::kBlockVoxels)])) {
                    continue;
                }
                // Within a block the run's coordinates are monotonic: those in the range are
                // one stretch of it.
                std::uint64_t begin = segment.begin;
                std::uint64_t end = segment.end;
                while (begin < end &&
                       (order[begin] < range.first || order[begin] >= range.second)) {
                    ++begin;
                }
                while (end > begin &&
                       (order[end - 1] < range.first || order[end - 1] >= range.second)) {
                    --end;
                }
                if (begin < end) {
                    visit(voxel, first, order + begin, static_cast<std::size_t>(end - begin));
                }
            }
        }
    }

    /// @brief Whether the walk visits the voxels of the allocated block whose voxel (0, 0, 0) is
    /// stored at @p first: false where the view's sides leave all their splats out of sight.
    [[nodiscard]] bool isInSight(ClassifiedGrid::StorageIndex first) const {
        return mOutOfSight.empty() ||
               !mOutOfSight[static_cast<std::size_t>(first / ClassifiedGrid::kBlockVoxels)];
    }

    /// @brief The axes from outermost to innermost: slices, rows of a slice, voxels of a row.
    [[nodiscard]] const std::array<int, 3>& axes() const { return mAxes; }

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
