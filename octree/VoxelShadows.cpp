#include "octree/VoxelShadows.h"

#include "octree/ClassifiedGrid.h"

#include <glm/geometric.hpp>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>

namespace texsplat::octree {
namespace {

// One bit per column of the plane across an axis, set from several threads at once.
class ColumnBits {
public:
    ColumnBits(std::uint64_t width, std::uint64_t height)
        : mWidth(width), mWords((width * height + 63) / 64) {}

    void set(std::uint64_t column, std::uint64_t row) {
        const std::uint64_t bit = row * mWidth + column;
        mWords[bit / 64].fetch_or(std::uint64_t{1} << (bit % 64), std::memory_order_relaxed);
    }

    std::uint64_t count() const {
        std::uint64_t total = 0;
        for (const auto& word : mWords) {
            total += static_cast<std::uint64_t>(__builtin_popcountll(word.load()));
        }
        return total;
    }

private:
    std::uint64_t mWidth;
    std::vector<std::atomic<std::uint64_t>> mWords;
};

} // namespace

VoxelShadows::VoxelShadows(const ClassifiedGrid& grid) : mSpacing(grid.spacing()) {
    const glm::u64vec3 dims = grid.dims();
    // Along x: the (y, z) plane; along y: (x, z); along z: (x, y).
    ColumnBits alongX(dims.y, dims.z);
    ColumnBits alongY(dims.x, dims.z);
    ColumnBits alongZ(dims.x, dims.y);
    std::vector<std::pair<glm::u64vec3, ClassifiedGrid::StorageIndex>> blocks;
    grid.forEachBlock([&](glm::u64vec3 block, ClassifiedGrid::StorageIndex first) {
        blocks.emplace_back(block, first);
    });
    std::atomic<std::uint64_t> voxels{0};
    tbb::parallel_for(std::size_t{0}, blocks.size(), [&](std::size_t b) {
        const auto [block, first] = blocks[b];
        constexpr std::uint64_t kSize = ClassifiedGrid::kBlockSize;
        std::uint64_t count = 0;
        for (std::uint64_t z = 0; z < kSize; ++z) {
            for (std::uint64_t y = 0; y < kSize; ++y) {
                for (std::uint64_t x = 0; x < kSize; ++x) {
                    const glm::u64vec3 voxel = block * kSize + glm::u64vec3(x, y, z);
                    if (glm::any(glm::greaterThanEqual(voxel, dims)) ||
                        grid.storedVoxel(first + x + kSize * (y + kSize * z)) == glm::vec4(0.0f)) {
                        continue;
                    }
                    ++count;
                    alongX.set(voxel.y, voxel.z);
                    alongY.set(voxel.x, voxel.z);
                    alongZ.set(voxel.x, voxel.y);
                }
            }
        }
        voxels.fetch_add(count, std::memory_order_relaxed);
    });
    mVoxels = voxels.load();
    mColumns = {alongX.count(), alongY.count(), alongZ.count()};
}

double VoxelShadows::meanDepth(const glm::dvec3& direction) const {
    const double length = glm::length(direction);
    if (mVoxels == 0 || !(length > 0.0) || !std::isfinite(length)) {
        return 0.0;
    }
    const glm::dvec3 d = glm::abs(direction) / length;
    const glm::dvec3& s = mSpacing;
    const double shadow = d.x * double(mColumns[0]) * s.y * s.z +
                          d.y * double(mColumns[1]) * s.x * s.z +
                          d.z * double(mColumns[2]) * s.x * s.y;
    const double voxel = std::cbrt(s.x * s.y * s.z);
    return double(mVoxels) * voxel * voxel / shadow;
}

} // namespace texsplat::octree
