#include "nodes/render/cpu/VoxelRaster.h"

#include "nodes/render/cpu/VoxelSpans.h"
#include "scenegraph/Assert.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace texsplat::render::cpu {
namespace {

// Pixels of margin on each bound: the rounding of the float centres, and the half pixel a
// stamp's phase moves a splat.
constexpr double kMargin = 2.0;

// The coordinates c (real) with low <= origin + step·c <= high, as [first, last] (empty when
// first > last).
std::pair<double, double> solve(double origin, double step, double low, double high) {
    constexpr double kFlat = 1e-12;
    if (std::abs(step) < kFlat) {
        return origin >= low && origin <= high
                   ? std::pair<double, double>(-std::numeric_limits<double>::infinity(),
                                               std::numeric_limits<double>::infinity())
                   : std::pair<double, double>(1.0, 0.0);
    }
    const double a = (low - origin) / step;
    const double b = (high - origin) / step;
    return {std::min(a, b), std::max(a, b)};
}

} // namespace

VoxelRaster::VoxelRaster(const octree::VoxelSplats& voxels, const SplatSetup& setup,
                         const FootprintSampler& sampler, int width, int height)
    : mVoxels(&voxels), mSetup(&setup), mSampler(&sampler), mWidth(width), mHeight(height) {
    const octree::ClassifiedGrid& grid = voxels.grid();
    const glm::dvec3 origin = grid.origin();
    const glm::dvec3 spacing = grid.spacing();
    for (int axis = 0; axis < 3; ++axis) {
        std::vector<float>& positions = mPositions[static_cast<std::size_t>(axis)];
        positions.resize(static_cast<std::size_t>(grid.dims()[axis]));
        for (std::size_t i = 0; i < positions.size(); ++i) {
            // As ClassifiedGrid::toWorld() computes it, axis by axis.
            positions[i] =
                static_cast<float>(origin[axis] + spacing[axis] * static_cast<double>(i));
        }
    }
    const ProjectiveRows& rows = setup.rows();
    for (int k = 0; k < 2; ++k) {
        const float(&row)[4] = rows.pixelFromLocal[k];
        mOrigin[k] = row[3];
        for (int axis = 0; axis < 3; ++axis) {
            mOrigin[k] += double(row[axis]) * origin[axis];
            mStep[k][axis] = double(row[axis]) * spacing[axis];
        }
        mReach[k] = setup.stampGeometry().halfExtent[k] + kMargin;
    }
    if (grid.storage() == octree::ClassifiedGrid::Storage::Palette && setup.stamps() != nullptr) {
        mThinEntries = cpu::thinEntries(grid.palette(), setup.stamps()->peak);
    }
}

VoxelRaster::RowPlace VoxelRaster::rowPlace(std::uint64_t slice, std::uint64_t row) const {
    const std::array<int, 3>& axes = mVoxels->order().axes();
    const int inner = axes[2];
    // The slice order keeps x or y innermost, so the tail holds one term at most: the sum's order
    // is kept.
    TEXSPLAT_ASSERT(inner != 2, "VoxelRaster::rowPlace(): the inner axis is z");
    // The position of the row's voxels along each axis (the inner one's unused).
    glm::dvec3 at(0.0);
    at[axes[0]] = mPositions[static_cast<std::size_t>(axes[0])][slice];
    at[axes[1]] = mPositions[static_cast<std::size_t>(axes[1])][row];
    const ProjectiveRows& rows = mSetup->rows();
    RowPlace place{};
    place.tailed = inner != 0;
    for (int k = 0; k < 3; ++k) {
        const float(&coefficients)[4] = rows.pixelFromLocal[k < 2 ? k : 3];
        // SplatSetup::centreOf()'s sum: the constant, then the z, y and x terms, those before
        // the inner axis' term in the head, those after it in the tail.
        double sum = coefficients[3];
        for (int axis = 2; axis > inner; --axis) {
            sum = sum + double(coefficients[axis]) * at[axis];
        }
        place.head[k] = sum;
        place.step[k] = coefficients[inner];
        double tail = 0.0;
        for (int axis = inner - 1; axis >= 0; --axis) {
            tail = tail + double(coefficients[axis]) * at[axis];
        }
        place.tail[k] = tail;
    }
    return place;
}

std::pair<int, int> VoxelRaster::rowRange() const {
    const glm::u64vec3 dims = mVoxels->grid().dims();
    // Pixel y is affine in the voxel's index: its extremes lie at corners of the index box.
    double low = mOrigin[1];
    double high = mOrigin[1];
    for (int axis = 0; axis < 3; ++axis) {
        const double span = mStep[1][axis] * static_cast<double>(dims[axis] - 1);
        low += std::min(span, 0.0);
        high += std::max(span, 0.0);
    }
    low = std::max(std::floor(low - mReach[1]), 0.0);
    high = std::min(std::ceil(high + mReach[1]) + 1.0, static_cast<double>(mHeight));
    if (!(low < high)) {
        return {0, 0};
    }
    return {static_cast<int>(low), static_cast<int>(high)};
}

std::pair<std::uint64_t, std::uint64_t>
VoxelRaster::innerRange(std::uint64_t slice, std::uint64_t row, int rowBegin, int rowEnd) const {
    const std::array<int, 3>& axes = mVoxels->order().axes();
    const auto inner = static_cast<std::size_t>(axes[2]);
    double first = 0.0;
    double last = static_cast<double>(mVoxels->grid().dims()[axes[2]]) - 1.0;
    // Pixel y within the band's rows widened by the reach, pixel x within the image's.
    const double low[2] = {-mReach[0], rowBegin - mReach[1]};
    const double high[2] = {mWidth + mReach[0], rowEnd + mReach[1]};
    for (int k = 0; k < 2; ++k) {
        const double base = mOrigin[k] + mStep[k][axes[0]] * static_cast<double>(slice) +
                            mStep[k][axes[1]] * static_cast<double>(row);
        const std::pair<double, double> range = solve(base, mStep[k][inner], low[k], high[k]);
        first = std::max(first, std::ceil(range.first));
        last = std::min(last, std::floor(range.second));
    }
    if (!(first <= last)) {
        return {0, 0};
    }
    return {static_cast<std::uint64_t>(first), static_cast<std::uint64_t>(last) + 1};
}

} // namespace texsplat::render::cpu
