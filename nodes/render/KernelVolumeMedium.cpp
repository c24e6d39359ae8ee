#include "nodes/render/KernelVolumeMedium.h"

#include "nodes/detail/Finite.h"
#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace texsplat::render {
namespace {

// The most voxels per axis within a support below 2 voxels: an open interval of width < 4.
constexpr int kMaxTaps = 4;

float finiteOrMax(float value) {
    return std::min(value, std::numeric_limits<float>::max());
}

} // namespace

KernelVolumeMedium::KernelVolumeMedium(std::shared_ptr<const octree::ClassifiedGrid> grid,
                                       const glm::mat4& model, const kernel::KernelTable& kernel,
                                       std::optional<Shading> shading)
    : mGrid(std::move(grid)), mKernel(&kernel), mShading(std::move(shading)) {
    TEXSPLAT_ASSERT(mGrid, "KernelVolumeMedium: no grid");
    TEXSPLAT_ASSERT(!mShading ||
                        (mShading->gradients && &mShading->gradients->grid() == mGrid.get()),
                    "KernelVolumeMedium: the shading's gradients are not the grid's");
    if (!(kernel.support() < 2.0f)) {
        throw DataError("KernelVolumeMedium: the kernel's support must be below 2 voxels, got " +
                        std::to_string(kernel.support()));
    }
    const glm::dmat3 linear(model);
    const double determinant = glm::determinant(linear);
    if (!nodes::detail::isFinite(model) || !std::isfinite(determinant) || determinant == 0.0) {
        throw DataError("KernelVolumeMedium: the model matrix must be finite and invertible");
    }
    mRootToLocal = glm::inverse(linear);
    const glm::dvec3 translation(model[3]);
    const glm::dvec3 spacing = mGrid->spacing();
    const glm::dmat3 localToIndex(1.0 / spacing.x, 0.0, 0.0, 0.0, 1.0 / spacing.y, 0.0, 0.0, 0.0,
                                  1.0 / spacing.z);
    mRootToIndex = localToIndex * mRootToLocal;
    // index = S⁻¹ (M⁻¹ (p − translation) − origin)
    mRootToIndexOffset = localToIndex * (-(mRootToLocal * translation) - mGrid->origin());

    mDims = glm::i64vec3(mGrid->dims());
    const glm::i64vec3 voxelBricks = (mDims + (kBrickSize - 1)) / kBrickSize;
    static_assert(kBrickSize == static_cast<std::int64_t>(octree::ClassifiedGrid::kBlockSize),
                  "voxel bricks are the classified grid's blocks");
    std::vector<std::uint8_t> occupied(
        static_cast<std::size_t>(voxelBricks.x * voxelBricks.y * voxelBricks.z), 0);
    mGrid->forEachBlock([&](glm::u64vec3 block, octree::ClassifiedGrid::StorageIndex first) {
        for (std::size_t voxel = 0; voxel < octree::ClassifiedGrid::kBlockVoxels; ++voxel) {
            if (mGrid->storedVoxel(first + voxel) != glm::vec4(0.0f)) {
                const glm::i64vec3 brick(block);
                occupied[static_cast<std::size_t>(
                    brick.x + voxelBricks.x * (brick.y + voxelBricks.y * brick.z))] = 1;
                return;
            }
        }
    });
    // Bricks of sample positions b = -1 .. voxelBricks (stored at b + 1) cover index positions
    // [b·B, (b+1)·B); the voxels within the support of such a position lie in voxel bricks
    // b−1 .. b+1.
    mBricks = voxelBricks + std::int64_t{2};
    mActive.assign(static_cast<std::size_t>(mBricks.x * mBricks.y * mBricks.z), 0);
    for (std::int64_t z = 0; z < voxelBricks.z; ++z) {
        for (std::int64_t y = 0; y < voxelBricks.y; ++y) {
            for (std::int64_t x = 0; x < voxelBricks.x; ++x) {
                const std::int64_t brick = x + voxelBricks.x * (y + voxelBricks.y * z);
                if (!occupied[static_cast<std::size_t>(brick)]) {
                    continue;
                }
                // Voxel brick v makes sample bricks v−1 .. v+1 active: stored at v .. v+2.
                for (std::int64_t dz = 0; dz < 3; ++dz) {
                    for (std::int64_t dy = 0; dy < 3; ++dy) {
                        for (std::int64_t dx = 0; dx < 3; ++dx) {
                            mActive[static_cast<std::size_t>(
                                (x + dx) + mBricks.x * ((y + dy) + mBricks.y * (z + dz)))] = 1;
                        }
                    }
                }
            }
        }
    }
}

