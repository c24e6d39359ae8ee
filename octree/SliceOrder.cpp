#include "octree/SliceOrder.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace texsplat::octree {

namespace {

void appendRange(std::vector<std::uint64_t>& order, std::uint64_t first, std::uint64_t count,
                 bool descending) {
    for (std::uint64_t step = 0; step < count; ++step) {
        order.push_back(descending ? first - step : first + step);
    }
}

// Coordinates 0..n-1 along one axis, far to near. The eye's cell is where the eye's index
// coordinate rounds to (cells are centred on the samples).
std::vector<std::uint64_t> axisOrderFor(const ClassifiedGrid& grid, const View& view, int axis) {
    const std::uint64_t count = grid.dims()[axis];
    std::vector<std::uint64_t> order;
    order.reserve(static_cast<std::size_t>(count));
    if (!view.isPerspective()) {
        const bool upperFar = view.direction()[axis] >= 0.0;
        appendRange(order, upperFar ? count - 1 : 0, count, upperFar);
        return order;
    }
    const double eyeCell =
        std::floor((view.eye()[axis] - grid.origin()[axis]) / grid.spacing()[axis] + 0.5);
    if (eyeCell < 0.0) {
        appendRange(order, count - 1, count, true);
    } else if (eyeCell >= static_cast<double>(count)) {
        appendRange(order, 0, count, false);
    } else {
        const auto eye = static_cast<std::uint64_t>(eyeCell);
        appendRange(order, 0, eye, false);
        appendRange(order, count - 1, count - 1 - eye, true);
        order.push_back(eye);
    }
    return order;
}

} // namespace

SliceOrder::SliceOrder(const ClassifiedGrid& grid, const View& view)
    : mGrid(&grid), mAxes{2, 1, 0} {
    const glm::dvec3 direction = glm::abs(view.direction());
    int slice = 2;
    if (direction.x > direction[slice]) {
        slice = 0;
    }
    if (direction.y > direction[slice]) {
        slice = 1;
    }
    // The slicing axis goes outermost; the other two keep x innermost for memory locality.
    int next = 1;
    for (int axis = 2; axis >= 0; --axis) {
        if (axis != slice) {
            mAxes[static_cast<std::size_t>(next++)] = axis;
        }
    }
    mAxes[0] = slice;
    for (int axis = 0; axis < 3; ++axis) {
        mOrder[static_cast<std::size_t>(axis)] = axisOrderFor(grid, view, axis);
    }
    constexpr std::uint64_t kSize = ClassifiedGrid::kBlockSize;
    const std::vector<std::uint64_t>& inner = mOrder[static_cast<std::size_t>(mAxes[2])];
    for (std::uint64_t step = 0; step < inner.size(); ++step) {
        const std::uint64_t block = inner[step] / kSize;
        if (mSegments.empty() || mSegments.back().block != block) {
            mSegments.push_back({block, step, step});
        }
        mSegments.back().end = step + 1;
    }
    const glm::u64vec3 blockDims = grid.blockDims();
    mRowHasBlocks.assign(static_cast<std::size_t>(blockDims[mAxes[0]] * blockDims[mAxes[1]]),
                         false);
    if (view.hasSides()) {
        mOutOfSight.assign(grid.blockCount(), false);
    }
    const glm::dvec3 spacing = grid.spacing();
    const double voxelEdge = std::max({spacing.x, spacing.y, spacing.z});
    const double voxelHalfWidth = 0.5 * std::min({spacing.x, spacing.y, spacing.z});
    grid.forEachBlock([&](glm::u64vec3 block, ClassifiedGrid::StorageIndex first) {
        if (!mOutOfSight.empty()) {
            const glm::u64vec3 begin = block * kSize;
            const glm::u64vec3 end = glm::min(begin + kSize, grid.dims());
            if (view.isOutOfSight(grid.toWorld(glm::dvec3(begin) - 0.5),
                                  grid.toWorld(glm::dvec3(end) - 0.5), voxelEdge,
                                  voxelHalfWidth)) {
                mOutOfSight[static_cast<std::size_t>(first / ClassifiedGrid::kBlockVoxels)] = true;
                return;
            }
        }
        mRowHasBlocks[static_cast<std::size_t>(block[mAxes[0]] +
                                               blockDims[mAxes[0]] * block[mAxes[1]])] = true;
    });
}

} // namespace texsplat::octree