std::size_t KernelVolumeMedium::activeBrickCount() const {
    return static_cast<std::size_t>(std::count(mActive.begin(), mActive.end(), std::uint8_t{1}));
}

bool KernelVolumeMedium::isActive(std::int64_t bx, std::int64_t by, std::int64_t bz) const {
    const std::int64_t index = (bx + 1) + mBricks.x * ((by + 1) + mBricks.y * (bz + 1));
    return mActive[static_cast<std::size_t>(index)] != 0;
}

void KernelVolumeMedium::intervals(const sg::RayCastRay& ray, float tMin, float tMax,
                                   float stepVoxels, std::vector<Interval>& out) const {
    const glm::dvec3 origin = mRootToIndex * glm::dvec3(ray.origin) + mRootToIndexOffset;
    const glm::dvec3 direction = mRootToIndex * glm::dvec3(ray.direction);
    const double voxelsPerLength = glm::length(direction);
    if (!(voxelsPerLength > 0.0) || !std::isfinite(voxelsPerLength) ||
        !std::isfinite(origin.x + origin.y + origin.z)) {
        return;
    }
    const float step = static_cast<float>(static_cast<double>(stepVoxels) / voxelsPerLength);
    if (!(step > 0.0f)) {
        return;
    }
    // Clip to where the field can be non-zero: index positions within the support of a voxel.
    const double reach = mKernel->support();
    double t0 = tMin;
    double t1 = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        const double low = -reach;
        const double high = static_cast<double>(mDims[axis] - 1) + reach;
        if (direction[axis] == 0.0) {
            if (origin[axis] <= low || origin[axis] >= high) {
                return;
            }
            continue;
        }
        double a = (low - origin[axis]) / direction[axis];
        double b = (high - origin[axis]) / direction[axis];
        if (a > b) {
            std::swap(a, b);
        }
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    if (!(t1 > t0)) {
        return;
    }

    // 3D DDA over the bricks from t0 to t1 (Amanatides & Woo), merging runs of active bricks.
    const double brick = static_cast<double>(kBrickSize);
    glm::i64vec3 cell;
    glm::i64vec3 stepCell;
    glm::dvec3 tNext;
    glm::dvec3 tDelta;
    const glm::dvec3 start = origin + t0 * direction;
    for (int axis = 0; axis < 3; ++axis) {
        const auto c = static_cast<std::int64_t>(std::floor(start[axis] / brick));
        cell[axis] = std::clamp<std::int64_t>(c, -1, mBricks[axis] - 2);
        if (direction[axis] > 0.0) {
            stepCell[axis] = 1;
            tNext[axis] = t0 + (static_cast<double>(cell[axis] + 1) * brick - start[axis]) /
                                   direction[axis];
            tDelta[axis] = brick / direction[axis];
        } else if (direction[axis] < 0.0) {
            stepCell[axis] = -1;
            tNext[axis] =
                t0 + (static_cast<double>(cell[axis]) * brick - start[axis]) / direction[axis];
            tDelta[axis] = -brick / direction[axis];
        } else {
            stepCell[axis] = 0;
            tNext[axis] = std::numeric_limits<double>::infinity();
            tDelta[axis] = std::numeric_limits<double>::infinity();
        }
    }
    double t = t0;
    bool open = false;
    Interval current;
    current.step = step;
    const std::int64_t maxCells = mBricks.x + mBricks.y + mBricks.z + 3;
    for (std::int64_t visited = 0; visited < maxCells && t < t1; ++visited) {
        const int axis =
            tNext.x < tNext.y ? (tNext.x < tNext.z ? 0 : 2) : (tNext.y < tNext.z ? 1 : 2);
        const double exit = std::min(tNext[axis], t1);
        const bool active = isActive(cell.x, cell.y, cell.z);
        if (active && !open) {
            current.t0 = static_cast<float>(t);
            open = true;
        } else if (!active && open) {
            current.t1 = static_cast<float>(t);
            out.push_back(current);
            open = false;
        }
        t = exit;
        cell[axis] += stepCell[axis];
        tNext[axis] += tDelta[axis];
        if (cell[axis] < -1 || cell[axis] > mBricks[axis] - 2) {
            break;
        }
    }
    if (open) {
        current.t1 = static_cast<float>(std::min(t, t1));
        if (current.t1 > current.t0) {
            out.push_back(current);
        }
    }
}

sg::RayCastMedium::Sample KernelVolumeMedium::sample(const sg::RayCastRay& ray, float t) const {
    const glm::dvec3 point =
        glm::dvec3(ray.origin) + static_cast<double>(t) * glm::dvec3(ray.direction);
    const glm::dvec3 q = mRootToIndex * point + mRootToIndexOffset;
    const double reach = mKernel->support();
    glm::i64vec3 low;
    int taps[3];
    float distance2[3][kMaxTaps];
    for (int axis = 0; axis < 3; ++axis) {
        const double position = q[axis];
        if (!(position > -reach && position < static_cast<double>(mDims[axis] - 1) + reach)) {
            return Sample(0.0f);
        }
        const auto first =
            std::max<std::int64_t>(0, static_cast<std::int64_t>(std::ceil(position - reach)));
        const auto last = std::min<std::int64_t>(
            mDims[axis] - 1, static_cast<std::int64_t>(std::floor(position + reach)));
        taps[axis] = static_cast<int>(std::clamp<std::int64_t>(last - first + 1, 0, kMaxTaps));
        low[axis] = first;
        for (int i = 0; i < taps[axis]; ++i) {
            const auto d = static_cast<float>(position - static_cast<double>(first + i));
            distance2[axis][i] = d * d;
        }
    }
    const float support2 = mKernel->supportSquared();
    glm::vec4 sum(0.0f);
    glm::vec3 gradient(0.0f);
    for (int k = 0; k < taps[2]; ++k) {
        for (int j = 0; j < taps[1]; ++j) {
            const float yz = distance2[1][j] + distance2[2][k];
            if (!(yz < support2)) {
                continue;
            }
            for (int i = 0; i < taps[0]; ++i) {
                const float r2 = yz + distance2[0][i];
                if (r2 < support2) {
                    const glm::u64vec3 voxel(low + glm::i64vec3(i, j, k));
                    const float weight = (*mKernel)(r2);
                    sum += weight * mGrid->voxel(voxel);
                    if (mShading) {
                        gradient += weight * mShading->gradients->at(voxel);
                    }
                }
            }
        }
    }
    if (mShading) {
        sum = glm::vec4(mShading->lighting.shade(glm::vec3(sum), sum.w, gradient), sum.w);
    }
    // Per unit local length → per unit root length along this ray.
    const auto localPerRoot =
        static_cast<float>(glm::length(mRootToLocal * glm::dvec3(ray.direction)));
    sum *= localPerRoot;
    return Sample(finiteOrMax(sum.x), finiteOrMax(sum.y), finiteOrMax(sum.z), finiteOrMax(sum.w));
}

} // namespace texsplat::render
